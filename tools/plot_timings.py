#!/usr/bin/env python3
"""Per-frame timings of `dermis render --timings FILE.csv` as a picture: the
GPU ms of every pass in every frame, stacked (the passes that take the most
on top, the rest summed as "other"), the frame's total as a line, warm-up
frames shaded; and beside it each pass's spread over the frames (its 5th to
95th percentile and median), the way the summary reports them.

usage: plot_timings.py TIMINGS.csv OUT.png [--top N]
       (needs matplotlib; Debian: python3-matplotlib)
"""
import csv
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def percentile(values, p):
    """numpy.percentile's default: linear between order statistics."""
    v = sorted(values)
    position = p / 100.0 * (len(v) - 1)
    below = int(position)
    above = min(below + 1, len(v) - 1)
    return v[below] + (position - below) * (v[above] - v[below])


def main(csv_path, png_path, top):
    frames = OrderedDict()  # frame -> {pass: gpu ms}
    warm_up = set()
    order = []
    with open(csv_path) as f:
        for row in csv.DictReader(f):
            frame = int(row["frame"])
            frames.setdefault(frame, {})
            frames[frame][row["pass"]] = frames[frame].get(row["pass"], 0.0) + float(row["gpu_ms"])
            if row["warm_up"] == "1":
                warm_up.add(frame)
            if row["pass"] not in order:
                order.append(row["pass"])
    if not frames:
        sys.exit(f"{csv_path}: no frames")
    measured = [f for f in frames if f not in warm_up]
    median_of = {p: percentile([frames[f].get(p, 0.0) for f in measured] or [0.0], 50) for p in order}
    biggest = sorted(order, key=lambda p: -median_of[p])[:top]
    shown = [p for p in order if p in biggest]
    xs = list(frames)
    layers = [[frames[f].get(p, 0.0) for f in xs] for p in shown]
    layers.append([sum(v for p, v in frames[f].items() if p not in biggest) for f in xs])
    labels = shown + ["other"]

    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2), dpi=100, gridspec_kw={"width_ratios": [3, 2]})
    # tab20 for the passes (tab10 repeats its first colour at the 11th layer), grey for "other".
    colours = [plt.get_cmap("tab20")(i % 20) for i in range(len(shown))] + ["0.6"]
    left.stackplot(xs, layers, labels=labels, colors=colours, alpha=0.85)
    left.plot(xs, [sum(frames[f].values()) for f in xs], color="black", lw=1, label="frame (sum)")
    for f in warm_up:
        left.axvspan(f - 0.5, f + 0.5, color="grey", alpha=0.25, lw=0)
    left.set_xlabel("frame" + (" (warm-up shaded)" if warm_up else ""))
    left.set_ylabel("GPU ms")
    left.set_title("every pass, every frame")
    left.set_xlim(xs[0] - 0.5, xs[-1] + 0.5)
    left.legend(fontsize=6, loc="upper right", ncol=2)

    names = list(reversed(shown))
    for i, p in enumerate(names):
        values = [frames[f].get(p, 0.0) for f in measured] or [0.0]
        lo, mid, hi = percentile(values, 5), percentile(values, 50), percentile(values, 95)
        right.plot([lo, hi], [i, i], color="tab:blue", lw=3, alpha=0.5)
        right.plot([mid], [i], "o", color="tab:blue", ms=4)
    right.set_yticks(range(len(names)))
    right.set_yticklabels(names, fontsize=7)
    right.set_xlabel("GPU ms: 5th-95th percentile and median")
    right.set_title(f"spread over {len(measured)} frames")
    fig.tight_layout()
    fig.savefig(png_path)


if __name__ == "__main__":
    args = sys.argv[1:]
    top = 8
    if "--top" in args:
        i = args.index("--top")
        top = int(args[i + 1])
        del args[i:i + 2]
    if len(args) != 2:
        sys.exit(__doc__)
    main(args[0], args[1], top)
