#!/usr/bin/env python3
"""tools/stress_total.py on synthetic summaries whose totals are known:
the sums, and a gap or an overlap between seed ranges fails."""

import json
import os
import subprocess
import sys
import tempfile


def summary(first_seed, cases, failed=0, nan=0, overflow=0, coverage=(0, 0)):
    return {
        "cases": cases, "first_seed": first_seed, "failed_cases": failed, "refused": 1,
        "non_finite_texels": nan, "seconds": 2.0 * cases,
        "counting": {"sanitised": {"nan": nan, "inf": 0, "overflow": overflow, "negative": 0},
                     "sanitised_per_pass": {"lighting": {"nan": nan, "inf": 0, "overflow": overflow, "negative": 0}}},
        "invariants": {"coverage": {"checked": coverage[0], "violated": coverage[1]}},
        "seconds_by_stage": {"frames": 1.0 * cases},
        "failures": [{"seed": first_seed, "pass": "lighting"}] if failed else [],
    }


def run(script, directory, summaries):
    paths = []
    for i, s in enumerate(summaries):
        path = os.path.join(directory, f"s{i}.json")
        with open(path, "w", encoding="utf-8") as f:
            json.dump(s, f)
        paths.append(path)
    result = subprocess.run([sys.executable, script] + paths, capture_output=True, text=True)
    return result.returncode, result.stdout


def main():
    script = os.path.join(sys.argv[1], "tools", "stress_total.py")
    problems = []
    with tempfile.TemporaryDirectory() as directory:
        code, out = run(script, directory, [summary(1, 250, overflow=7, coverage=(100, 0)),
                                            summary(251, 250, overflow=5, coverage=(50, 0))])
        for expected in ("500 cases, seeds 1-500", "| overflow | 12 |", "| coverage | 150 | 0 |",
                         "- refused as they must be: 2", "| lighting | 0 | 0 | 12 | 0 |"):
            if expected not in out:
                problems.append(f"sum: {expected!r} missing from:\n{out}")
        if code != 0:
            problems.append(f"clean consecutive summaries: exit {code}")
        code, out = run(script, directory, [summary(1, 250), summary(252, 250)])
        if code != 1 or "seeds 251-251 are missing" not in out:
            problems.append(f"a gap: exit {code}\n{out}")
        code, out = run(script, directory, [summary(1, 250), summary(250, 250)])
        if code != 1 or "overlap (seeds 250-250)" not in out:
            problems.append(f"an overlap: exit {code}\n{out}")
        code, out = run(script, directory, [summary(1, 250, failed=1, nan=3)])
        if code != 1 or "failed: seed 1" not in out or "| nan | 3 |" not in out:
            problems.append(f"a failed case: exit {code}\n{out}")
    for problem in problems:
        print(problem)
    print(f"stress_total: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
