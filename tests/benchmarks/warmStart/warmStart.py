"""warmStart: the sweeps of ./run side by side: as the shipped table was swept
(the reference: the solver settings and the dictionary set-up of then), as the
dictionary says now from still gas, and the same warm-started.

  python3 warmStart.py WORK RESULTS [SHIPPED]

WORK holds earlier.csv, cold.csv, warm.csv (the tables), earlier/, cold/ and warm/
(their runs, each with curtainCase.args.json: iterations, cells, wall time) and
earlier.time, cold.time, warm.time (user s, system s, start, end of each sweep).
Writes RESULTS/summary.csv, RESULTS/cases.csv, RESULTS/columns.csv (each table
against the earlier one) and RESULTS/warmStart.png. With SHIPPED (the table the
dictionary names), summary.csv says whether the earlier sweep's rows are its rows."""
import csv
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.realpath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "src", "python"))
from flightedDryer import files  # noqa: E402
from flightedDryer.sweep.compare import compare, read_rows  # noqa: E402


MODES = ("earlier", "cold", "warm")


def solver_cpu(case):
    """curtainFoam's own CPU time (its last ExecutionTime) in a run's case."""
    t = None
    with open(os.path.join(case, "log.curtainFoam"), errors="replace") as f:
        for line in f:
            if line.startswith("ExecutionTime = "):
                t = float(line.split()[2])
    if t is None or not math.isfinite(t):
        raise SystemExit("warmStart: no finite ExecutionTime in %s/log.curtainFoam" % case)
    return t


def runs(folder):
    """{case: (iterations, wall s, warm-started, solver CPU s)} of a sweep's finished runs."""
    out = {}
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name, "curtainCase.args.json")
        if os.path.isfile(path):
            with open(path) as f:
                a = json.load(f)
            out[name] = (int(a["iterations"]), float(a["wall_time_s"]), "-startFrom" in a["argv"],
                         solver_cpu(os.path.join(folder, name, "case")))
    if not out:
        raise SystemExit("warmStart: no finished runs in %s" % folder)
    return out


def csv_text(cols, rows, fmt):
    return ",".join(cols) + "\n" + "".join(",".join(fmt(r[c]) for c in cols) + "\n" for r in rows)


def g(v):
    return "%.6g" % v if isinstance(v, float) else str(v)


def data_rows(path):
    with open(path) as f:
        return [line for line in f if not line.startswith("#")]


