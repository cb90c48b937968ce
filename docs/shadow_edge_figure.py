#!/usr/bin/env python3
"""The shadow-edge profile of the engine against the CPU reference: the figure
docs/shadow_edge.png of docs/shadows.md.

    mkdir -p /tmp/pen
    S="--size 160x12 --set camera.vertical_fov_deg=1.0249 --set transmittance.enabled=false"
    for d in 0.53 5; do for sss in true false; do
        build/dermis render content/scenes/penumbra.json $S --aov diffuse --frames 1 \\
            --set lights.0.angular_diameter_deg=$d --set sss.enabled=$sss --out /tmp/pen/engine_${d}_$sss.exr
        build/dermis reference content/scenes/penumbra.json $S --quiet \\
            --set lights.0.angular_diameter_deg=$d --set sss.enabled=$sss --out /tmp/pen/reference_${d}_$sss.exr
    done; done
    /usr/bin/python3 docs/shadow_edge_figure.py csv /tmp/pen      # each EXR's middle row -> a CSV beside it
    /usr/bin/python3 docs/shadow_edge_figure.py plot /tmp/pen docs/shadow_edge.png

160x12 pixels at a 1.0249-degree vertical field of view are the middle
(12 rows x 160 columns) of edge.json's 640x360 frame: 0.447 mm per pixel on
the plane 0.3 m below, 71.5 mm across (the reference with SSS costs many
minutes per light size on two shared cores, so only what the plot shows is
rendered; the edge runs along the rows, so the rows differ only in noise).
The CSVs hold x (mm on the plane, 0 at the geometric shadow edge) and the
green channel of the diffuse AOV averaged over the rows. Prints, per light
size and SSS setting, the largest |engine - reference| as a fraction of the
reference's lit level (the mean of its right tenth).
"""
import subprocess
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from PIL import Image  # noqa: E402

MM_PER_PIXEL = 2 * 300.0 * np.tan(np.radians(1.0249 / 2)) / 12
SIZES = ["0.53", "5"]


def exr_rows(path):
    """Green channel of an EXR as an array of rows (oiiotool to a float TIFF, read by Pillow)."""
    tif = Path(path).with_suffix(".g.tif")
    subprocess.run(["oiiotool", str(path), "--ch", "G", "-d", "float", "-o", str(tif)], check=True)
    return np.array(Image.open(tif), dtype=np.float64)


def to_csv(folder):
    for exr in sorted(Path(folder).glob("*.exr")):
        rows = exr_rows(exr)
        profile = rows.mean(axis=0)
        xs = (np.arange(len(profile)) + 0.5 - len(profile) / 2) * MM_PER_PIXEL
        np.savetxt(exr.with_suffix(".csv"), np.column_stack([xs, profile]), delimiter=",", header="x_mm,diffuse_g",
                   comments="")


def load(folder, name):
    data = np.loadtxt(Path(folder) / f"{name}.csv", delimiter=",", skiprows=1)
    return data[:, 0], data[:, 1]


def plot(folder, out):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4), constrained_layout=True)
    for ax, size in zip(axes, SIZES):
        for sss, style in (("true", "-"), ("false", ":")):
            x, reference = load(folder, f"reference_{size}_{sss}")
            _, engine = load(folder, f"engine_{size}_{sss}")
            lit = reference[len(reference) * 9 // 10:].mean()
            worst = np.abs(engine - reference).max() / lit
            at = x[np.abs(engine - reference).argmax()]
            print(f"{size} deg, sss {sss}: largest |engine - reference| = {worst:.4f} of the lit level, at x = {at:.2f} mm")
            label = "SSS on" if sss == "true" else "SSS off"
            ax.plot(x, reference / lit, "k" + style, lw=1.5, label=f"reference, {label}")
            ax.plot(x, engine / lit, "C3" + style, lw=1.2, label=f"engine (pcss), {label}")
        ax.set_xlim(*((-4, 4) if size == "0.53" else (-15, 15)))
        ax.set_title(f"directional light, angular diameter {size} deg")
        ax.set_xlabel("x on the skin plane (mm; geometric shadow edge at 0)")
        ax.set_ylabel("diffuse AOV / lit level")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="upper left")
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    if sys.argv[1] == "csv":
        to_csv(sys.argv[2])
    else:
        plot(sys.argv[2], sys.argv[3])
