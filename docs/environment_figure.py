#!/usr/bin/env python3
"""The figures of docs/environment.md: renders each panel with build/dermis
and tiles them with their labels (matplotlib).

    python3 docs/environment_figure.py [--out-dir docs] [--scan ../shared/content/LeePerrySmith/...json]

Run from the repository root after building. The scan's row is skipped when
its scene is absent. Each panel is `dermis render SCENE --size 320x180` with
the --set overrides listed below (printed as it goes).
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

ONLY_ENVIRONMENT = ["lights=[]", "ambient=[0,0,0]"]


def environment(source, occlusion, intensity=1.0):
    return [f'environment={{"source": "{source}", "intensity": {intensity}, "occlusion": "{occlusion}"}}']


OCCLUSIONS = ("none", "ssao", "transfer")
DIFFERENCE_SCALE = 4


def panels(scene):
    """(label, overrides) per panel: two environments, occlusion off / SSAO / transfer."""
    rows = []
    for source, intensity in (("sky", 0.2), ("studio", 0.3)):
        rows.append([(f"{source}, occlusion {occlusion}", ONLY_ENVIRONMENT + environment(source, occlusion, intensity))
                     for occlusion in OCCLUSIONS])
    return rows


def render(scene, overrides, out):
    command = ["build/dermis", "render", scene, "--size", "320x180", "--frames", "1", "--out", out]
    for o in overrides:
        command += ["--set", o]
    print(" ".join(command[:2] + [scene] + [f"--set '{o}'" for o in overrides]), flush=True)
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)


def figure(scene, out, title):
    grid = panels(scene)
    columns = len(grid[0]) + 1  # the last: what the transfer darkens, |none - transfer| x DIFFERENCE_SCALE
    fig, axes = plt.subplots(len(grid), columns, figsize=(3.2 * columns, 2.0 * len(grid)), dpi=100)
    with tempfile.TemporaryDirectory() as tmp:
        for r, row in enumerate(grid):
            images = []
            for c, (label, overrides) in enumerate(row):
                path = os.path.join(tmp, f"{r}_{c}.png")
                render(scene, overrides, path)
                images.append(mpimg.imread(path)[:, :, :3])
                axes[r][c].imshow(images[-1])
                axes[r][c].set_title(label, fontsize=9)
                axes[r][c].axis("off")
            none, transfer = images[OCCLUSIONS.index("none")], images[OCCLUSIONS.index("transfer")]
            darkened = ((none - transfer).max(axis=2) * DIFFERENCE_SCALE).clip(0.0, 1.0)
            axes[r][-1].imshow(darkened, cmap="gray", vmin=0.0, vmax=1.0)
            axes[r][-1].set_title(f"none - transfer, x{DIFFERENCE_SCALE}", fontsize=9)
            axes[r][-1].axis("off")
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(out)
    print("wrote", out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out-dir", default="docs")
    parser.add_argument("--scan", default="content/scenes/lee_perry_smith.json")
    args = parser.parse_args()
    figure("content/scenes/default.json", os.path.join(args.out_dir, "environment_head.png"),
           "procedural head, environment light only")
    if os.path.exists(args.scan):
        try:
            figure(args.scan, os.path.join(args.out_dir, "environment_scan.png"), "Lee Perry-Smith scan, environment light only")
        except subprocess.CalledProcessError as error:
            print("scan skipped:", error, file=sys.stderr)
    else:
        print("scan skipped: no", args.scan)


if __name__ == "__main__":
    main()
