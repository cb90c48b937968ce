#!/usr/bin/env python3
"""The screen-space SSS techniques side by side (docs/screen-space.md,
"Techniques compared", docs/results/techniques.md): the final frame of each, and where its diffuse AOV
differs from a reference, as a heatmap on one scale.

    /usr/bin/python3 docs/techniques_figure.py [--scene content/scenes/default.json]
        [--reference out/bench-default/reference.exr] [--size 320x180] [--out docs/techniques_head.png]
        [--config 'label=--set a=b --set c=d' ...]

Run from the repository root after building. Each panel is `dermis render
SCENE --size SIZE` with its --set overrides (printed as it goes); the SSS
passes' GPU ms of each (median over --frames) are in its title, so equal cost
can be read off. The reference is the full CPU reference of `dermis bench`
(its reference.exr at the same size) when given, otherwise the finest d'Eon
chain (every Gaussian at 33 taps, none skipped). The heatmap is
max over RGB |technique - reference| / the reference's mean over SSS pixels,
on the pixels whose albedo AOV marks them as SSS.
"""
import argparse
import json
import os
import shlex
import subprocess
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import OpenImageIO as oiio  # noqa: E402

FINEST = ["sss.technique=gaussians", "sss.gaussians=8", "sss.taps=33", "sss.min_width_px=0"]
# Each technique at about the same SSS cost on the default head at 320x180
# (the sssTechniques benchmark's table, docs/screen-space.md).
DEFAULT_CONFIGS = [
    "d'Eon chain (default)=",
    "separable 11=--set sss.technique=separable --set sss.separable_samples=11",
    "disk 32=--set sss.technique=disk --set sss.disk_samples=32",
]
HEATMAP_MAX = 0.2  # 20% of the mean level: the colour scale's top


def run(scene, size, overrides, out, aov=None, timings=None, frames=1):
    command = ["build/dermis", "render", scene, "--size", size, "--frames", str(frames), "--out", out]
    if aov:
        command += ["--aov", aov]
    if timings:
        command += ["--timings", timings]
    for o in overrides:
        command += ["--set", o]
    print(" ".join(shlex.quote(c) for c in command), flush=True)
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)


def read_exr(path):
    image = oiio.ImageBuf(path)
    if image.has_error:
        raise SystemExit(f"{path}: {image.geterror()}")
    return image.get_pixels(oiio.FLOAT)[:, :, :3]


def sss_ms(timings):
    with open(timings) as f:
        passes = json.load(f)["passes"]
    return sum(p["gpu_ms"] for p in passes if p["name"].startswith("sss ") and p["executed"])


def parse_config(text):
    label, _, flags = text.partition("=")
    words = shlex.split(flags)
    overrides = [words[i + 1] for i in range(len(words) - 1) if words[i] == "--set"]
    return label, overrides


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default="content/scenes/default.json")
    parser.add_argument("--reference", help="the full CPU reference .exr at --size (dermis bench's reference.exr)")
    parser.add_argument("--size", default="320x180")
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--out", default="docs/techniques_head.png")
    parser.add_argument("--config", action="append", help="LABEL=--set K=V ...; repeatable")
    parser.add_argument("--set", action="append", default=[], help="an override for every panel")
    args = parser.parse_args()
    configs = [parse_config(c) for c in (args.config or DEFAULT_CONFIGS)]
    common = ["ssao.enabled=false"] + args.set  # the CPU reference takes AO as 1

    with tempfile.TemporaryDirectory() as tmp:
        albedo = os.path.join(tmp, "albedo.exr")
        run(args.scene, args.size, common, albedo, aov="albedo")
        image = oiio.ImageBuf(albedo)
        mask = image.get_pixels(oiio.FLOAT)[:, :, 3] > 0.5
        if args.reference:
            reference = read_exr(args.reference)
            reference_label = "CPU reference"
        else:
            path = os.path.join(tmp, "finest.exr")
            run(args.scene, args.size, common + FINEST, path, aov="diffuse")
            reference = read_exr(path)
            reference_label = "finest d'Eon chain"
        if reference.shape[:2] != mask.shape:
            raise SystemExit(f"{args.reference}: {reference.shape[1]}x{reference.shape[0]}, not {args.size}")
        level = reference[mask].mean()

        fig, axes = plt.subplots(2, len(configs), figsize=(3.3 * len(configs), 4.4), dpi=100, squeeze=False)
        heat = None
        for c, (label, overrides) in enumerate(configs):
            final = os.path.join(tmp, f"{c}.png")
            timings = os.path.join(tmp, f"{c}.json")
            run(args.scene, args.size, common + overrides, final, timings=timings, frames=args.frames)
            diffuse = os.path.join(tmp, f"{c}.exr")
            run(args.scene, args.size, common + overrides, diffuse, aov="diffuse")
            test = read_exr(diffuse)
            difference = np.abs(test - reference).max(axis=2) / level
            rel_rmse = np.sqrt(((test - reference)[mask] ** 2).mean()) / np.sqrt((reference[mask] ** 2).mean())
            shown = np.where(mask, difference, np.nan)
            axes[0][c].imshow(mpimg.imread(final)[:, :, :3])
            axes[0][c].set_title(f"{label}\nSSS {sss_ms(timings):.1f} ms", fontsize=9)
            heat = axes[1][c].imshow(shown, cmap="inferno", vmin=0.0, vmax=HEATMAP_MAX)
            axes[1][c].set_title(f"vs {reference_label}: {100 * rel_rmse:.2f}%", fontsize=9)
            for row in axes:
                row[c].axis("off")
        fig.colorbar(heat, ax=list(axes[1]), fraction=0.02, pad=0.01,
                     label="max RGB |difference| / mean level")
        fig.suptitle(f"{os.path.basename(args.scene)} at {args.size}: final frame (top), diffuse difference (bottom)",
                     fontsize=10)
        fig.savefig(args.out, bbox_inches="tight")
        print("wrote", args.out)


if __name__ == "__main__":
    main()