def main(work, results, shipped=None):
    os.makedirs(results, exist_ok=True)
    sweeps = {}
    for mode in MODES:
        with open(os.path.join(work, mode + ".time")) as f:
            user, sys_, t0, t1 = (float(x) for x in f.read().split())
        r = runs(os.path.join(work, mode))
        sweeps[mode] = {"cpu": user + sys_, "wall": t1 - t0, "runs": r}
    ref = sweeps["earlier"]
    for mode in MODES:
        if set(sweeps[mode]["runs"]) != set(ref["runs"]):
            raise SystemExit("warmStart: the %s sweep ran other cases than the earlier one" % mode)
    ref_solver = sum(v[3] for v in ref["runs"].values())
    summary = []
    for mode in MODES:
        s = sweeps[mode]
        its = [v[0] for v in s["runs"].values()]
        solver = sum(v[3] for v in s["runs"].values())
        summary.append({"sweep": mode, "runs": len(its), "warm_started": sum(v[2] for v in s["runs"].values()),
                        "cpu_s": s["cpu"], "solver_cpu_s": solver, "wall_s": s["wall"], "iterations_total": sum(its),
                        "iterations_min": min(its), "iterations_max": max(its),
                        "outside_solver_cpu_per_run_s": (s["cpu"] - solver) / len(its),
                        "cpu_over_earlier": s["cpu"] / ref["cpu"], "solver_cpu_over_earlier": solver / ref_solver,
                        "solver_ms_per_iteration": 1000 * solver / sum(its),
                        "rows_as_shipped": ("" if shipped is None else "yes" if data_rows(os.path.join(work, mode + ".csv"))
                                            == data_rows(shipped) else "no")})
    files.atomic_write(os.path.join(results, "summary.csv"),
                       "# regenerate: tests/benchmarks/warmStart/run (2 cores)\n" + csv_text(
                           ["sweep", "runs", "warm_started", "cpu_s", "solver_cpu_s", "wall_s", "iterations_total",
                            "iterations_min", "iterations_max", "outside_solver_cpu_per_run_s", "cpu_over_earlier",
                            "solver_cpu_over_earlier", "solver_ms_per_iteration",
                            "rows_as_shipped"],
                           summary, g))
    cases = [dict([("case", n)]
                  + [("%s_iterations" % m, sweeps[m]["runs"][n][0]) for m in MODES]
                  + [("%s_solver_cpu_s" % m, sweeps[m]["runs"][n][3]) for m in MODES]
                  + [("warm_started", "yes" if sweeps["warm"]["runs"][n][2] else "no")])
             for n in sorted(ref["runs"])]
    files.atomic_write(os.path.join(results, "cases.csv"), csv_text(list(cases[0]), cases, g))
    cols = ["table", "column", "rows", "outside", "max_abs_diff", "max_rel_diff", "worst_row", "rel_tolerance",
            "abs_tolerance"]
    cmp_rows = []
    for table, ref_name, name in (("cold", "earlier", "cold"), ("warm", "earlier", "warm"),
                                  ("warm_vs_cold", "cold", "warm")):
        for c in compare(os.path.join(work, ref_name + ".csv"), os.path.join(work, name + ".csv")).values():
            cmp_rows.append(dict(c, table=table))
    files.atomic_write(os.path.join(results, "columns.csv"), csv_text(cols, cmp_rows, g))
    figure(cases, work, os.path.join(results, "warmStart.png"), summary)
    for r in summary:
        print("%s: %d runs, CPU %.0f s, wall %.0f s, iterations %d-%d (CPU %.2f of the earlier sweep)%s"
              % (r["sweep"], r["runs"], r["cpu_s"], r["wall_s"], r["iterations_min"], r["iterations_max"],
                 r["cpu_over_earlier"], "; the shipped table's rows: " + r["rows_as_shipped"]
                 if r["rows_as_shipped"] else ""))
    for c in cmp_rows:
        print("%s, %s: largest difference %.3g (%.2f %%), %d of %d rows outside the steady criterion"
              % (c["table"], c["column"], c["max_abs_diff"], 100 * c["max_rel_diff"], c["outside"], c["rows"]))


def figure(cases, work, out, summary):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(1, 3, figsize=(16, 4.8))
    x = range(len(cases))
    labels = {"earlier": "as the shipped table was swept", "cold": "now, from still gas", "warm": "now, from a neighbour"}
    for k, m in enumerate(MODES):
        axs[0].bar([i + 0.27 * (k - 1) for i in x], [c["%s_iterations" % m] for c in cases], 0.27, label=labels[m])
    axs[0].set_xlabel("run (by name)")
    axs[0].set_ylabel("iterations to a steady drift")
    by = {r["sweep"]: r for r in summary}
    axs[0].set_title("CPU of the shipped table's sweep: %.2f from still gas, %.2f warm"
                     % (by["cold"]["cpu_over_earlier"], by["warm"]["cpu_over_earlier"]))
    axs[0].legend(fontsize=8)
    ref = read_rows(os.path.join(work, "earlier.csv"))
    for ax, col, label in ((axs[1], "drift_m", "drift [m]"), (axs[2], "vc_over_vg", "V_c/V_g")):
        xs = [float(ref[k][col]) for k in sorted(ref)]
        for m in ("cold", "warm"):
            b = read_rows(os.path.join(work, m + ".csv"))
            ax.plot(xs, [float(b[k][col]) for k in sorted(ref)], ".", ms=4, label=labels[m])
        lo, hi = min(xs), max(xs)
        ax.plot([lo, hi], [lo, hi], "k-", lw=0.8)
        ax.set_xlabel("%s, as the shipped table was swept" % label)
        ax.set_ylabel("%s, the dictionary now" % label)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        if col == "drift_m":
            ax.set_xscale("log")
            ax.set_yscale("log")
    fig.tight_layout()
    files.save_figure(fig, out, 100)


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4):
        raise SystemExit(__doc__)
    main(*sys.argv[1:])
