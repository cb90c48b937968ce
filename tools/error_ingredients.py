#!/usr/bin/env python3
"""The error of a scene split by ingredient (docs/bench.md and docs/results/bench.md, "Error by ingredient").

usage: tools/error_ingredients.py SCENE --out DIR [--size WxH] [--density N]
                                  [--irradiance-size N] [--dermis PATH]

Runs `dermis compare SCENE --errors` once with every ingredient on, then once
per ingredient with it switched off on both sides (the renderer and the CPU
reference read the same scene overrides), each into DIR/<ingredient>/, and
writes DIR/ingredients.md and DIR/ingredients.json: per ingredient, the
screen-space and texture-space error by cause over all SSS pixels, the
silhouette band and the rest, and its share (the error with it on minus with
it off). References that an ingredient does not change are computed once and
copied (the transmittance and the pixel sampling reuse the baseline's).

Ingredients:
  normal_map           every material's normal map (use_normal_map=false)
  shadows              every light's shadow (lights.N.shadow=false): shadow
                       maps in the renderer, shadow rays in the reference
  energy_conservation  the share 1 - rho_s rho_dt(N.L) that the specular
                       lobe leaves the diffuse light, both ways
  transmittance        the renderer's back-lit transmittance pass (the
                       reference has none of its own: its profile already
                       carries light through thin parts)
  pixel_sampling       with SSS off on both sides, references box-filtered
                       over 16 sub-samples per pixel instead of the pixel
                       centre (pixels they do not cover fully left out): the
                       engine's aliasing, which the baseline does not count
                       (its irradiance row is the one to read)
SSAO is not an ingredient: the reference takes AO as 1, so `--errors` always
turns SSAO off.
"""

import argparse
import json
import shutil
import subprocess
import sys
from pathlib import Path

CAUSES = ("total", "irradiance", "scatter")
REGIONS = ("all", "silhouette", "rest")
MODES = ("ss", "ts")


def ingredient_overrides(scene):
    lights = len(scene.get("lights", []))
    characters = len(scene.get("characters", []))
    return {
        "normal_map": [f"characters.{c}.material.use_normal_map=false" for c in range(characters)],
        "shadows": [f"lights.{i}.shadow=false" for i in range(lights)],
        "energy_conservation": ["settings.energy_conservation=false"],
        "transmittance": ["settings.transmittance.enabled=false"],
        # SSS off: a full reference at 16 sub-samples would cost 16 of the baseline's.
        "pixel_sampling": ["settings.sss.enabled=false"],
    }


def run_compare(dermis, scene_path, out, size, overrides, extra):
    command = [dermis, "compare", scene_path, "--errors", "--frames", "1", "--size", size, "--out", str(out), "--quiet"]
    for override in overrides:
        command += ["--set", override]
    command += extra
    print("error_ingredients: " + " ".join(command), file=sys.stderr, flush=True)
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"error_ingredients: {' '.join(command)} failed ({result.returncode}):\n{result.stderr}")
    metrics = json.loads((out / "metrics.json").read_text())
    return {mode: {cause: {region: metrics["errors"][mode][cause][region]["relative_rmse"]
                           for region in REGIONS if metrics["errors"][mode][cause].get(region)}
                   for cause in CAUSES} for mode in MODES}


def seed_references(source, target):
    """Copies the baseline's CPU images (and their notes); compare reuses those whose note matches."""
    target.mkdir(parents=True, exist_ok=True)
    for path in source.iterdir():
        if path.suffix in (".exr", ".json") and path.name not in ("ss.exr", "ts.exr", "metrics.json"):
            shutil.copy2(path, target / path.name)


def table(results):
    lines = ["| ingredient switched off | mode | total all / band / rest | irradiance all / band / rest | scatter all / band / rest |",
             "| --- | --- | --- | --- | --- |"]
    for name, errors in results.items():
        for mode in MODES:
            cells = []
            for cause in CAUSES:
                figures = errors[mode][cause]
                cells.append(" / ".join(f"{100 * figures[r]:.2f}" if r in figures else "–" for r in REGIONS))
            lines.append(f"| {name} | {mode} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scene")
    parser.add_argument("--out", required=True)
    parser.add_argument("--size", default="320x180")
    parser.add_argument("--density", help="the references' quadrature density (compare's default: 8)")
    parser.add_argument("--irradiance-size", help="texels of the engine's irradiance for the matched reference")
    parser.add_argument("--dermis", default=str(Path(__file__).resolve().parent.parent / "build" / "dermis"))
    args = parser.parse_args()
    try:
        scene = json.loads(Path(args.scene).read_text())
    except (OSError, json.JSONDecodeError) as error:
        sys.exit(f"error: {args.scene}: {error}")
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    passed = []
    if args.density:
        passed += ["--density", args.density]
    if args.irradiance_size:
        passed += ["--irradiance-size", args.irradiance_size]
    results = {"(none)": run_compare(args.dermis, args.scene, out / "baseline", args.size, [], passed)}
    for name, overrides in ingredient_overrides(scene).items():
        target = out / name
        seed_references(out / "baseline", target)
        extra = passed + (["--spp", "16"] if name == "pixel_sampling" else [])
        results[name] = run_compare(args.dermis, args.scene, target, args.size, overrides, extra)

    shares = {name: {mode: {cause: {region: results["(none)"][mode][cause][region] - figures[mode][cause][region]
                                    for region in figures[mode][cause] if region in results["(none)"][mode][cause]}
                            for cause in (("irradiance",) if name == "pixel_sampling" else CAUSES)}
                     for mode in MODES}
              for name, figures in results.items() if name != "(none)"}
    (out / "ingredients.json").write_text(json.dumps({"scene": args.scene, "size": args.size, "errors": results,
                                                       "shares": shares}, indent=2) + "\n")
    text = (f"{args.scene} at {args.size}: relative RMSE (%) of the diffuse AOV over SSS pixels, "
            "with every ingredient on and with each switched off on both sides "
            "(`tools/error_ingredients.py`):\n\n" + table(results))
    (out / "ingredients.md").write_text(text)
    print(text)


if __name__ == "__main__":
    main()
