#!/usr/bin/env python3
"""The default head's ear before and after a change: the matched reference,
and each mode's signed scatter error against it, before and after, on one
scale.

    /usr/bin/python3 docs/ear_error_figure.py --compare out/cmp [--scene content/scenes/default.json]
        [--size 640x360] [--crop X0,Y0,X1,Y1] [--before-shaders DIR --labels BEFORE,AFTER]
        [--out docs/thin_edges_ear.png]

Run from the repository root after building, with --compare the folder of a
`dermis compare SCENE --errors --size SIZE` run (its scatter_change_*.exr is
the matched reference's change). The script renders, with OpenImageIO
reading the EXRs: the SSS-off diffuse AOV (SSAO off, as the references take
it), whose sum with the change is the matched reference, and each mode's
diffuse AOV before and after. Without --before-shaders, before and after are
`transmittance.thin_edges` false and true (docs/screen-space.md, "Thin
edges"); with it, "before" runs the shaders of DIR (a changed copy of
shaders/, through DERMIS_SHADER_DIR) and "after" the tree's.

    docs/thin_edges_ear.png:  --compare DIR
    docs/ts_ear_taps.png:     --compare DIR --before-shaders COPY --labels "6 taps,24 taps"
                              --out docs/ts_ear_taps.png  (COPY: kBackTapsPerRing = 6)
"""
import argparse
import glob
import os
import subprocess
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import OpenImageIO as oiio  # noqa: E402


def read(path):
    image = oiio.ImageInput.open(path)
    if image is None:
        raise SystemExit(f"ear_error_figure.py: cannot read {path}: {oiio.geterror()}")
    pixels = np.asarray(image.read_image(format="float"))[..., :3]
    image.close()
    return pixels


def render(scene, size, out, sets, shaders=None):
    command = ["build/dermis", "render", scene, "--size", size, "--aov", "diffuse", "--frames", "1", "--quiet",
               "--out", out, "--set", "ssao.enabled=false"]
    for s in sets:
        command += ["--set", s]
    environment = dict(os.environ)
    if shaders:
        environment["DERMIS_SHADER_DIR"] = shaders
    print(("DERMIS_SHADER_DIR=" + shaders + " " if shaders else "") + " ".join(command), flush=True)
    subprocess.run(command, check=True, env=environment)
    return read(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--compare", required=True, help="a `dermis compare --errors` output folder")
    parser.add_argument("--scene", default="content/scenes/default.json")
    parser.add_argument("--size", default="640x360")
    parser.add_argument("--crop", default="395,115,475,235", help="x0,y0,x1,y1 in pixels (the default head's ear)")
    parser.add_argument("--before-shaders", help="a changed copy of shaders/ for the 'before' panels")
    parser.add_argument("--labels", help="BEFORE,AFTER panel titles (default: thin_edges false,thin_edges true)")
    parser.add_argument("--out", default="docs/thin_edges_ear.png")
    args = parser.parse_args()
    labels = (args.labels or "thin_edges false,thin_edges true").split(",")
    if len(labels) != 2:
        raise SystemExit(f"ear_error_figure.py: --labels {args.labels!r}: expected two titles separated by a comma")
    if args.before_shaders:
        if not os.path.isfile(os.path.join(args.before_shaders, "transmittance.frag")):
            raise SystemExit(f"ear_error_figure.py: --before-shaders {args.before_shaders}: not a copy of shaders/")
        variants = [(labels[0], [], args.before_shaders), (labels[1], [], None)]
    else:
        variants = [(labels[0], ["transmittance.thin_edges=false"], None),
                    (labels[1], ["transmittance.thin_edges=true"], None)]
    changes = glob.glob(os.path.join(args.compare, "scatter_change_*.exr"))
    if len(changes) != 1:
        raise SystemExit(f"ear_error_figure.py: {args.compare}: expected one scatter_change_*.exr, found {len(changes)}")
    x0, y0, x1, y1 = (int(v) for v in args.crop.split(","))
    with tempfile.TemporaryDirectory() as tmp:
        unscattered = render(args.scene, args.size, os.path.join(tmp, "off.exr"), ["sss.enabled=false"])
        matched = unscattered + read(changes[0])
        panels = []
        for mode in ("ss", "ts"):
            for index, (label, sets, shaders) in enumerate(variants):
                image = render(args.scene, args.size, os.path.join(tmp, f"{mode}_{index}.exr"),
                               [f"mode={mode}"] + sets, shaders)
                panels.append((f"{mode}, {label}", image))
    mask = matched.sum(-1) > 0
    scale = np.sqrt((matched[mask] ** 2).mean())
    figure, axes = plt.subplots(1, 5, figsize=(17, 5.2))
    axes[0].imshow(np.clip(matched[y0:y1, x0:x1] / np.percentile(matched[y0:y1, x0:x1], 99), 0, 1), interpolation="nearest")
    axes[0].set_title("matched reference")
    for axis, (title, image) in zip(axes[1:], panels):
        error = (image - matched).sum(-1) / (3 * scale)
        rmse = np.sqrt((((image - matched)[mask]) ** 2).mean()) / scale
        shown = axis.imshow(error[y0:y1, x0:x1], cmap="RdBu_r", vmin=-0.3, vmax=0.3, interpolation="nearest")
        axis.set_title(f"{title}\nscatter error {100 * rmse:.2f}%", fontsize=10)
    for axis in axes:
        axis.axis("off")
    figure.colorbar(shown, ax=axes[1:], shrink=0.8, label="engine - matched (RGB mean), / RMS of matched")
    figure.savefig(args.out, dpi=80, bbox_inches="tight")
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
