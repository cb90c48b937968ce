#!/usr/bin/env python3
"""Texture-space cost against screen coverage (docs/texture-space.md, "Texture size").

Renders the bending cylinder of the tests with its full UV layout and as an
atlas chart (UVs in 1/16 of the square) at four camera distances, in
texture-space mode, and prints a markdown table: the character's pixels, the
irradiance texture side the planner chose, and the GPU milliseconds of the
texture-space passes and of the frame (medians of 5 frames; on llvmpipe
single figures vary by tens of percent).

    build/tests/dermis_test_content out/content
    python3 tools/ts_coverage_table.py [build/dermis]

Counting pixels needs OpenImageIO's Python module (Debian:
python3-openimageio); without it that column says "-".
"""
import json
import os
import subprocess
import sys
import tempfile

BINARY = sys.argv[1] if len(sys.argv) > 1 else "build/dermis"
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def covered_pixels(path):
    try:
        import OpenImageIO as oiio
    except ImportError:
        return "-"
    pixels = oiio.ImageBuf(path).get_pixels(oiio.FLOAT)
    return str(int((pixels[:, :, 0] > 0).sum()))


def main():
    base = json.load(open(os.path.join(ROOT, "docs/animation_cylinder.json")))
    content = os.path.join(ROOT, "out/content")
    if not os.path.exists(os.path.join(content, "bending_cylinder_atlas.gltf")):
        sys.exit("error: out/content/bending_cylinder_atlas.gltf not found: run build/tests/dermis_test_content out/content")
    print("| distance (m) | layout | pixels | texture side | ts passes (ms) | frame (ms) |")
    print("| ---: | --- | ---: | ---: | ---: | ---: |")
    with tempfile.TemporaryDirectory() as tmp:
        for distance in [0.25, 0.5, 1.0, 2.0]:
            for name, label in [("bending_cylinder.gltf", "full"), ("bending_cylinder_atlas.gltf", "atlas (1/16)")]:
                scene = json.loads(json.dumps(base))
                scene["camera"]["position_m"] = [0.0, 0.11, distance]
                scene["characters"][0]["mesh"]["gltf"] = os.path.join(content, name)
                scene["characters"][0]["animation"]["speed"] = 0
                scene_path = os.path.join(tmp, "scene.json")
                json.dump(scene, open(scene_path, "w"))
                common = [BINARY, "render", scene_path, "--mode", "ts", "--size", "640x360", "--quiet"]
                subprocess.run(common + ["--frames", "1", "--aov", "object", "--out", os.path.join(tmp, "object.png")], check=True)
                timings = os.path.join(tmp, "t.json")
                subprocess.run(common + ["--frames", "5", "--out", os.path.join(tmp, "x.png"), "--timings", timings], check=True)
                t = json.load(open(timings))
                ts_ms = sum(p["gpu_ms"] for p in t["passes"] if p["name"].startswith("ts ") and p["executed"])
                side = t["characters"][0]["texture_space_size"]
                print(f"| {distance} | {label} | {covered_pixels(os.path.join(tmp, 'object.png'))} | {side} | {ts_ms:.0f} | {t['frame']['gpu_ms']:.0f} |", flush=True)


if __name__ == "__main__":
    main()
