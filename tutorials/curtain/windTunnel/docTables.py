"""docTables: the mesh study's tables of this tutorial's README, written from
results/meshStudy.csv and results/meshStudyGCI.txt (docs/figures -update calls them)."""

import os
import re

from flightedDryer import docFigures as df

STUDY = "tutorials/curtain/windTunnel/results/meshStudy.csv"
GCI = "tutorials/curtain/windTunnel/results/meshStudyGCI.txt"


def mesh(results):
    """Per level: cells, cells across the half sheet, drift, V_c/V_g, iterations and CPU to 1 %."""
    rows = results.rows(STUDY)
    if not rows:
        raise df.FigureError("%s: no rows" % STUDY)
    out = ["| level | cells | cells across the half sheet | drift at floor [m] | V_c/V_g | iterations to 1 % | CPU to 1 % [s] |",
           "|---|---|---|---|---|---|---|"]
    for r in rows:
        v = lambda c: df.finite(r[c], STUDY)
        out.append("| %s | %s | %s | %s | %s | %s | %s |" % (
            r["level"], df.fmt(v("cells"), "%.0f"), df.fmt(v("nzSheet"), "%.0f"), df.fmt(v("drift_m"), "%.4f"),
            df.fmt(v("VcByVg"), "%.4f"), df.fmt(v("steady_iterations"), "%.0f"), df.fmt(v("steady_cpu_s"), "%.1f")))
    return "\n".join(out)


def gci(results):
    """Richardson extrapolation and the fine-level GCI, with each refinement ratio."""
    try:
        with open(os.path.join(results.root, GCI)) as f:
            text = f.read()
    except OSError as e:
        raise df.FigureError("cannot read %s: %s" % (GCI, e.strerror or e))
    out = ["| refinement ratio | apparent order | extrapolated drift [m] | fine-level GCI |", "|---|---|---|---|"]
    pattern = re.compile(r"^r = (.+?): .*apparent order (\S+), extrapolated drift (\S+) m, "
                         r"fine-level GCI (\S+) %", re.M)
    found = pattern.findall(text)
    if not found:
        raise df.FigureError("%s: no Richardson lines" % GCI)
    for ratio, order, drift, g in found:
        out.append("| %s | %s | %s | %s %% |" % (ratio, df.fmt(df.finite(order, GCI), "%.2f"),
                                                 df.fmt(df.finite(drift, GCI), "%.3f"),
                                                 df.fmt(df.finite(g, GCI), "%.1f")))
    return "\n".join(out)
