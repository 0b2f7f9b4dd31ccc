"""profile: where curtainFoam's CPU goes, from OpenFOAM's profiling of a run
(curtainPeer PROFILE=1): the latest time's uniform/profiling read, one row per
timed section (the solver's own: solids fractions, momentum predictor, pressure,
solids momentum, turbulence, local time step, field checks; and inside them
every fvMatrix::solve and function object), with its calls, total and own
(self) time and shares of the run, and the iterations the run made.

  python3 profile.py CASE OUT.csv"""
import csv
import io
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "..", "src", "python"))
from flightedDryer import files  # noqa: E402


def triggers(text):
    """{id: {description, parentId, calls, totalTime, childTime}} of a profiling file."""
    out = {}
    for m in re.finditer(r"trigger\d+\s*\{([^{}]*)\}", text):
        body = m.group(1)
        e = dict(re.findall(r"(\w+)\s+([^;]+);", body))
        out[int(e["id"])] = {"description": e["description"].strip().strip('"'),
                             "parent": int(e["parentId"]) if "parentId" in e else None,
                             "calls": int(e["calls"]), "total": float(e["totalTime"]),
                             "child": float(e.get("childTime", 0))}
    return out


def main(case, out):
    times = [d for d in os.listdir(case) if re.fullmatch(r"[0-9]+(\.[0-9]+)?", d) and
             os.path.isfile(os.path.join(case, d, "uniform", "profiling"))]
    if not times:
        sys.exit("profile: no <time>/uniform/profiling in %s (run with PROFILE=1)" % case)
    last = max(times, key=float)
    t = triggers(open(os.path.join(case, last, "uniform", "profiling")).read())
    main_id = next(i for i, e in t.items() if e["description"] == "application::main")
    run = t[main_id]["total"]
    if not (run > 0 and math.isfinite(run)):
        sys.exit("profile: the run's total time is %s" % run)
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["section", "parent", "calls", "total_s", "self_s", "share_total", "share_self", "iterations"])
    for i in sorted(t, key=lambda k: -t[k]["total"]):
        e = t[i]
        parent = t[e["parent"]]["description"] if e["parent"] is not None and e["parent"] in t else ""
        self_s = e["total"] - e["child"]
        w.writerow([e["description"], parent, e["calls"], "%.4g" % e["total"], "%.4g" % self_s,
                    "%.4f" % (e["total"] / run), "%.4f" % (self_s / run), last])
    files.atomic_write(out, buf.getvalue())
    print(buf.getvalue())


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
