"""segmentStop: the two sweeps of tests/benchmarks/segmentStop/run compared, per
segment (CPU, steps, whether the statistics knew their means) and per curtain
(each mean of the statistical stop against the fixed run's band: the smallest and
largest sample of its averaging window).

  python3 segmentStop.py WORK RESULTS

Writes RESULTS/segmentStop.csv (per curtain and quantity), RESULTS/summary.csv
(per segment and the totals) and RESULTS/segmentStop.png."""
import csv
import io
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.realpath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "src", "python"))
from flightedDryer import files, foamOutput  # noqa: E402

QUANTITIES = (("vc_over_vg", "gasInCurtain", "VcByVg"), ("drift_m", "drift", "drift"))


def cpu_and_steps(run):
    """curtainFoam's CPU time (its last ExecutionTime) and its last step."""
    cpu = None
    with open(os.path.join(run, "log.curtainFoam"), errors="replace") as f:
        for line in f:
            m = re.match(r"^ExecutionTime = ([0-9.eE+-]+) s", line)
            if m:
                cpu = float(m.group(1))
    steps = max(int(d) for d in os.listdir(os.path.join(run, "case")) if d.isdigit())
    if cpu is None or not math.isfinite(cpu):
        raise SystemExit("segmentStop: %s/log.curtainFoam: no ExecutionTime" % run)
    return cpu, steps


def curtains(run):
    with open(os.path.join(run, "curtains.csv"), newline="") as f:
        return {r["curtain"]: r for r in csv.DictReader(f)}


def window_extent(run, name, key, window):
    """(least, largest) sample of a function object's result over the window."""
    rows = foamOutput.fo_rows(os.path.join(run, "case"), name)
    last = rows[-1]["Time"]
    vals = [r[key] for r in rows if r["Time"] > last - window]
    return min(vals), max(vals)


def number(text, what):
    v = float(text)
    if not math.isfinite(v):
        raise SystemExit("segmentStop: %s is %s" % (what, text))
    return v


def main(work, out):
    cases = sorted(d for d in os.listdir(os.path.join(work, "fixed"))
                   if os.path.isfile(os.path.join(work, "fixed", d, "curtains.csv")))
    if not cases:
        raise SystemExit("segmentStop: no finished segment in %s/fixed" % work)
    rows, summary = [], []
    for c in cases:
        fx, st = os.path.join(work, "fixed", c), os.path.join(work, "statistical", c)
        fcpu, fsteps = cpu_and_steps(fx)
        scpu, ssteps = cpu_and_steps(st)
        with open(os.path.join(st, "log.curtainFoam"), errors="replace") as f:
            log = f.read()
        fc, sc = curtains(fx), curtains(st)
        window = int(fc["section"]["window_steps"])
        summary.append([c, fsteps, "%.1f" % fcpu, ssteps, "%.1f" % scpu, sc["section"]["window_steps"],
                        "%.3f" % (scpu / fcpu)])
        for name in fc:
            for q, fo, prefix in QUANTITIES:
                key = ("%s_%s" % (prefix, name)) if name != "section" else ("VcByVg" if q == "vc_over_vg"
                                                                             else "drift_bulk")
                lo, hi = window_extent(fx, fo, key, window)
                fm = number(fc[name][q], "%s %s %s fixed" % (c, name, q))
                sm = number(sc[name][q], "%s %s %s statistical" % (c, name, q))
                rows.append([c, name, q, "%.6g" % fm, "%.6g" % lo, "%.6g" % hi, "%.6g" % sm,
                             "%.4g" % ((sm - fm) / (hi - lo) if hi > lo else 0.0),
                             "yes" if lo <= sm <= hi else "no"])
        if "mean known" not in log and "Conditions met" not in log:
            print("segmentStop: %s: the statistics did not know their means before the cap" % c)
    ft = sum(float(s[2]) for s in summary)
    stt = sum(float(s[4]) for s in summary)
    summary.append(["total", sum(s[1] for s in summary), "%.1f" % ft, sum(s[3] for s in summary), "%.1f" % stt,
                    "", "%.3f" % (stt / ft)])
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["case", "curtain", "quantity", "fixed_mean", "fixed_window_min", "fixed_window_max",
                "statistical_mean", "shift_over_band", "inside_band"])
    w.writerows(rows)
    files.atomic_write(os.path.join(out, "segmentStop.csv"), buf.getvalue())
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["case", "fixed_steps", "fixed_cpu_s", "statistical_steps", "statistical_cpu_s",
                "statistical_window_steps", "cpu_ratio"])
    w.writerows(summary)
    files.atomic_write(os.path.join(out, "summary.csv"), buf.getvalue())
    inside = sum(1 for r in rows if r[-1] == "yes")
    print("segmentStop: CPU %.0f s (fixed) against %.0f s (statistical), ratio %.3f; %d of %d means inside "
          "the fixed run's band" % (ft, stt, stt / ft, inside, len(rows)))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(1, 3, figsize=(16, 4.8))
    x = range(len(cases))
    axs[0].bar([i - 0.2 for i in x], [float(s[2]) for s in summary[:-1]], 0.4, label="fixed 900 steps")
    axs[0].bar([i + 0.2 for i in x], [float(s[4]) for s in summary[:-1]], 0.4, label="statistical stop")
    axs[0].set_xticks(list(x))
    axs[0].set_xticklabels(cases, rotation=30, fontsize=8)
    axs[0].set_ylabel("curtainFoam CPU [s]")
    axs[0].legend(fontsize=8)
    for ax, q, label in ((axs[1], "vc_over_vg", "V_c/V_g"), (axs[2], "drift_m", "drift [m]")):
        sel = [r for r in rows if r[1] == "section" and r[2] == q]
        for i, r in enumerate(sel):
            ax.plot([i, i], [float(r[4]), float(r[5])], color="0.6", lw=6, solid_capstyle="butt",
                    label="fixed: window's band" if i == 0 else None)
            ax.plot(i, float(r[3]), "o", color="tab:blue", label="fixed: mean" if i == 0 else None)
            ax.plot(i, float(r[6]), "x", color="tab:red", ms=9, label="statistical: mean" if i == 0 else None)
        ax.set_xticks(range(len(sel)))
        ax.set_xticklabels([r[0] for r in sel], rotation=30, fontsize=8)
        ax.set_ylabel("section " + label)
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
    fig.suptitle("Invicta drum segments: the statistical stop against 900 fixed steps "
                 "(CPU ratio %.2f, %d of %d means inside the band)" % (stt / ft, inside, len(rows)))
    fig.tight_layout()
    files.save_figure(fig, os.path.join(out, "segmentStop.png"), 100)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
