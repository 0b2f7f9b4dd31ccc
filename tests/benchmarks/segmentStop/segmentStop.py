"""segmentStop: what the statistical stop makes of the shipped segment table's runs.

  python3 segmentStop.py WORK RESULTS     (the fixed sweep of ./run in WORK/fixed)
  python3 segmentStop.py -replay CASE     (one run: the replayed stop, for checking)
  python3 segmentStop.py -warm WORK RESULTS   (the warm-started statistical sweep in WORK/warm)

A statistical stop changes nothing before it: the run that stops at step N is the
fixed run up to N. So each fixed run (900 steps, the means of the last 300: the
shipped table) also gives the statistical one: the rule of the template's
`statistics` (batchMeans, src/curtainModels/runTimeConditions/batchMeans) replayed
on the same 10-step samples of V_c/V_g and the drift gives the step N, the window
and its means; the CPU to N is curtainFoam's own ExecutionTime at N in the run's
log. The replay is this benchmark's copy of the rule; `-replay` on a run made with
-stop statistical shows it gives that run's step and window
(tests/benchmarks/segmentStop/README.md).

Per segment and curtain: each mean of the statistical window against the fixed
run's band (the smallest and largest sample of its window). Writes
RESULTS/segmentStop.csv, RESULTS/summary.csv, RESULTS/segmentStop.png."""
import csv
import io
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.realpath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "src", "python"))
from flightedDryer import files, foamDictionary, foamOutput  # noqa: E402

TEMPLATE = os.path.join(ROOT, "etc", "templates", "curtain", "drumSegment", "system", "controlDict")


def rule():
    """The statistics' settings of the template (batch, minBatches, tolerances, start)."""
    def v(cond, key, default=None):
        try:
            return float(foamDictionary.value(TEMPLATE, "functions/statistics/conditions/%s/%s" % (cond, key)))
        except foamDictionary.FoamDictionaryError:
            if default is None:
                raise
            return default
    return {c: {"batch": v(c, "batch"), "minBatches": int(v(c, "minBatches")), "tol": v(c, "tolerance"),
                "abs": v(c, "absTolerance", 0.0), "start": v(c, "startTime", -1e300)} for c in ("vc", "drift")}


