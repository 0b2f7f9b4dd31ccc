"""compare: two drift tables of the same grid, value by value, against the steady
criterion a curtain run stops on (curtainCase's tolerances: drift steady to 1 %
or 1 mm, V_c/V_g to 5 % or 0.002): how far a warm-started table lies from the
cold one, the largest difference per column, and how many values lie outside."""

import csv
import math

from ..curtain.settings import DRIFT_ABS_TOL, REL_TOL, VC_ABS_TOL, VC_REL_TOL
from ..errors import InputError

KEY = ("case", "gas_velocity_m_s", "spill_rate_kg_m_s", "fall_height_m", "flight_length_m",
       "particle_density_kg_m3", "particle_diameter_m")
# column: (relative tolerance, absolute tolerance) of the steady criterion
TOLERANCES = {"drift_m": (REL_TOL, DRIFT_ABS_TOL), "vc_over_vg": (VC_REL_TOL, VC_ABS_TOL)}


def read_rows(path):
    """{key: row} of a drift table (its '#' lines skipped); every value finite."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    if not rows:
        raise InputError("%s: no rows" % path)
    out = {}
    for r in rows:
        for col in TOLERANCES:
            v = float(r[col])
            if not math.isfinite(v):
                raise InputError("%s: %s = %s in case %s is not a finite number" % (path, col, r[col], r["case"]))
        out[tuple(r[k] for k in KEY)] = r
    return out


def compare(reference, other):
    """Per column: the largest difference (absolute and relative to the reference),
    the row where it is, and the count of rows outside the steady criterion
    (|a - b| > max(rel |a|, abs)). The two tables must hold the same rows."""
    a, b = read_rows(reference), read_rows(other)
    if set(a) != set(b):
        missing = sorted(set(a) ^ set(b))[:3]
        raise InputError("%s and %s hold other rows (e.g. %s)" % (reference, other, missing))
    out = {}
    for col, (rel, absolute) in TOLERANCES.items():
        worst = {"column": col, "max_abs_diff": 0.0, "max_rel_diff": 0.0, "worst_row": "", "outside": 0,
                 "rows": len(a), "rel_tolerance": rel, "abs_tolerance": absolute}
        for k in sorted(a):
            x, y = float(a[k][col]), float(b[k][col])
            d = abs(y - x)
            r = d / abs(x) if x != 0 else (0.0 if d == 0 else math.inf)
            if d > max(rel * abs(x), absolute):
                worst["outside"] += 1
            if r > worst["max_rel_diff"] or (r == worst["max_rel_diff"] and d > worst["max_abs_diff"]):
                worst.update(max_rel_diff=r, worst_row="%s d=%s y=%s" % (k[0], k[6], k[3]))
            worst["max_abs_diff"] = max(worst["max_abs_diff"], d)
        out[col] = worst
    return out
