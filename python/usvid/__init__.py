"""usvid from Python: simulate, identify, evaluate, diagnose and compare (docs/python.md).

Data are dicts of channel name to 1-D numpy array, with the time "t" [s]; NaN marks a sample a
channel did not take. Models, metrics, diagnoses and results are dicts shaped as model.json,
metrics.json, diagnosis.json and results.json (docs/data.md). Bad arguments raise ValueError
with the command line's one-line message.
"""
try:
    import numpy  # noqa: F401
except ImportError:  # an interpreter of its own (pyenv) beside Debian's python3-numpy
    import sys

    sys.path.append("/usr/lib/python3/dist-packages")
    import numpy  # noqa: F401

from ._usvid import compare, diagnose, evaluate, identify, simulate, vessels  # noqa: F401

__all__ = ["simulate", "identify", "evaluate", "diagnose", "compare", "vessels"]
