#!/usr/bin/env python3
"""Plots for `dermis bench`: reads DIR/results.csv, DIR/passes.csv and
DIR/summary.json, which the bench writes, and draws

  DIR/pareto.png  two panels, total error (against the full reference) and
                  scatter error (against the matched-irradiance reference),
                  over frame GPU ms, one colour per front group (each
                  screen-space technique, texture space), each group's Pareto
                  front joined by a line, the shipped defaults ringed;
  DIR/regions.png the shipped defaults' relative RMSE by cause and region;
  DIR/errors.md   the same as a Markdown table (for docs/bench.md);
  DIR/passes.png  stacked GPU ms per pass group of the configurations on the
                  fronts and the defaults.

usage: plot_bench.py DIR     (needs matplotlib; Debian: python3-matplotlib)
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MODE_STYLE = {"ss": ("tab:blue", "screen space"), "ts": ("tab:red", "texture space")}
# One Pareto front per screen-space technique (results.csv's technique column; BenchReport.h paretoGroup).
GROUP_STYLE = {"ss gaussians": ("tab:blue", "ss gaussians"), "ss separable": ("tab:green", "ss separable"),
               "ss disk": ("tab:purple", "ss disk"), "ts": ("tab:red", "texture space")}


def front_group(row):
    return f"{row['mode']} {row['technique']}" if row.get("technique") else row["mode"]

# Pass names (render/Renderer and passes/*) grouped so that a bar has a few
# readable layers instead of forty: the first prefix that matches wins.
PASS_GROUPS = [
    ("shadow", ("shadow",)),
    ("G-buffer", ("gbuffer",)),
    ("SSAO", ("ssao",)),
    ("lighting", ("lighting", "lean")),
    ("SS blurs", ("sss ",)),
    ("transmittance", ("transmittance",)),
    ("TS stretch + TSM", ("ts ",)),  # refined below for irradiance and blurs
    ("composite + tonemap", ("composite", "tonemap", "aov")),
]


def pass_group(name):
    if name.startswith("ts "):
        if " irradiance" in name or " dilate" in name:
            return "TS irradiance"
        if " g" in name and (name.endswith(" u") or name.endswith(" v")):
            return "TS blurs"
        if " gather" in name or name == "ts init":
            return "TS gather"
        return "TS stretch + TSM"
    for group, prefixes in PASS_GROUPS:
        if name.startswith(prefixes):
            return group
    return "other"


GROUP_ORDER = ["shadow", "G-buffer", "SSAO", "lighting", "SS blurs", "transmittance", "TS stretch + TSM",
               "TS irradiance", "TS blurs", "TS gather", "composite + tonemap", "other"]


def read_rows(directory):
    with open(os.path.join(directory, "results.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        for key in ("frame_gpu_ms", "relative_rmse", "scatter_rel_rmse"):
            row[key] = float(row[key])
        row["default"] = row["default"] == "1"
        row["pareto"] = row["pareto"] == "1"
        row["pareto_scatter"] = row["pareto_scatter"] == "1"
    return rows


def save(figure, path):
    temporary = path + ".tmp.png"
    figure.savefig(temporary, dpi=110)
    os.replace(temporary, path)
    plt.close(figure)


# (error column, front column, axis label) of each panel of pareto.png.
PARETO_PANELS = [
    ("relative_rmse", "pareto", "total error: relative RMSE against the full CPU reference (%)"),
    ("scatter_rel_rmse", "pareto_scatter",
     "scatter error: relative RMSE against the matched-irradiance reference (%)"),
]


def plot_front(axes, rows, error_key, front_key):
    fronts = []
    # The front groups as the bench wrote them; a group without a style gets the next colour.
    for index, group in enumerate(dict.fromkeys(front_group(r) for r in rows)):
        colour, name = GROUP_STYLE.get(group, (f"C{index + 4}", group))
        mine = [r for r in rows if front_group(r) == group and r[error_key] == r[error_key]]
        if not mine:
            continue
        axes.scatter([r["frame_gpu_ms"] for r in mine], [100 * r[error_key] for r in mine], s=18,
                     color=colour, alpha=0.45, label=f"{name}: every configuration")
        front = sorted((r for r in mine if r[front_key]), key=lambda r: r["frame_gpu_ms"])
        axes.plot([r["frame_gpu_ms"] for r in front], [100 * r[error_key] for r in front], "-o",
                  color=colour, markersize=5, label=f"{name}: Pareto front")
        for r in front:
            axes.annotate(r["id"], (r["frame_gpu_ms"], 100 * r[error_key]), fontsize=7,
                          xytext=(3, 3), textcoords="offset points", color=colour)
        fronts.extend(front)
        for r in mine:
            if r["default"]:
                axes.scatter([r["frame_gpu_ms"]], [100 * r[error_key]], s=160, facecolors="none",
                             edgecolors="black", linewidths=1.5, zorder=5)
    axes.scatter([], [], s=160, facecolors="none", edgecolors="black", label="shipped default settings")
    axes.set_xscale("log")
    axes.grid(True, which="both", alpha=0.3)
    return fronts


def plot_pareto(rows, summary, path):
    figure, panels = plt.subplots(1, 2, figsize=(18, 6.5))
    fronts = {}
    for axes, (error_key, front_key, label) in zip(panels, PARETO_PANELS):
        for r in plot_front(axes, rows, error_key, front_key):
            fronts[r["id"]] = r
        axes.set_xlabel(f"frame GPU ms (median of {summary['frames']} frames; {summary['renderer']})")
        axes.set_ylabel(label, fontsize=9)
        axes.legend(fontsize=7)
    panels[1].axhline(100 * summary["scatter_error_limit"], color="grey", linestyle="--", linewidth=1)
    fixed = ", ".join(summary.get("every_configuration", [])) or "nothing"
    figure.suptitle(f"{summary['scene']} at {summary['width']}x{summary['height']}: run time against error "
                    f"(set in every configuration, as in the reference: {fixed})", fontsize=10)
    # The fronts' configurations, by the id written beside each point.
    key = "\n".join(f"{r['id']:>3}  {front_group(r)} {r['label']}" for r in sorted(fronts.values(), key=lambda r: int(r["id"])))
    figure.text(0.755, 0.5, "Pareto fronts (id, mode and technique, swept values):\n" + key, fontsize=6, family="monospace",
                va="center")
    figure.tight_layout(rect=(0, 0, 0.75, 0.95))
    save(figure, path)


def plot_regions(summary, path):
    """The shipped defaults' relative RMSE, one group of bars per region, one bar per mode and cause."""
    modes = [m for m, entry in summary["modes"].items() if entry.get("default_errors")]
    if not modes:
        return
    causes = list(summary["modes"][modes[0]]["default_errors"].keys())
    regions = list(summary["modes"][modes[0]]["default_errors"][causes[0]].keys())
    figure, axes = plt.subplots(figsize=(12, 5))
    bars = [(m, c) for m in modes for c in causes]
    width = 0.8 / len(bars)
    hatches = {"total": "", "irradiance": "//", "scatter": ".."}
    for k, (mode, cause) in enumerate(bars):
        colour, name = MODE_STYLE.get(mode, (f"C{k}", mode))
        values = []
        for region in regions:
            figure_ = summary["modes"][mode]["default_errors"][cause][region]
            values.append(100 * figure_["relative_rmse"] if figure_ and figure_["relative_rmse"] is not None else 0.0)
        xs = [i + (k - len(bars) / 2 + 0.5) * width for i in range(len(regions))]
        axes.bar(xs, values, width, color=colour, alpha=0.35 + 0.65 * (causes.index(cause) + 1) / len(causes),
                 hatch=hatches.get(cause, ""), edgecolor="black", linewidth=0.4, label=f"{name}: {cause}")
    pixels = summary.get("region_pixels", {})
    axes.set_xticks(range(len(regions)))
    axes.set_xticklabels([f"{r}\n({pixels.get(r, '?')} px)" for r in regions], fontsize=8)
    axes.set_ylabel("relative RMSE of the diffuse AOV (%)")
    axes.axhline(100 * summary["scatter_error_limit"], color="grey", linestyle="--", linewidth=1)
    axes.set_title(f"{summary['scene']} at {summary['width']}x{summary['height']}: the shipped defaults' error "
                   "by cause and region", fontsize=10)
    axes.grid(True, axis="y", alpha=0.3)
    axes.legend(fontsize=7, ncol=2)
    figure.tight_layout()
    save(figure, path)


