#!/usr/bin/env python3
"""Joins rendered PNGs side by side, each under its label, into one figure
(the README's and the chapters' side-by-side images).

    python3 docs/panels.py --out FIGURE.png [--crop X,Y,W,H] [--width-in W]
        LABEL=IMAGE.png [LABEL=IMAGE.png ...]

--crop keeps the rectangle of W x H pixels whose top-left corner is (X, Y)
of each image; the panels are drawn without smoothing, so a crop is
enlarged pixel for pixel. --width-in is the figure's width in inches at
100 dpi (default: 4 inches a panel).
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402


def parse_crop(text):
    try:
        x, y, w, h = (int(v) for v in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f"--crop: '{text}' is not X,Y,W,H (four integers)")
    if w <= 0 or h <= 0 or x < 0 or y < 0:
        raise argparse.ArgumentTypeError(f"--crop: '{text}' needs X, Y >= 0 and W, H > 0")
    return x, y, w, h


def parse_panel(text):
    label, sep, path = text.partition("=")
    if not sep or not path:
        raise argparse.ArgumentTypeError(f"'{text}' is not LABEL=IMAGE.png")
    return label, path


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True)
    parser.add_argument("--crop", type=parse_crop)
    parser.add_argument("--width-in", type=float)
    parser.add_argument("panels", nargs="+", type=parse_panel, metavar="LABEL=IMAGE.png")
    args = parser.parse_args()
    images = []
    for label, path in args.panels:
        image = mpimg.imread(path)
        if args.crop:
            x, y, w, h = args.crop
            if y + h > image.shape[0] or x + w > image.shape[1]:
                parser.error(f"{path}: --crop {x},{y},{w},{h} reaches outside its {image.shape[1]}x{image.shape[0]} pixels")
            image = image[y:y + h, x:x + w]
        images.append((label, image))
    height, width = images[0][1].shape[:2]
    figure_width = args.width_in or 4.0 * len(images)
    panel_height = figure_width / len(images) * height / width
    figure, axes = plt.subplots(1, len(images), figsize=(figure_width, panel_height + 0.4), squeeze=False)
    for axis, (label, image) in zip(axes[0], images):
        axis.imshow(image, interpolation="nearest")
        axis.set_title(label, fontsize=11)
        axis.axis("off")
    figure.tight_layout(pad=0.3)
    figure.savefig(args.out, dpi=100)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
