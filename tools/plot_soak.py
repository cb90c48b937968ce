#!/usr/bin/env python3
"""Plot for `dermis soak`: reads DIR/soak.json and draws DIR/soak.png, the
resident memory (top) and the texture pool's bytes (bottom) over the frames,
one line per mode, the warm-up shaded and the two compared windows marked.

usage: plot_soak.py DIR     (needs matplotlib; Debian: python3-matplotlib)
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MODE_STYLE = {"ss": ("tab:blue", "screen space"), "ts": ("tab:red", "texture space")}
MIB = 1024.0 * 1024.0


def main(out_dir):
    with open(os.path.join(out_dir, "soak.json")) as f:
        report = json.load(f)
    fig, (rss, pool) = plt.subplots(2, 1, figsize=(7.4, 4.2), sharex=True, dpi=100)
    for mode, data in report["modes"].items():
        colour, label = MODE_STYLE.get(mode, ("black", mode))
        frames = [s["frame"] for s in data["samples"]]
        rss.plot(frames, [s["resident_bytes"] / MIB for s in data["samples"]], color=colour, lw=1, label=label)
        pool.plot(frames, [s["pool_bytes"] / MIB for s in data["samples"]], color=colour, lw=1, label=label)
    first = next(iter(report["modes"].values()))
    for ax in (rss, pool):
        ax.axvspan(0, report["warmup"], color="0.9", lw=0)
        for start, end in (first["first_window"], first["last_window"]):
            ax.axvspan(start - 1, end, color="tab:green", alpha=0.12, lw=0)
        ax.grid(True, lw=0.3)
    rss.set_ylabel("resident (MiB)")
    pool.set_ylabel("texture pool (MiB)")
    pool.set_xlabel("frame (each mode from 0; grey: warm-up; green: the compared periods)")
    rss.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8)
    rss.set_title("dermis soak: %s at %s, %d frames per mode" % (os.path.basename(report["scene"]), report["size"],
                                                                   report["frames"]), fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "soak.png"))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