def plot_passes(rows, passes, summary, path):
    chosen = [r for r in rows if r["pareto"] or r["pareto_scatter"] or r["default"]]
    chosen.sort(key=lambda r: (r["mode"], r["frame_gpu_ms"]))
    totals = {r["id"]: {} for r in chosen}
    for p in passes:
        if p["id"] in totals:
            group = pass_group(p["pass"])
            totals[p["id"]][group] = totals[p["id"]].get(group, 0.0) + float(p["gpu_ms"])
    groups = [g for g in GROUP_ORDER if any(g in t for t in totals.values())]
    # Horizontal bars, so that the configurations' long labels stay readable.
    figure, axes = plt.subplots(figsize=(12, 1.6 + 0.38 * len(chosen)))
    colours = plt.get_cmap("tab20").colors
    lefts = [0.0] * len(chosen)
    for k, group in enumerate(groups):
        widths = [totals[r["id"]].get(group, 0.0) for r in chosen]
        axes.barh(range(len(chosen)), widths, left=lefts, color=colours[k % len(colours)], label=group)
        lefts = [x + w for x, w in zip(lefts, widths)]
    labels = [f"{r['id']}  {r['mode']} {r['label']}{' (default)' if r['default'] and r['label'] != 'default' else ''}"
              for r in chosen]
    axes.set_yticks(range(len(chosen)))
    axes.set_yticklabels(labels, fontsize=7)
    axes.invert_yaxis()
    axes.set_xlabel("GPU ms per frame (median per pass)")
    axes.set_title(f"{summary['scene']} at {summary['width']}x{summary['height']}: "
                   "per-pass cost of the Pareto-front and default configurations", fontsize=10)
    axes.legend(fontsize=7, ncol=2, loc="upper right")  # the cheap screen-space rows are on top
    figure.tight_layout()
    save(figure, path)


