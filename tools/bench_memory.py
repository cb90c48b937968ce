#!/usr/bin/python3
"""Peak memory per texel of a loaded texture: renders the default head with an
8-bit PNG albedo map (and, separately, normal map) of each size, in its own
process, and reports the process's peak resident memory (GNU time's %M) and
the marginal cost per texel: the growth of the peak from the previous size,
divided by the texels added (the peak without a map varies by 100 MiB from
run to run with llvmpipe's threads, so the difference from it is not used).

usage: tools/bench_memory.py [--dermis build/dermis] [--sizes 1024,2048,4096,8192,16384]
                             [--maps albedo,normal] [--json OUT.json]

A size the engine refuses is reported with its one-line error. Needs
/usr/bin/time (Debian package `time`) and OpenImageIO's Python module
(python3-openimageio) to write the maps. docs/testing.md, "Memory", has the
figures."""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import numpy as np
import OpenImageIO as oiio

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def write_map(path, size, kind):
    # A smooth pattern compresses well (a 16384^2 map is a few hundred KB),
    # like a hostile input; a normal map points mostly up +Z.
    ramp = np.linspace(0, 255, size, dtype=np.float32)
    image = np.empty((size, size, 3), dtype=np.uint8)
    if kind == "normal":
        image[:, :, 0] = 128 + ((ramp[None, :] % 16) - 8).astype(np.int16)
        image[:, :, 1] = 128
        image[:, :, 2] = 250
    else:
        image[:, :, 0] = ramp[None, :].astype(np.uint8)
        image[:, :, 1] = ramp[:, None].astype(np.uint8)
        image[:, :, 2] = 180
    out = oiio.ImageOutput.create(path)
    out.open(path, oiio.ImageSpec(size, size, 3, "uint8"))
    out.write_image(image)
    out.close()


def write_scene(path, map_path, kind):
    with open(os.path.join(REPO, "content", "scenes", "default.json")) as f:
        scene = json.load(f)
    material = scene["characters"][0]["material"]
    if map_path:
        material[kind + "_map"] = map_path
    with open(path, "w") as f:
        json.dump(scene, f)


def peak_kib(dermis, scene, out_png):
    command = ["/usr/bin/time", "-f", "%M", dermis, "render", scene, "--size", "64x36", "--frames", "1",
               "--out", out_png, "--quiet"]
    run = subprocess.run(command, capture_output=True, text=True)
    lines = run.stderr.strip().splitlines()
    peak = int(lines[-1]) if lines and lines[-1].strip().isdigit() else None
    error = "\n".join(l for l in lines[:-1] if l.strip()) if run.returncode else ""
    return peak, run.returncode, error


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--dermis", default=os.path.join(REPO, "build", "dermis"))
    parser.add_argument("--sizes", default="1024,2048,4096,8192,16384")
    parser.add_argument("--maps", default="albedo,normal")
    parser.add_argument("--json")
    args = parser.parse_args()
    sizes = [int(s) for s in args.sizes.split(",")]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        base_scene = os.path.join(tmp, "base.json")
        write_scene(base_scene, None, "albedo")
        base, rc, error = peak_kib(args.dermis, base_scene, os.path.join(tmp, "base.png"))
        if rc:
            sys.exit("bench_memory: the render without a map failed: " + error)
        print(f"without a map: peak {base / 1024:.0f} MiB", flush=True)
        for kind in args.maps.split(","):
            for size in sizes:
                map_path = os.path.join(tmp, f"{kind}_{size}.png")
                write_map(map_path, size, kind)
                scene = os.path.join(tmp, f"{kind}_{size}.json")
                write_scene(scene, map_path, kind)
                peak, rc, error = peak_kib(args.dermis, scene, os.path.join(tmp, "out.png"))
                os.remove(map_path)
                row = {"map": kind, "size": size, "peak_mib": peak / 1024 if peak else None,
                       "refused": error if rc else None}
                if rc:
                    print(f"{kind} {size}^2: refused (peak {peak / 1024:.0f} MiB): {error}", flush=True)
                else:
                    line = f"{kind} {size}^2: peak {peak / 1024:.0f} MiB"
                    previous = rows[-1] if rows and rows[-1]["map"] == kind and not rows[-1]["refused"] else None
                    if previous:
                        added = size * size - previous["size"] ** 2
                        row["marginal_bytes_per_texel"] = (peak / 1024 - previous["peak_mib"]) * 2**20 / added
                        line += f", {row['marginal_bytes_per_texel']:.1f} bytes per texel added since {previous['size']}^2"
                    print(line, flush=True)
                rows.append(row)
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"base_peak_mib": base / 1024, "rows": rows}, f, indent=1)


if __name__ == "__main__":
    main()
