"""foamOutput: the one reader of what OpenFOAM's function objects write.

- read_dat: a function object's .dat file (columns named by the last '#'
  line), rows as dicts of floats; a line still being written is skipped;
- fo_rows: a function object's rows by iteration over its time folders (a
  resumed run writes a new folder; for an iteration in two folders the
  later start wins);
- read_raw: a 'raw' surface sample (surfaces function object): '#' header,
  then x y z and the value(s) per face, as a numpy array.
"""

import os


class FoamOutputError(Exception):
    """A function object's output that is missing or empty."""


def read_dat(path):
    """Rows of a function-object .dat file as dicts (header from the last # line)."""
    header = None
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                header = line[1:].split()
                continue
            vals = line.split()
            if header and len(vals) == len(header) and line.endswith("\n"):
                try:
                    rows.append({k: float(v) for k, v in zip(header, vals)})
                except ValueError:
                    pass   # a line being written
    return rows


def fo_rows(case, name):
    """A function object's rows by iteration. A resumed run writes a new time
    folder; where two folders hold the same iteration the later start wins."""
    base = os.path.join(case, "postProcessing", name)
    if not os.path.isdir(base):
        raise FoamOutputError("no output of function object %s in %s" % (name, base))
    by_time = {}
    for t in sorted(os.listdir(base), key=float):
        for f in sorted(os.listdir(os.path.join(base, t))):
            if f.endswith(".dat"):
                for r in read_dat(os.path.join(base, t, f)):
                    by_time[r["Time"]] = r
    return [by_time[t] for t in sorted(by_time)]


def read_raw(path):
    """OpenFOAM raw surface file: '#' header, then x y z value(s)"""
    import numpy as np
    data = np.loadtxt(path, comments="#", ndmin=2)
    if data.size == 0:
        raise FoamOutputError("empty sample %s" % path)
    return data