def write_error_table(summary, path):
    """One row per region, one column per mode and cause: the shipped defaults' relative RMSE (%)."""
    modes = [m for m, entry in summary["modes"].items() if entry.get("default_errors")]
    if not modes:
        return
    causes = list(summary["modes"][modes[0]]["default_errors"].keys())
    regions = list(summary["modes"][modes[0]]["default_errors"][causes[0]].keys())
    pixels = summary.get("region_pixels", {})
    lines = [f"{summary['scene']} at {summary['width']}x{summary['height']}, shipped defaults, "
             "relative RMSE of the diffuse AOV (%):", "",
             "| region (pixels) | " + " | ".join(f"{m} {c}" for m in modes for c in causes) + " |",
             "| --- |" + " --- |" * (len(modes) * len(causes))]
    for region in regions:
        cells = []
        for mode in modes:
            for cause in causes:
                figure = summary["modes"][mode]["default_errors"][cause][region]
                value = figure["relative_rmse"] if figure else None
                cells.append("—" if value is None else f"{100 * value:.2f}")
        lines.append(f"| {region} ({pixels.get(region, '?')}) | " + " | ".join(cells) + " |")
    temporary = path + ".tmp"
    with open(temporary, "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(temporary, path)


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    directory = sys.argv[1]
    try:
        rows = read_rows(directory)
        with open(os.path.join(directory, "passes.csv"), newline="") as f:
            passes = list(csv.DictReader(f))
        with open(os.path.join(directory, "summary.json")) as f:
            summary = json.load(f)
    except (OSError, ValueError, KeyError) as error:
        print(f"error: {directory}: {error}", file=sys.stderr)
        return 1
    plot_pareto(rows, summary, os.path.join(directory, "pareto.png"))
    plot_passes(rows, passes, summary, os.path.join(directory, "passes.png"))
    plot_regions(summary, os.path.join(directory, "regions.png"))
    write_error_table(summary, os.path.join(directory, "errors.md"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
