"""report: the study's HTML page (open standards, no server: the PNGs beside it)
from its results: the routes, the error band, the RTD of every route on linear and
log axes with the tracer, the holdup along the drum, the drift table and one of its
curtains, and every assumption the description left to defaults."""

import csv
import datetime
import math
import os
import shutil

from .. import PROJECT, files

TEMPLATE = os.path.join(PROJECT, "etc", "templates", "study")
LABELS = {"table": "CFD drift table", "sherritt": "Eq 142 (Sherritt)", "isolated": "lone particles",
          "tableLow": "CFD table, low end of the band", "tableHigh": "CFD table, high end of the band",
          "isolatedLow": "lone particles, low end of the band",
          "isolatedHigh": "lone particles, high end of the band", "segment": "CFD drum segments",
          "segmentLow": "CFD drum segments, low end of the band",
          "segmentHigh": "CFD drum segments, high end of the band"}


def _primary(names):
    """The study's own route (the first) and its band's routes."""
    return names[0], names[0] + "Low", names[0] + "High"


def _rtd(results):
    t, E = [], []
    with open(os.path.join(results, "rtd.csv"), newline="") as f:
        for r in csv.DictReader(f):
            t.append(float(r["time_s"]) / 60.0)
            E.append(float(r["E_per_s"]) * 60.0)
    return t, E


def _tracer(desc):
    """(t min, E 1/min) of the description's tracer, or None."""
    tr = desc.sections["rtd"].get("tracer") if isinstance(desc.sections["rtd"], dict) else None
    if not isinstance(tr, dict):
        return None
    path = os.path.expandvars(tr["file"])
    t_scale = {"s": 1 / 60.0, "min": 1.0, "h": 60.0}.get(tr.get("timeUnit", "s"), 1 / 60.0)
    e_scale = {"per_s": 60.0, "per_min": 1.0, "per_h": 1 / 60.0}.get(tr.get("EUnit", "per_s"), 60.0)
    t, E = [], []
    with open(path, newline="") as f:
        for r in csv.DictReader(l for l in f if not l.startswith("#")):
            t.append(float(r[tr["timeColumn"]]) * t_scale)
            E.append(float(r[tr["EColumn"]]) * e_scale)
    return t, E


def rtd_figure(work, desc, out, names):
    """rtdRoutes.png: E(t) of every route (names, the study's own first), linear and
    log, the band shaded."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(1, 2, figsize=(13, 4.8))
    own, low, high = _primary(names)
    curves = {r: _rtd(os.path.join(work, r, "results")) for r in names}
    tracer = _tracer(desc)
    if tracer:   # samples before the pulse (background) are not drawn
        tracer = ([t for t in tracer[0] if t >= 0], [e for t, e in zip(*tracer) if t >= 0])
    # to where every curve is down to 1e-4 of its peak, or the tracer's last sample
    ends = [max(t for t, e in zip(*c) if e >= 1e-4 * max(c[1])) for c in curves.values()]
    right = 1.05 * max(ends + ([max(tracer[0])] if tracer else []))
    for ax, log in zip(axs, (False, True)):
        lo, hi = curves[low], curves[high]
        n = min(len(lo[0]), len(hi[0]))
        ax.fill_between(lo[0][:n], [min(a, b) for a, b in zip(lo[1][:n], hi[1][:n])],
                        [max(a, b) for a, b in zip(lo[1][:n], hi[1][:n])], color="tab:blue", alpha=0.2,
                        label="%s, error band" % LABELS[own])
        for name, style in (("table", "-"), ("segment", "-"), ("sherritt", "--"), ("isolated", ":")):
            if name in curves:
                ax.plot(curves[name][0], curves[name][1], style, label=LABELS[name])
        if tracer:
            ax.plot(tracer[0], tracer[1], "k.", ms=3, label="measured tracer")
        ax.set_xlim(0, right)
        ax.set_xlabel("time [min]")
        ax.set_ylabel("E(t) [1/min]")
        if log:
            ax.set_yscale("log")
            ax.set_ylim(1e-5, None)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Residence time distribution: %s" % os.path.basename(desc.path))
    fig.tight_layout()
    files.save_figure(fig, out, 100)


def unloading_figure(results, out):
    """unloading.png: the flights' unloading (drumSolver's unloading.csv, Lee 2008 Ch. 4)
    at the feed end, mid-drum and the discharge end: the holdup a flight carries and the
    spill rate it releases against its root angle. False where the model writes none
    (the two-phase model's flights are Sherritt's)."""
    path = os.path.join(results, "unloading.csv")
    if not os.path.isfile(path):
        return False
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    slices = sorted({int(float(r["slice"])) for r in rows})
    if not slices:
        return False
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(1, 2, figsize=(13, 4.5))
    for i, label in ((slices[0], "feed end"), (slices[len(slices) // 2], "mid-drum"), (slices[-1], "discharge end")):
        rs = [r for r in rows if int(float(r["slice"])) == i]
        a = [float(r["root_angle_deg"]) for r in rs]
        name = "slice %d, %s (repose %.1f deg)" % (i, label, float(rs[0]["phi_deg"]))
        axs[0].plot(a, [float(r["flight_holdup_kg"]) for r in rs], label=name)
        axs[1].plot(a, [float(r["spill_rate_kg_m_s"]) for r in rs], label=name)
    for ax, ylabel in zip(axs, ("flight holdup [kg per flight and slice]", "spill rate [kg/(m s)]")):
        ax.set_xlabel("flight root angle from the drum bottom [deg]")
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Flight unloading (Lee 2008 Ch. 4), as the drum model releases the curtains")
    fig.tight_layout()
    files.save_figure(fig, out, 100)
    return True


def curve_figure(rows, entry, out):
    """curve.png: holdup, mean residence time (with the error band) and the RTD's
    quantiles of every route against the curve's input."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(1, 3, figsize=(15, 4.5))
    values = sorted({r["value"] for r in rows})
    names = list(dict.fromkeys(r["route"] for r in rows))
    own, low, high = _primary(names)
    pick = lambda route, col: [next(r[col] for r in rows if r["route"] == route and r["value"] == v) for v in values]
    axs[1].fill_between(values, pick(low, "mean_residence_time_min"), pick(high, "mean_residence_time_min"),
                        color="tab:blue", alpha=0.2, label="%s, error band" % LABELS[own])
    for name, style in (("table", "-o"), ("segment", "-o"), ("sherritt", "--s"), ("isolated", ":^")):
        if name in names:
            axs[0].plot(values, pick(name, "holdup_kg"), style, label=LABELS[name])
            axs[1].plot(values, pick(name, "mean_residence_time_min"), style, label=LABELS[name])
    for col, style in (("t10_min", "-v"), ("t50_min", "-o"), ("t90_min", "-^")):
        axs[2].plot(values, pick(own, col), style, label="%s, %s" % (LABELS[own], col.split("_")[0]))
    for ax, ylabel in zip(axs, ("holdup [kg]", "mean residence time [min]", "RTD quantiles [min]")):
        ax.set_xlabel(entry)
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Operating curve: %s" % entry)
    fig.tight_layout()
    files.save_figure(fig, out, 100)


