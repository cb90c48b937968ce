#!/usr/bin/env python3
"""The budget crowd with full meshes and with levels of detail: the figure
docs/crowd_lod.png of docs/results/crowds.md.

    /usr/bin/python3 docs/crowd_lod_figure.py [--lod-px 1] [--size 640x360] [--out docs/crowd_lod.png]

Run from the repository root after building. Renders
content/scenes/crowd8_mixed.json twice with `build/dermis render` (tone-mapped
PNGs, one frame each: `--set lod.max_error_px=0`, then the given value), and
draws them side by side with five times their largest channel difference.
Prints each render's command, the levels `dermis render` reports, and how
many pixels differ by more than 1/255 in some channel.
"""
import argparse
import shlex
import subprocess
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

SCENE = "content/scenes/crowd8_mixed.json"


def render(size, lod_px, out):
    command = ["build/dermis", "render", SCENE, "--size", size, "--frames", "1", "--out", out,
               "--set", f"lod.max_error_px={lod_px}"]
    print(" ".join(shlex.quote(c) for c in command), flush=True)
    result = subprocess.run(command, check=True, capture_output=True, text=True)
    for line in (result.stdout + result.stderr).splitlines():
        if "level of detail" in line:
            print("  " + line.strip())
    return mpimg.imread(out)[..., :3]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--lod-px", type=float, default=1.0, help="settings.lod.max_error_px of the middle image")
    parser.add_argument("--size", default="640x360")
    parser.add_argument("--out", default="docs/crowd_lod.png")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as directory:
        full = render(args.size, 0, f"{directory}/full.png")
        levels = render(args.size, args.lod_px, f"{directory}/levels.png")
    difference = np.abs(full - levels).max(axis=2)
    changed = int((difference > 1.0 / 255.0 + 1e-6).sum())
    print(f"{changed} pixels differ by more than 1/255 in some channel")
    figure, axes = plt.subplots(1, 3, figsize=(15, 3.1), dpi=100)
    panels = [(full, "full meshes"), (levels, f"levels of detail ({args.lod_px:g} px)"),
              (np.clip(5.0 * difference, 0.0, 1.0), f"5 x largest channel difference ({changed} px > 1/255)")]
    for axis, (image, title) in zip(axes, panels):
        axis.imshow(image, cmap="gray" if image.ndim == 2 else None, vmin=0.0, vmax=1.0, interpolation="nearest")
        axis.set_title(title, fontsize=10)
        axis.axis("off")
    figure.tight_layout()
    figure.savefig(args.out)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
