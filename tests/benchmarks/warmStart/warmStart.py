"""warmStart: the cold and the warm-started sweep of ./run side by side.

  python3 warmStart.py WORK RESULTS

WORK holds cold.csv, warm.csv (the two tables), cold/ and warm/ (their runs,
each with curtainCase.args.json: iterations, cells, wall time) and cold.time,
warm.time (user s, system s, start, end of each sweep). Writes RESULTS/summary.csv,
RESULTS/cases.csv, RESULTS/columns.csv and RESULTS/warmStart.png."""
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


def main(work, results):
    os.makedirs(results, exist_ok=True)
    sweeps = {}
    for mode in ("cold", "warm"):
        with open(os.path.join(work, mode + ".time")) as f:
            user, sys_, t0, t1 = (float(x) for x in f.read().split())
        r = runs(os.path.join(work, mode))
        sweeps[mode] = {"cpu": user + sys_, "wall": t1 - t0, "runs": r}
    cold, warm = sweeps["cold"], sweeps["warm"]
    if set(cold["runs"]) != set(warm["runs"]):
        raise SystemExit("warmStart: the sweeps ran other cases")
    summary = []
    for mode in ("cold", "warm"):
        s = sweeps[mode]
        its = [v[0] for v in s["runs"].values()]
        solver = sum(v[3] for v in s["runs"].values())
        cold_solver = sum(v[3] for v in cold["runs"].values())
        summary.append({"sweep": mode, "runs": len(its), "warm_started": sum(v[2] for v in s["runs"].values()),
                        "cpu_s": s["cpu"], "solver_cpu_s": solver, "wall_s": s["wall"], "iterations_total": sum(its),
                        "iterations_min": min(its), "iterations_max": max(its),
                        "cpu_over_cold": s["cpu"] / cold["cpu"], "solver_cpu_over_cold": solver / cold_solver})
    files.atomic_write(os.path.join(results, "summary.csv"),
                       "# regenerate: tests/benchmarks/warmStart/run (2 cores)\n" + csv_text(
                           ["sweep", "runs", "warm_started", "cpu_s", "solver_cpu_s", "wall_s", "iterations_total",
                            "iterations_min", "iterations_max", "cpu_over_cold", "solver_cpu_over_cold"], summary, g))
    cases = [{"case": n, "cold_iterations": cold["runs"][n][0], "warm_iterations": warm["runs"][n][0],
              "cold_wall_s": cold["runs"][n][1], "warm_wall_s": warm["runs"][n][1],
              "cold_solver_cpu_s": cold["runs"][n][3], "warm_solver_cpu_s": warm["runs"][n][3],
              "warm_started": "yes" if warm["runs"][n][2] else "no"} for n in sorted(cold["runs"])]
    files.atomic_write(os.path.join(results, "cases.csv"), csv_text(
        ["case", "cold_iterations", "warm_iterations", "cold_wall_s", "warm_wall_s", "cold_solver_cpu_s",
         "warm_solver_cpu_s", "warm_started"], cases, g))
    cmp = compare(os.path.join(work, "cold.csv"), os.path.join(work, "warm.csv"))
    cols = ["column", "rows", "outside", "max_abs_diff", "max_rel_diff", "worst_row", "rel_tolerance",
            "abs_tolerance"]
    files.atomic_write(os.path.join(results, "columns.csv"), csv_text(cols, list(cmp.values()), g))
    figure(cases, os.path.join(work, "cold.csv"), os.path.join(work, "warm.csv"),
           os.path.join(results, "warmStart.png"), summary)
    for r in summary:
        print("%s: %d runs, CPU %.0f s, wall %.0f s, iterations %d-%d (CPU %.2f of cold)"
              % (r["sweep"], r["runs"], r["cpu_s"], r["wall_s"], r["iterations_min"], r["iterations_max"],
                 r["cpu_over_cold"]))
    for c in cmp.values():
        print("%s: largest difference %.3g (%.2f %%), %d of %d rows outside the steady criterion"
              % (c["column"], c["max_abs_diff"], 100 * c["max_rel_diff"], c["outside"], c["rows"]))


def figure(cases, cold_csv, warm_csv, out, summary):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(1, 3, figsize=(16, 4.8))
    x = range(len(cases))
    axs[0].bar([i - 0.2 for i in x], [c["cold_iterations"] for c in cases], 0.4, label="from still gas")
    axs[0].bar([i + 0.2 for i in x], [c["warm_iterations"] for c in cases], 0.4, label="from a neighbour")
    axs[0].set_xlabel("run (by name)")
    axs[0].set_ylabel("iterations to a steady drift")
    axs[0].set_title("CPU: warm %.2f of cold" % summary[1]["cpu_over_cold"])
    axs[0].legend(fontsize=8)
    a, b = read_rows(cold_csv), read_rows(warm_csv)
    for ax, col, label in ((axs[1], "drift_m", "drift [m]"), (axs[2], "vc_over_vg", "V_c/V_g")):
        xs = [float(a[k][col]) for k in sorted(a)]
        ys = [float(b[k][col]) for k in sorted(a)]
        ax.plot(xs, ys, ".", ms=4)
        lo, hi = min(xs + ys), max(xs + ys)
        ax.plot([lo, hi], [lo, hi], "k-", lw=0.8)
        ax.set_xlabel("%s, from still gas" % label)
        ax.set_ylabel("%s, warm-started" % label)
        ax.grid(alpha=0.3)
        if col == "drift_m":
            ax.set_xscale("log")
            ax.set_yscale("log")
    fig.tight_layout()
    files.save_figure(fig, out, 100)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    main(sys.argv[1], sys.argv[2])