def decide(times, values, t, r):
    """batchMeans at time t on the samples up to t: (satisfied, window start, kept, mean, se)."""
    nb = int(math.floor((t - r["start"] + 1e-9) / r["batch"]))
    frm = t - nb * r["batch"]
    if nb < 2:
        return False, frm, 0, float("nan"), float("nan")
    m = [0.0] * nb
    n = [0] * nb
    for tt, x in zip(times, values):
        if frm + 1e-9 < tt <= t + 1e-9 and tt > r["start"] + 1e-9:
            j = min(nb - 1, int(math.floor((tt - frm - 1e-9) / r["batch"])))
            m[j] += x
            n[j] += 1
    if min(n) == 0:
        return False, frm, 0, float("nan"), float("nan")
    m = [a / k for a, k in zip(m, n)]
    best, d = None, 0
    for dd in range(0, nb // 2 + 1):
        kept = m[dd:]
        mean = sum(kept) / len(kept)
        z = sum((x - mean) ** 2 for x in kept) / len(kept) ** 2
        if best is None or z < best:
            best, d = z, dd
    return m, frm, d, nb


def replay(case):
    """(stop step or None, window start, kept batches, {field: (mean, se)}) of the
    template's statistics replayed on a run's 10-step samples."""
    r = rule()
    g = foamOutput.fo_rows(case, "gasInCurtain")
    dr = foamOutput.fo_rows(case, "drift")
    series = {"vc": ([x["Time"] for x in g], [x["VcByVg"] for x in g]),
              "drift": ([x["Time"] for x in dr], [x["drift_bulk"] for x in dr])}
    for t in series["vc"][0]:
        if int(round(t)) % 10:
            continue
        out, ok = {}, True
        drops = []
        for c in ("vc", "drift"):
            res = decide(*series[c], t, r[c])
            if res[0] is False:
                ok = False
                break
            m, frm, d, nb = res
            drops.append((m, frm, d, nb))
        if not ok:
            continue
        # one window for all fields of a condition; each condition its own window
        for c, (m, frm, d, nb) in zip(("vc", "drift"), drops):
            kept = m[d:]
            mean = sum(kept) / len(kept)
            se = math.sqrt(sum((x - mean) ** 2 for x in kept) / (len(kept) * (len(kept) - 1))) \
                if len(kept) > 1 else float("inf")
            out[c] = (mean, se, frm + d * r[c]["batch"], len(kept))
            ok = ok and len(kept) >= r[c]["minBatches"] and se <= max(r[c]["tol"] * abs(mean), r[c]["abs"])
        if ok:
            start = max(out["vc"][2], out["drift"][2])
            return int(round(t)), start, min(out["vc"][3], out["drift"][3]), out
    return None, None, None, None


def cpu_at(run, step):
    """curtainFoam's ExecutionTime at a step (and its last), from the run's log."""
    at = last = None
    cur = None
    with open(os.path.join(run, "log.curtainFoam"), errors="replace") as f:
        for line in f:
            m = re.match(r"^Time = ([0-9.eE+-]+)$", line.strip())
            if m:
                cur = float(m.group(1))
                continue
            m = re.match(r"^ExecutionTime = ([0-9.eE+-]+) s", line)
            if m:
                last = float(m.group(1))
                if cur is not None and step is not None and abs(cur - step) < 1e-9:
                    at = last
    for v in (last,) + ((at,) if step is not None else ()):
        if v is None or not math.isfinite(v):
            raise SystemExit("segmentStop: %s/log.curtainFoam: no ExecutionTime at step %s" % (run, step))
    return at, last


def window_stats(case, name, key, start, end):
    rows = [r for r in foamOutput.fo_rows(case, name) if start < r["Time"] <= end]
    vals = [r[key] for r in rows]
    if not vals or not all(math.isfinite(v) for v in vals):
        raise SystemExit("segmentStop: %s %s: no finite samples in (%g, %g]" % (case, key, start, end))
    return sum(vals) / len(vals), min(vals), max(vals)


def main(work, out):
    base = os.path.join(work, "fixed")
    cases = sorted(d for d in os.listdir(base) if os.path.isfile(os.path.join(base, d, "curtains.csv")))
    if not cases:
        raise SystemExit("segmentStop: no finished segment in %s" % base)
    rows, summary = [], []
    for c in cases:
        run = os.path.join(base, c)
        case = os.path.join(run, "case")
        with open(os.path.join(run, "curtains.csv"), newline="") as f:
            fixed = {r["curtain"]: r for r in csv.DictReader(f)}
        last = max(int(d) for d in os.listdir(case) if d.isdigit())
        window = int(fixed["section"]["window_steps"])
        stop, start, kept, stats = replay(case)
        end = stop if stop is not None else last
        start = start if stop is not None else last - window
        cpu_stop, cpu_last = cpu_at(run, end)
        n0 = len(rows)
        for name in fixed:
            for q, fo, key in (("vc_over_vg", "gasInCurtain", "VcByVg" if name == "section" else "VcByVg_" + name),
                               ("drift_m", "drift", "drift_bulk" if name == "section" else "drift_" + name)):
                fm, lo, hi = window_stats(case, fo, key, last - window, last)
                sm, _, _ = window_stats(case, fo, key, start, end)
                rows.append([c, name, q, "%.6g" % fm, "%.6g" % lo, "%.6g" % hi, "%.6g" % sm,
                             "%.4g" % ((sm - fm) / (hi - lo) if hi > lo else 0.0),
                             "yes" if lo <= sm <= hi else "no"])
        mine = rows[n0:]
        summary.append([c, last, "%.1f" % cpu_last, end, "%.1f" % cpu_stop, int(end - start),
                        "yes" if stop is not None else "no", "%.3f" % (cpu_stop / cpu_last),
                        sum(1 for r in mine if r[-1] == "yes"), len(mine)])
    ft = sum(float(s[2]) for s in summary)
    stt = sum(float(s[4]) for s in summary)
    summary.append(["total", sum(s[1] for s in summary), "%.1f" % ft, sum(s[3] for s in summary), "%.1f" % stt,
                    "", sum(1 for s in summary if s[6] == "yes"), "%.3f" % (stt / ft),
                    sum(s[8] for s in summary), sum(s[9] for s in summary)])
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["case", "curtain", "quantity", "fixed_mean", "fixed_window_min", "fixed_window_max",
                "statistical_mean", "shift_over_band", "inside_band"])
    w.writerows(rows)
    files.atomic_write(os.path.join(out, "segmentStop.csv"), buf.getvalue())
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["case", "fixed_steps", "fixed_cpu_s", "statistical_steps", "statistical_cpu_s",
                "statistical_window_steps", "means_known", "cpu_ratio", "means_inside_band", "means"])
    w.writerows(summary)
    files.atomic_write(os.path.join(out, "summary.csv"), buf.getvalue())
    inside = sum(1 for r in rows if r[-1] == "yes")
    print(buf.getvalue())
    print("segmentStop: CPU %.0f s (fixed) against %.0f s (statistical), ratio %.3f; %d of %d means inside "
          "the fixed run's band" % (ft, stt, stt / ft, inside, len(rows)))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(1, 3, figsize=(16, 4.8))
    x = list(range(len(cases)))
    axs[0].bar([i - 0.2 for i in x], [float(s[2]) for s in summary[:-1]], 0.4, label="fixed: 900 steps")
    axs[0].bar([i + 0.2 for i in x], [float(s[4]) for s in summary[:-1]], 0.4, label="statistical stop")
    axs[0].set_xticks(x)
    axs[0].set_xticklabels(cases, rotation=30, fontsize=8)
    axs[0].set_ylabel("curtainFoam CPU [s]")
    axs[0].legend(fontsize=8)
    for ax, q, label in ((axs[1], "vc_over_vg", "V_c/V_g"), (axs[2], "drift_m", "drift [m]")):
        sel = [r for r in rows if r[1] == "section" and r[2] == q]
        for i, r in enumerate(sel):
            ax.plot([i, i], [float(r[4]), float(r[5])], color="0.6", lw=6, solid_capstyle="butt",
                    label="fixed: its window's band" if i == 0 else None)
            ax.plot(i, float(r[3]), "o", color="tab:blue", label="fixed: mean" if i == 0 else None)
            ax.plot(i, float(r[6]), "x", color="tab:red", ms=9, label="statistical: mean" if i == 0 else None)
        ax.set_xticks(range(len(sel)))
        ax.set_xticklabels([r[0] for r in sel], rotation=30, fontsize=8)
        ax.set_ylabel("section " + label)
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
    fig.suptitle("Invicta drum segments: the statistical stop against 900 fixed steps "
                 "(CPU ratio %.2f; %d of %d means inside the band)" % (stt / ft, inside, len(rows)))
    fig.tight_layout()
    files.save_figure(fig, os.path.join(out, "segmentStop.png"), 100)


