#!/usr/bin/env python3
"""Frame time against the number of characters (docs/crowds.md,
docs/results/crowds.md): crowds of 1 to 255 procedural heads (the most a scene may have: object ids are 8 bits) that repeat one
model, in a grid receding from the camera so that most are small on screen,
rendered with and without levels of detail (settings.lod.max_error_px).

    python3 docs/crowd_count_figure.py [--size 1280x720] [--frames 3]
        [--counts 1,4,16,64,255] [--lod-px 1] [--out docs/crowd_count.png]
        [--scene-dir DIR]

Run from the repository root after building. Each point is `dermis render
SCENE --size SIZE --frames N --timings T.json` (printed as it goes): the
frame's GPU ms (the sum of the passes' medians; llvmpipe: CPU time) and the
wall ms per frame. The scenes are written to a temporary folder, or kept in
--scene-dir as DIR/crowdCOUNT.json; the table of figures is printed as
Markdown.
"""
import argparse
import contextlib
import json
import os
import shlex
import subprocess
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLUMNS = 16  # heads per row; each row 0.8 m further away


def crowd_scene(count):
    with open("content/scenes/crowd8_mixed.json", encoding="utf-8") as f:
        scene = json.load(f)
    scene["camera"] = {"position_m": [0.0, 0.15, 0.6], "target_m": [0.0, 0.0, -2.0],
                       "vertical_fov_deg": 50, "near_m": 0.05, "far_m": 40}
    scene["settings"].pop("quality", None)
    head = scene["characters"][0]
    scene["characters"] = []
    for i in range(count):
        row, column = divmod(i, COLUMNS)
        in_row = min(COLUMNS, count - row * COLUMNS)  # each row centred, so that a small crowd is in view
        character = json.loads(json.dumps(head))
        character["name"] = f"head {i}"
        character["transform"] = {"translation_m": [(column - (in_row - 1) / 2) * 0.3, -0.15 + 0.08 * row, -0.4 - 0.8 * row]}
        scene["characters"].append(character)
    return scene


def measure(path, size, frames, lod_px, directory):
    timings = f"{directory}/timings.json"
    command = ["build/dermis", "render", path, "--size", size, "--frames", str(frames), "--out", f"{directory}/frame.png",
               "--timings", timings, "--set", f"lod.max_error_px={lod_px}"]
    print(" ".join(shlex.quote(c) for c in command), flush=True)
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(timings, encoding="utf-8") as f:
        frame = json.load(f)["frame"]
    return frame["gpu_ms"], frame["wall_ms"]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--size", default="1280x720")
    parser.add_argument("--frames", type=int, default=3)
    parser.add_argument("--counts", default="1,4,16,64,255")
    parser.add_argument("--lod-px", type=float, default=1.0)
    parser.add_argument("--out", default="docs/crowd_count.png")
    parser.add_argument("--scene-dir", help="keep the scenes (and the last frame and timings) in this folder")
    args = parser.parse_args()
    counts = [int(c) for c in args.counts.split(",")]
    rows = []
    if args.scene_dir:
        os.makedirs(args.scene_dir, exist_ok=True)
    folder = contextlib.nullcontext(args.scene_dir) if args.scene_dir else tempfile.TemporaryDirectory()
    with folder as directory:
        for count in counts:
            path = f"{directory}/crowd{count}.json"
            with open(path, "w", encoding="utf-8") as f:
                json.dump(crowd_scene(count), f)
            full = measure(path, args.size, args.frames, 0, directory)
            lod = measure(path, args.size, args.frames, args.lod_px, directory)
            rows.append((count, full, lod))
    print(f"\n| heads | frame GPU ms, full meshes | wall ms | frame GPU ms, levels of detail ({args.lod_px:g} px) | wall ms |")
    print("| ---: | ---: | ---: | ---: | ---: |")
    for count, full, lod in rows:
        print(f"| {count} | {full[0]:.1f} | {full[1]:.1f} | {lod[0]:.1f} | {lod[1]:.1f} |")
    figure, axes = plt.subplots(figsize=(6.4, 4.0))
    xs = [r[0] for r in rows]
    axes.plot(xs, [r[1][0] for r in rows], "o-", label="full meshes")
    axes.plot(xs, [r[2][0] for r in rows], "s-", label=f"levels of detail ({args.lod_px:g} px)")
    one = rows[0][1][0] / rows[0][0]
    axes.plot(xs, [one * x for x in xs], ":", color="grey", label="linear from one head")
    axes.set_xscale("log", base=2)
    axes.set_yscale("log")
    axes.set_xlabel("heads (one model, most far away)")
    axes.set_ylabel("frame GPU ms (llvmpipe: CPU time)")
    axes.set_title(f"Frame time against the crowd's size, {args.size}")
    axes.legend()
    axes.grid(True, which="both", alpha=0.3)
    figure.tight_layout()
    figure.savefig(args.out, dpi=100)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
