#!/usr/bin/env python3
"""Totals of several `dermis stress` summaries (docs/results/stress.md).

A long run is split into processes of consecutive seeds, each writing its
own summary; this adds them up: cases, failures, refusals, the sanitised
values per kind and per pass, the detectors' checks and violations, the time
by stage. It checks that the seed ranges neither overlap nor leave gaps, and
prints a Markdown report.

    tools/stress_total.py out/stress-*.json

Exit status: 0 when the summaries cover one run of consecutive seeds with no
failed case, 1 otherwise, 2 for bad usage or an unreadable summary.
"""

import json
import sys
from collections import defaultdict

SANITISED_KINDS = ("nan", "inf", "overflow", "negative")


def load(path):
    try:
        with open(path, encoding="utf-8") as f:
            summary = json.load(f)
        for key in ("cases", "first_seed", "failed_cases", "counting", "invariants", "failures"):
            if key not in summary:
                raise ValueError(f'no "{key}" key')
        return summary
    except (OSError, ValueError) as error:
        print(f"error: {path}: {error}", file=sys.stderr)
        sys.exit(2)


def seed_problems(summaries):
    """Gaps and overlaps between the summaries' seed ranges."""
    ranges = sorted((s["first_seed"], s["first_seed"] + s["cases"] - 1, path) for path, s in summaries)
    problems = []
    for (first_a, last_a, path_a), (first_b, _, path_b) in zip(ranges, ranges[1:]):
        if first_b <= last_a:
            problems.append(f"{path_a} and {path_b} overlap (seeds {first_b}-{last_a})")
        elif first_b > last_a + 1:
            problems.append(f"seeds {last_a + 1}-{first_b - 1} are missing (between {path_a} and {path_b})")
    return ranges, problems


def main(paths):
    if not paths or paths[0] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if paths else 2
    summaries = [(path, load(path)) for path in paths]
    ranges, problems = seed_problems(summaries)

    totals = defaultdict(float)
    sanitised = defaultdict(int)
    per_pass = defaultdict(lambda: defaultdict(int))
    detectors = defaultdict(lambda: defaultdict(int))
    stages = defaultdict(float)
    failures = []
    for _, s in summaries:
        for key in ("cases", "failed_cases", "refused", "non_finite_texels", "seconds"):
            totals[key] += s.get(key, 0)
        for kind in SANITISED_KINDS:
            sanitised[kind] += s["counting"]["sanitised"][kind]
        for name, counts in s["counting"].get("sanitised_per_pass", {}).items():
            for kind in SANITISED_KINDS:
                per_pass[name][kind] += counts[kind]
        for name, tally in s["invariants"].items():
            detectors[name]["checked"] += tally["checked"]
            detectors[name]["violated"] += tally["violated"]
        for stage, seconds in s.get("seconds_by_stage", {}).items():
            stages[stage] += seconds
        failures += s["failures"]

    print(f"# dermis stress: {int(totals['cases'])} cases, seeds {ranges[0][0]}-{ranges[-1][1]}, "
          f"{len(summaries)} summaries\n")
    print(f"- failed cases: {int(totals['failed_cases'])}")
    print(f"- refused as they must be: {int(totals['refused'])}")
    print(f"- NaN/Inf/bad values: {int(totals['non_finite_texels'])}")
    print(f"- seconds: {totals['seconds']:.0f} in the processes, "
          f"{totals['seconds'] / max(totals['cases'], 1):.2f} per case; by stage: "
          + ", ".join(f"{stage} {seconds:.0f}" for stage, seconds in stages.items()))
    print("\n| sanitised | count |\n| --- | --- |")
    for kind in SANITISED_KINDS:
        print(f"| {kind} | {sanitised[kind]:,} |")
    print("\n| pass with sanitised values | " + " | ".join(SANITISED_KINDS) + " |")
    print("| --- |" + " --- |" * len(SANITISED_KINDS))
    for name in sorted(per_pass):
        counts = per_pass[name]
        if any(counts.values()):
            print(f"| {name} | " + " | ".join(f"{counts[k]:,}" for k in SANITISED_KINDS) + " |")
    print("\n| detector | checked | violated |\n| --- | --- | --- |")
    for name, tally in detectors.items():
        print(f"| {name} | {tally['checked']:,} | {tally['violated']:,} |")
    for problem in problems:
        print(f"\nerror: {problem}")
    for failure in failures:
        print(f"\nfailed: seed {failure['seed']}: {json.dumps(failure)[:400]}")
    return 0 if not problems and not failures and totals["failed_cases"] == 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
