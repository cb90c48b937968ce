#!/usr/bin/env python3
"""The three variants of Vila Verde 2015 side by side, with difference heatmaps: the
figure docs/lean_variants.png of docs/lean.md.

    for v in c lcb lbb; do
        build/dermis render content/scenes/default.json --size 960x540 --frames 1 \
            --variant $v --out /tmp/lean/$v.png
        build/dermis render content/scenes/default.json --size 960x540 --frames 1 \
            --variant $v --aov specular --out /tmp/lean/${v}_spec.exr
        oiiotool /tmp/lean/${v}_spec.exr --ch R,G,B --mulc 25 -d uint16 -o /tmp/lean/${v}_spec.png
    done
    python3 docs/lean_figure.py /tmp/lean docs/lean_variants.png

Row 1: the tone-mapped frames (cropped to the head). Row 2: per-pixel
largest channel difference of the displayed (sRGB) values, in false colour
with one scale bar. Row 3: the specular alone (linear, x25): KS from the
mip-mapped pore normals in C, the LEAN lobe of the blurred moments in LBB,
and their difference. Prints the mean and largest differences over the
pixels where any of the three differs from the background.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

VARIANTS = [("c", "C: Jimenez, KS specular"), ("lcb", "LCB: LEAN, control blur"),
            ("lbb", "LBB: LEAN, bilateral blur")]
PAIRS = [("lcb", "c"), ("lbb", "c"), ("lbb", "lcb")]


def main(folder, out):
    images = {v: mpimg.imread(f"{folder}/{v}.png")[:, :, :3].astype(np.float64) for v, _ in VARIANTS}
    height, width, _ = images["c"].shape
    background = images["c"][0, 0]
    covered = np.zeros((height, width), dtype=bool)
    for image in images.values():
        covered |= np.abs(image - background).max(axis=2) > 1.5 / 255.0
    rows, cols = np.nonzero(covered)
    pad = 12
    top, bottom = max(rows.min() - pad, 0), min(rows.max() + pad, height)
    left, right = max(cols.min() - pad, 0), min(cols.max() + pad, width)

    differences = {pair: np.abs(images[pair[0]] - images[pair[1]]).max(axis=2) for pair in PAIRS}
    scale = max(float(np.percentile(d[covered], 99.9)) for d in differences.values())

    specular = {v: mpimg.imread(f"{folder}/{v}_spec.png")[:, :, :3].astype(np.float64) for v in ("c", "lbb")}
    figure, axes = plt.subplots(3, 3, figsize=(12, 9.6), dpi=100)
    for axis, (variant, title) in zip(axes[0], VARIANTS):
        axis.imshow(np.clip(images[variant][top:bottom, left:right], 0, 1), interpolation="nearest")
        axis.set_title(title, fontsize=10)
    for axis, (a, b) in zip(axes[1], PAIRS):
        d = differences[(a, b)]
        shown = axis.imshow(d[top:bottom, left:right], cmap="inferno", vmin=0.0, vmax=scale, interpolation="nearest")
        axis.set_title(f"|{a.upper()} - {b.upper()}|: mean {d[covered].mean():.4f}, max {d[covered].max():.3f}",
                       fontsize=10)
        print(f"|{a} - {b}| over {covered.sum()} pixels: mean {d[covered].mean():.5f}, "
              f"99th percentile {np.percentile(d[covered], 99):.4f}, max {d[covered].max():.4f}")
    titles = ["specular, C (KS), linear x25", "specular, LBB (LEAN), linear x25"]
    for axis, variant, title in zip(axes[2], ("c", "lbb"), titles):
        axis.imshow(np.clip(specular[variant][top:bottom, left:right], 0, 1), interpolation="nearest")
        axis.set_title(title, fontsize=10)
    specularDifference = np.abs(specular["lbb"] - specular["c"]).max(axis=2)
    axes[2][2].imshow(specularDifference[top:bottom, left:right], cmap="inferno", vmin=0.0,
                      vmax=float(np.percentile(specularDifference[covered], 99.9)), interpolation="nearest")
    axes[2][2].set_title("|LBB - C| specular (own scale: 0 to its 99.9th percentile)", fontsize=9)
    print(f"specular x25 |lbb - c|: mean {specularDifference[covered].mean():.5f}, "
          f"max {specularDifference[covered].max():.4f}; sums c {specular['c'][covered].sum():.1f}, "
          f"lbb {specular['lbb'][covered].sum():.1f}")
    for axis in axes.flat:
        axis.set_xticks([])
        axis.set_yticks([])
    bar = figure.colorbar(shown, ax=list(axes[1]), fraction=0.025, pad=0.01)
    bar.set_label("largest sRGB channel difference (display value, 0..1)")
    figure.suptitle("default.json at 960x540: the variants of Vila Verde 2015, their differences, "
                    "and the specular alone", fontsize=11)
    figure.savefig(out, dpi=100, bbox_inches="tight")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
