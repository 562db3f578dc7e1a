#!/usr/bin/env python3
"""Pins a compare run as a baseline that a test holds later runs against.

usage: tools/pin-baseline.py RESULTS.json BASELINE.json

Keeps the run's rows (what `usvid compare --baseline` and the real-data tests read) and the
baseline's "about" line, and drops the suite echo, whose data paths are this machine's."""
import json
import os
import sys


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__.strip().splitlines()[2])
    results, baseline = sys.argv[1], sys.argv[2]
    with open(results) as f:
        rows = json.load(f)["rows"]
    about = ""
    if os.path.exists(baseline):
        with open(baseline) as f:
            about = json.load(f).get("about", "")
    with open(baseline + ".tmp", "w") as f:
        json.dump({"about": about, "rows": rows}, f, indent=1, sort_keys=True)
        f.write("\n")
    os.replace(baseline + ".tmp", baseline)
    print(f"pinned {len(rows)} rows of {results} in {baseline}")


if __name__ == "__main__":
    main()
