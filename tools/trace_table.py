#!/usr/bin/env python3
"""The slices of one frame of a `dermis render --trace` file as a Markdown
table, for reading a trace without a browser: per pass, its CPU and GPU
slices (start in ms from the frame's CPU start, length in ms), and the
frame's culled passes with their reasons.

usage: trace_table.py TRACE.json [FRAME]   (FRAME: default the last one)
"""
import json
import sys


def main(path, wanted):
    with open(path) as f:
        events = json.load(f)["traceEvents"]
    frames = sorted({e["args"]["frame"] for e in events if e.get("ph") == "X"})
    frame = frames[-1] if wanted is None else wanted
    mine = [e for e in events if e.get("args", {}).get("frame") == frame]
    cpu_frame = next(e for e in mine if e["ph"] == "X" and e["cat"] == "frame" and e["tid"] == 1)
    origin = cpu_frame["ts"]
    rows = {}
    for e in mine:
        if e["ph"] != "X" or e["cat"] == "frame":
            continue
        rows.setdefault(e["name"], {})["gpu" if e["tid"] == 2 else "cpu"] = ((e["ts"] - origin) / 1e3, e["dur"] / 1e3)
    print(f"Frame {frame} of {path} (ms; starts from the frame's CPU start):\n")
    print("| pass | CPU start | CPU ms | GPU start | GPU ms |\n| --- | ---: | ---: | ---: | ---: |")
    for name, slices in rows.items():
        cpu = slices.get("cpu", (float("nan"),) * 2)
        gpu = slices.get("gpu", (float("nan"),) * 2)
        print(f"| {name} | {cpu[0]:.3f} | {cpu[1]:.3f} | {gpu[0]:.3f} | {gpu[1]:.3f} |")
    culled = [e for e in mine if e["ph"] == "i"]
    if culled:
        print("\nCulled in this frame (instant events):\n")
        for e in culled:
            print(f"- {e['args']['pass']}: {e['args']['because']}")


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    main(sys.argv[1], int(sys.argv[2]) if len(sys.argv) == 3 else None)