def write(desc, study_dir, rows, error, error_source, plan, curtain_note, curve=None):
    """report.html (and rtdRoutes.png, profile.png beside it), written whole."""
    import jinja2
    work = os.path.join(study_dir, "routes")
    names = [r["route"] for r in rows]
    own, low, high = _primary(names)
    rtd_figure(work, desc, os.path.join(study_dir, "rtdRoutes.png"), names)
    shutil.copyfile(os.path.join(work, own, "results", "profile.png"), os.path.join(study_dir, ".profile.png"))
    os.replace(os.path.join(study_dir, ".profile.png"), os.path.join(study_dir, "profile.png"))
    unloading = unloading_figure(os.path.join(work, own, "results"), os.path.join(study_dir, "unloading.png"))
    by = {r["route"]: r for r in rows}
    band = [by[low]["mean_residence_time_min"], by[high]["mean_residence_time_min"]]
    tracer = None
    tc = os.path.join(work, own, "results", "tracerComparison.csv")
    summ = os.path.join(work, own, "results", "summary.csv")
    if desc.tracer() and os.path.isfile(tc):
        with open(tc, newline="") as f:
            m = {r["quantity"]: float(r["measured"]) for r in csv.DictReader(f)}
        with open(summ, newline="") as f:
            s = list(csv.DictReader(f))[0]
        tracer = {"mean_min": float(s["measured_mean_s"]) / 60, "sd_min": float(s["measured_std_s"]) / 60,
                  "t10_min": m["t10_s"] / 60, "t50_min": m["t50_s"] / 60, "t90_min": m["t90_s"] / 60}
    env = jinja2.Environment(loader=jinja2.FileSystemLoader(TEMPLATE), autoescape=True,
                             undefined=jinja2.StrictUndefined)
    html = env.get_template("report.html").render(
        name=os.path.splitext(os.path.basename(desc.path))[0], description=desc.path,
        written=datetime.date.today().isoformat(), routes=rows, labels=LABELS, own=own, table=by[own],
        low=by[low], high=by[high], band_lo=min(band), band_hi=max(band), tracer=tracer,
        error=error, error_source=error_source, plan=plan, curtain=curtain_note, defaults=desc.defaults,
        curve=curve, unloading=unloading)
    for r in rows:
        for k, v in r.items():
            if isinstance(v, float) and not math.isfinite(v):
                raise ValueError("route %s: %s is not a finite number" % (r["route"], k))
    files.atomic_write(os.path.join(study_dir, "report.html"), html)
