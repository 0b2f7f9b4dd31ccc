"""results: what a finished run gives: the means over the steady window per fall
height (from the function objects' files), the result CSV and the landing CSV
(written as text here; folders writes them)."""

import csv
import io
import os
import re

from .. import foamOutput
from ..errors import RunError
from ..messages import g8 as fmt
from .settings import COLUMNS


def fo_rows(case, name):
    """A function object's rows by iteration (foamOutput.fo_rows)."""
    try:
        return foamOutput.fo_rows(case, name)
    except foamOutput.FoamOutputError as e:
        raise RunError(str(e))


def dat_header_value(case, name, key):
    base = os.path.join(case, "postProcessing", name)
    for t in sorted(os.listdir(base), key=float):
        for f in os.listdir(os.path.join(base, t)):
            with open(os.path.join(base, t, f)) as fh:
                for line in fh:
                    if not line.startswith("#"):
                        break
                    m = re.match(r"#\s*%s\s*:\s*(\S+)" % re.escape(key), line)
                    if m:
                        return m.group(1)
    return None


def _mean(values):
    return sum(values) / len(values)


def window_results(s, case, end):
    """Means over the steady window [end - window, end] per fall height."""
    results = []
    lo = end - s["window"]
    for i, h in enumerate(s["heights"]):
        dw = [r for r in fo_rows(case, "drift%d" % i) if lo - 1e-9 <= r["Time"] <= end + 1e-9]
        gw = [r for r in fo_rows(case, "gas%d" % i) if lo - 1e-9 <= r["Time"] <= end + 1e-9]
        if len(dw) < 3 or len(gw) < 3:
            raise RunError("fewer than 3 samples of the drift at fall height %g m in iterations "
                           "%d-%d" % (h, lo, end))
        mean = {k: _mean([r[k] for r in dw]) for k in dw[-1]}
        # no cell as dense as the curtain edge: V_c is undefined (nan), not 0
        vc = _mean([r["VcByVg"] for r in gw]) if all(r["solidsVolume"] > 0 for r in gw) \
            else float("nan")
        results.append((h, mean, vc))
    return results


def count_cells(case):
    with open(os.path.join(case, "log.blockMesh"), errors="replace") as f:
        for line in f:
            m = re.search(r"nCells:\s*(\d+)", line)
            if m:
                return int(m.group(1))
    raise RunError("no cell count in %s" % os.path.join(case, "log.blockMesh"))


def result_text(s, results, cells, iterations):
    out = io.StringIO()
    wr = csv.writer(out, lineterminator="\n")
    wr.writerow(COLUMNS)
    dmean = sum(w * d for w, d in zip(s["w"], s["d"]))
    for h, mean, vc in results:
        rows = [[n, fmt(d), fmt(w), fmt(h), fmt(mean["drift_" + n]),
                 fmt(mean["captured_" + n]), fmt(vc)] for n, d, w in zip(s["names"], s["d"], s["w"])]
        rows.append(["bulk", fmt(dmean), "1", fmt(h), fmt(mean["drift_bulk"]),
                     fmt(mean["captured_bulk"]), fmt(vc)])
        for r in rows:
            wr.writerow(r + [fmt(s["Vg"]), str(cells), str(iterations), "true"])
    return out.getvalue()


def landing_text(s, case, last):
    """The landing distributions of the final iteration (curtainDrift's landing.csv
    of every fall height) as one CSV with the fall height in front."""
    out = ["fall_height_m,class,x_low_m,x_high_m,mass_flow_kg_s,fraction_of_inflow,x_centre_m\n"]
    names = set(s["names"])
    for i, h in enumerate(s["heights"]):
        path = os.path.join(case, "postProcessing", "drift%d" % i, "%g" % last, "landing.csv")
        try:
            with open(path) as f:
                lines = f.read().splitlines()
        except OSError:
            raise RunError("no landing distribution at iteration %d: %s" % (last, path))
        if not lines or not lines[0].startswith("class,x_low_m"):
            raise RunError("%s: not a landing distribution" % path)
        for line in lines[1:]:
            if line.split(",")[0] not in names:
                raise RunError("%s: unknown class in '%s'" % (path, line))
            out.append("%s,%s\n" % (fmt(h), line))
    return "".join(out)
