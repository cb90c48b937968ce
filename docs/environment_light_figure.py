#!/usr/bin/env python3
"""The figure of docs/environment.md, "The dominant light": the procedural
head under the two generated maps of docs/environment_maps.py (outdoor, a low
sun; indoor, soft boxes), environment light only, with the dominant light
left in the map (extract_light off) and taken out as a shadowed light
(auto), and what taking it out changes (|auto - off| x 2).

    python3 docs/environment_light_figure.py [--out docs/environment_light.png] [--maps DIR]

Run from the repository root after building. Each panel is `dermis render
content/scenes/default.json --size 320x180` with the --set overrides printed
as it goes.
"""
import argparse
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

SCENE = "content/scenes/default.json"
DIFFERENCE_SCALE = 2


def render(overrides, out):
    command = ["build/dermis", "render", SCENE, "--size", "320x180", "--frames", "1", "--out", out]
    for o in overrides:
        command += ["--set", o]
    print(" ".join(command[:3] + [f"--set '{o}'" for o in overrides]), flush=True)
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="docs/environment_light.png")
    parser.add_argument("--maps", default=None, help="where the maps are written (default: a temporary folder)")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        maps = args.maps or tmp
        subprocess.run([sys.executable, os.path.join(os.path.dirname(__file__), "environment_maps.py"), "--out-dir", maps],
                       check=True, stdout=subprocess.DEVNULL)
        rows = [("outdoor, low sun", os.path.join(maps, "outdoor.hdr"), 0.3), ("indoor, soft boxes", os.path.join(maps, "indoor.hdr"), 0.15)]
        fig, axes = plt.subplots(len(rows), 3, figsize=(9.6, 2.0 * len(rows)), dpi=100)
        for r, (label, path, intensity) in enumerate(rows):
            images = {}
            for extract in ("off", "auto"):
                overrides = ["lights=[]", "ambient=[0,0,0]",
                             f'environment={{"source": "{path}", "intensity": {intensity}, "extract_light": "{extract}"}}']
                out = os.path.join(tmp, f"{r}_{extract}.png")
                render(overrides, out)
                images[extract] = mpimg.imread(out)[:, :, :3]
            for c, extract in enumerate(("off", "auto")):
                axes[r][c].imshow(images[extract])
                axes[r][c].set_title(f"{label}, extract_light {extract}", fontsize=9)
                axes[r][c].axis("off")
            changed = (abs(images["auto"] - images["off"]).max(axis=2) * DIFFERENCE_SCALE).clip(0.0, 1.0)
            axes[r][2].imshow(changed, cmap="gray", vmin=0.0, vmax=1.0)
            axes[r][2].set_title(f"|auto - off|, x{DIFFERENCE_SCALE}", fontsize=9)
            axes[r][2].axis("off")
        fig.suptitle("procedural head, environment light only: the dominant light kept in the SH or taken out", fontsize=10)
        fig.tight_layout()
        fig.savefig(args.out)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
