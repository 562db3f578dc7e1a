#!/usr/bin/env python3
"""usvid from a notebook (docs/python.md): simulate a vessel, identify it with two usvid
methods, and compare them with an external method written in numpy.

Run with PYTHONPATH=build/python (the folder the default build puts the module in).
"""
import os
import sys

import usvid

here = os.path.dirname(os.path.abspath(__file__))

# 1. Simulate: a training record and a held-out one (another maneuver, another seed).
train = usvid.simulate(vessel="odin3dof", maneuver="random-steps", noise=0.005, seed=3,
                       duration=300)
test = usvid.simulate(vessel="odin3dof", maneuver="multisine", noise=0.005, seed=4, duration=180)
print(f"simulated {len(train['t'])} samples of {sorted(train)}")

# 2. Identify with two usvid methods, and score them on the held-out record.
for method in ("sindy", "fossen-ceres"):
    model = usvid.identify(train, method=method, vessel="odin3dof", threads=2)
    metrics = usvid.evaluate(model, test)
    fits = {s: round(metrics[s]["fit_percent"], 1) for s in ("u", "v", "r")}
    print(f"{method}: held-out fit {fits}")

# 3. Compare them with an external method (least_squares_method.py) in one suite.
results = usvid.compare({
    "name": "notebook",
    "vessels": ["odin3dof"],
    "train_maneuvers": ["random-steps"],
    "test_maneuvers": ["multisine"],
    "methods": ["sindy", "fossen-ceres",
                {"method": "external", "name": "least-squares",
                 "command": [sys.executable, os.path.join(here, "least_squares_method.py")]}],
    "noise": [0.005], "seeds": [1], "train_seconds": 300, "test_seconds": 180,
}, threads=2)
for row in results["rows"]:
    print(f"{row['method']:>14}: {row['status']}, mean fit "
          f"{row.get('mean_fit_percent', float('nan')):.1f} %")
assert all(row["status"] == "ok" for row in results["rows"])
