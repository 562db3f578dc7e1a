#!/usr/bin/env python3
"""An external identification method for `usvid compare` (docs/python.md): linear least squares
on a fixed library of Fossen-like terms, in numpy.

usvid calls it as
    python3 least_squares_method.py --data TRAIN.csv --states u,v,r --inputs tau_x,tau_y,tau_n \
        --out MODEL.json
and scores the model.json it writes like any other row.
"""
import argparse
import json
import sys

try:
    import numpy as np
except ImportError:  # an interpreter of its own (pyenv) beside Debian's python3-numpy
    sys.path.append("/usr/lib/python3/dist-packages")
    import numpy as np


def main():
    parser = argparse.ArgumentParser()
    for flag in ("--data", "--states", "--inputs", "--out"):
        parser.add_argument(flag, required=True)
    args = parser.parse_args()
    states, inputs = args.states.split(","), args.inputs.split(",")
    table = np.genfromtxt(args.data, delimiter=",", names=True)
    t = table["t"]
    x = {name: table[name] for name in states + inputs}
    # Library: each state, |state| state, the products of two states, and the inputs.
    terms = {s: x[s] for s in states}
    terms.update({f"abs({s})*{s}": np.abs(x[s]) * x[s] for s in states})
    terms.update({f"{a}*{b}": x[a] * x[b]
                  for i, a in enumerate(states) for b in states[i + 1:]})
    terms.update({i: x[i] for i in inputs})
    names = list(terms)
    library = np.column_stack([terms[n] for n in names])
    equations = {}
    for s in states:
        derivative = np.gradient(x[s], t)  # central differences
        keep = np.isfinite(derivative) & np.all(np.isfinite(library), axis=1)
        coefficients, *_ = np.linalg.lstsq(library[keep], derivative[keep], rcond=None)
        equations[s] = " + ".join(f"({c:.10g})*{n}" for c, n in zip(coefficients, names))
    with open(args.out, "w") as f:
        json.dump({"method": "least-squares", "states": states, "inputs": inputs,
                   "equations": equations}, f)


if __name__ == "__main__":
    main()
