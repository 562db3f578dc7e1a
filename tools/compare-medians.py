#!/usr/bin/env python3
"""Medians of a `usvid compare` run, per vessel and method: the median held-out fit (mean over
the identified states) over every row, the share of free runs that diverged, the median per
test maneuver and per speed regime, and the inputs the rows used. The summary's tables show
means of clamped values; these are the robust numbers docs/compare.md quotes.

Usage: tools/compare-medians.py DIR/results.json
"""
import json
import statistics
import sys
from collections import defaultdict


def median(values):
    return f"{statistics.median(values):.1f}" if values else "-"


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    rows = json.load(open(sys.argv[1]))["rows"]
    groups = defaultdict(list)
    for row in rows:
        groups[(row["vessel"], row["method"])].append(row)
    tests = sorted({r["test_maneuver"] for r in rows})
    regimes = ["displacement", "semi-displacement", "planing"]
    print("| vessel | method | inputs | rows | median fit % | diverged | "
          + " | ".join(tests) + " | " + " | ".join(regimes) + " |")
    print("| --- " * (6 + len(tests) + len(regimes)) + "|")
    for (vessel, method), group in sorted(groups.items()):
        ok = [r for r in group if r["status"] == "ok"]
        inputs = sorted({r.get("inputs", "") for r in ok}) or ["-"]
        fits = [r["mean_fit_percent"] for r in ok]
        diverged = sum(r["diverged"] for r in ok)
        per_test = [median([r["mean_fit_percent"] for r in ok if r["test_maneuver"] == t])
                    for t in tests]
        per_regime = [median([r["regime_fit_percent"][g] for r in ok
                              if g in r.get("regime_fit_percent", {})]) for g in regimes]
        failed = len(group) - len(ok)
        print(f"| {vessel} | {method} | {'; '.join(inputs)} | {len(ok)}"
              f"{f' ({failed} failed)' if failed else ''} | {median(fits)} | "
              f"{diverged} ({100 * diverged / max(1, len(ok)):.0f} %) | "
              + " | ".join(per_test) + " | " + " | ".join(per_regime) + " |")


if __name__ == "__main__":
    main()
