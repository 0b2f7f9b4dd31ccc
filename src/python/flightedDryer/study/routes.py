"""routes: the drum model on the description, once per drift route: the CFD table,
Sherritt's Eq 142 and lone particles side by side (how much the drift model moves
the answer), and the table's drift scaled by exp(-e) and exp(+e), e the RMS ln of
the cross-validated CFD route on the wind tunnel (its measured out-of-sample
error): the error band of holdup, residence time and the RTD's quantiles."""

import csv
import math
import os
import subprocess

from .. import PROJECT
from ..errors import RunError
from ..files import atomic_write
from ..processes import run_tied

SCORES = os.path.join(PROJECT, "validation", "windTunnelDrift", "results", "scoresBreakdown.csv")
COLUMNS = ["route", "drift", "drift_scale", "holdup_kg", "airborne_fraction", "mean_residence_time_min",
           "rtd_std_min", "t10_min", "t50_min", "t90_min"]


def error_band():
    """(e, its source): the larger out-of-sample RMS ln of the cross-validated
    per-row CFD (leave one fall height out, leave one material out)."""
    with open(SCORES, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["model"] in ("cv_height", "cv_material")
                and r["group"] == "all"]
    if len(rows) != 2:
        raise RunError("%s: no cross-validated scores (cv_height, cv_material)" % SCORES)
    e = max(float(r["rms_ln"]) for r in rows)
    if not (math.isfinite(e) and 0 < e < 2):
        raise RunError("%s: cross-validated RMS ln %s is not a usable error" % (SCORES, e))
    return e, "%s (cv_height, cv_material: the larger)" % os.path.relpath(SCORES, PROJECT)


def route_settings(table, e, kind="table"):
    """(name, model.drift, drift section) of every route, the study's own route first
    and its band last: the CFD table's (kind table), the drum segments' (kind
    segment: V_c/V_g per release angle, the release angles beyond the runs' flights
    at their nearest), or without a table (a scene that needs no curtain run) the
    lone particles'."""
    lo, hi = float("%.6g" % math.exp(-e)), float("%.6g" % math.exp(e))
    if table is None:
        return [("isolated", "isolated", {}), ("sherritt", "sherritt", {}),
                ("isolatedLow", "isolated", {"scale": lo}), ("isolatedHigh", "isolated", {"scale": hi})]
    if kind == "segment":
        t = {"segmentTable": table, "outside": "clamp"}
        return [("segment", "segmentVc", dict(t)), ("sherritt", "sherritt", {}), ("isolated", "isolated", {}),
                ("segmentLow", "segmentVc", dict(t, scale=lo)), ("segmentHigh", "segmentVc", dict(t, scale=hi))]
    t = {"table": table}
    return [("table", "table", dict(t)), ("sherritt", "sherritt", {}), ("isolated", "isolated", {}),
            ("tableLow", "table", dict(t, scale=lo)), ("tableHigh", "table", dict(t, scale=hi))]


def _row(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if len(rows) != 1:
        raise RunError("%s: not one row" % path)
    return rows[0]


def quantiles(results):
    """t10, t50, t90 in minutes from the RTD (F_cumulative of rtd.csv)."""
    t, F = [], []
    with open(os.path.join(results, "rtd.csv"), newline="") as f:
        for r in csv.DictReader(f):
            t.append(float(r["time_s"]))
            F.append(float(r["F_cumulative"]))
    total = F[-1] if F and F[-1] > 0 else float("nan")
    out = []
    for p in (0.1, 0.5, 0.9):
        target = p * total
        k = next((i for i, v in enumerate(F) if v >= target), None)
        if k is None or k == 0:
            out.append(float("nan"))
            continue
        a = (target - F[k - 1]) / (F[k] - F[k - 1]) if F[k] > F[k - 1] else 0.0
        out.append((t[k - 1] + a * (t[k] - t[k - 1])) / 60.0)
    return out


def run_routes(desc, table, e, work, say, override=None, kind="table"):
    """Every route's drumSolver run in work/<route>, the band's routes at exp(+-e)
    (on an operating curve, with override = (SECTION.KEY, value)); the rows of
    routes.csv."""
    rows = []
    for name, drift, section in route_settings(table, e, kind):
        case = os.path.join(work, name)
        os.makedirs(case, exist_ok=True)
        atomic_write(os.path.join(case, "drumDict"), desc.drum_dict(drift, section, override))
        with open(os.path.join(case, "log.drumSolver"), "w") as log:
            rc = run_tied(["drumSolver", "-case", case], stdout=log, stderr=subprocess.STDOUT).returncode
        if rc != 0:
            raise RunError("drumSolver on route %s failed (log: %s)" % (name, os.path.join(case, "log.drumSolver")))
        s = _row(os.path.join(case, "results", "summary.csv"))
        q = quantiles(os.path.join(case, "results"))
        row = {"route": name, "drift": drift, "drift_scale": section.get("scale", 1.0),
               "holdup_kg": float(s["holdup_kg"]), "airborne_fraction": float(s["airborne_fraction"]),
               "mean_residence_time_min": float(s["exact_mean_s"]) / 60.0,
               "rtd_std_min": float(s["exact_std_s"]) / 60.0, "t10_min": q[0], "t50_min": q[1], "t90_min": q[2]}
        rows.append(row)
        say("%sroute %-9s holdup %.0f kg, mean residence time %.2f min, SD %.2f min"
            % ("%s %g: " % override if override else "", name, row["holdup_kg"], row["mean_residence_time_min"],
               row["rtd_std_min"]))
    return rows


def write_routes(rows, path, first=()):
    """routes.csv (or curve.csv: the curve's value first), written whole."""
    cols = list(first) + COLUMNS
    lines = [",".join(cols)]
    for r in rows:
        lines.append(",".join(r[c] if isinstance(r[c], str) else "%.6g" % r[c] for c in cols))
    atomic_write(path, "\n".join(lines) + "\n")