def warm(work, out):
    """WORK/warm: the statistical sweep with warmStart (a repose angle's second segment
    from the first's fields): per segment its steps, curtainFoam's CPU and every mean
    against the fixed run's band (WORK/fixed); RESULTS/warmSegments.csv."""
    base, fixed_base = os.path.join(work, "warm"), os.path.join(work, "fixed")
    cases = sorted(d for d in os.listdir(base) if os.path.isfile(os.path.join(base, d, "curtains.csv")))
    if not cases:
        raise SystemExit("segmentStop: no finished segment in %s" % base)
    rows = []
    for c in cases:
        run, frun = os.path.join(base, c), os.path.join(fixed_base, c)
        with open(os.path.join(run, "curtains.csv"), newline="") as f:
            means = {r["curtain"]: r for r in csv.DictReader(f)}
        with open(os.path.join(frun, "curtains.csv"), newline="") as f:
            fixed = {r["curtain"]: r for r in csv.DictReader(f)}
        fcase = os.path.join(frun, "case")
        flast = max(int(d) for d in os.listdir(fcase) if d.isdigit())
        fwindow = int(fixed["section"]["window_steps"])
        steps = max(int(d) for d in os.listdir(os.path.join(run, "case")) if d.isdigit())
        _, cpu = cpu_at(run, None)
        _, fcpu = cpu_at(frun, None)
        inside = n = 0
        for name in fixed:
            for q, fo, key in (("vc_over_vg", "gasInCurtain", "VcByVg" if name == "section" else "VcByVg_" + name),
                               ("drift_m", "drift", "drift_bulk" if name == "section" else "drift_" + name)):
                _, lo, hi = window_stats(fcase, fo, key, flast - fwindow, flast)
                v = float(means[name][q])
                if not math.isfinite(v):
                    raise SystemExit("segmentStop: %s/curtains.csv: %s %s is not a number" % (run, name, q))
                inside += lo <= v <= hi
                n += 1
        with open(os.path.join(base, c + ".log"), errors="replace") as f:
            src = next((re.search(r"warm start from \S+/(\S+) ", l).group(1) for l in f if "warm start from" in l), "-")
        rows.append({"case": c, "from": src, "steps": steps, "fixed_steps": flast, "cpu_s": cpu, "fixed_cpu_s": fcpu,
                     "window_steps": int(means["section"]["window_steps"]), "means_inside_band": inside, "means": n})
    total = {"case": "total", "from": "", "steps": sum(r["steps"] for r in rows),
             "fixed_steps": sum(r["fixed_steps"] for r in rows), "cpu_s": sum(r["cpu_s"] for r in rows),
             "fixed_cpu_s": sum(r["fixed_cpu_s"] for r in rows), "window_steps": "",
             "means_inside_band": sum(r["means_inside_band"] for r in rows), "means": sum(r["means"] for r in rows)}
    # (the fixed runs' CPU was measured in another sweep, on a machine under another load:
    # the steps' ratio is the side-by-side measure)
    cols = ["case", "from", "steps", "fixed_steps", "steps_ratio", "cpu_s", "fixed_cpu_s", "cpu_ratio", "window_steps",
            "means_inside_band", "means"]
    text = "# regenerate: WARM=1 tests/benchmarks/segmentStop/run\n" + ",".join(cols) + "\n"
    for r in rows + [total]:
        r["cpu_ratio"] = "%.3f" % (r["cpu_s"] / r["fixed_cpu_s"])
        r["steps_ratio"] = "%.3f" % (r["steps"] / r["fixed_steps"])
        r["cpu_s"], r["fixed_cpu_s"] = "%.1f" % r["cpu_s"], "%.1f" % r["fixed_cpu_s"]
        text += ",".join(str(r[k]) for k in cols) + "\n"
    files.atomic_write(os.path.join(out, "warmSegments.csv"), text)
    print(text, end="")


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "-replay":
        stop, start, kept, stats = replay(sys.argv[2])
        print("stop %s, window from %s, %s batches, %s" % (stop, start, kept, stats))
    elif len(sys.argv) == 4 and sys.argv[1] == "-warm":
        warm(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 3:
        main(sys.argv[1], sys.argv[2])
    else:
        sys.exit(__doc__)
