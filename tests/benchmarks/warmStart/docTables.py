"""docTables: the warm-start benchmark's tables of docs/performance.md, written from
results/summary.csv and results/columns.csv (docs/figures -update calls them)."""

from flightedDryer import docFigures as df

SUMMARY = "tests/benchmarks/warmStart/results/summary.csv"
COLUMNS = "tests/benchmarks/warmStart/results/columns.csv"


def sweeps(results):
    """Cold against warm: CPU, wall time, iterations."""
    out = ["| sweep | runs (warm-started) | CPU [s] | of it curtainFoam [s] | wall [s] | iterations: total, per run | CPU / cold | curtainFoam CPU / cold |",
           "|---|---|---|---|---|---|---|---|"]
    rows = results.rows(SUMMARY)
    if len(rows) != 2:
        raise df.FigureError("%s: not the two sweeps" % SUMMARY)
    for r in rows:
        v = lambda c: df.finite(r[c], SUMMARY)
        out.append("| %s | %s (%s) | %s | %s | %s | %s, %s–%s | %s | %s |"
                   % ("from still gas" if r["sweep"] == "cold" else "warm start", r["runs"], r["warm_started"],
                      df.fmt(v("cpu_s"), "%.0f"), df.fmt(v("solver_cpu_s"), "%.0f"), df.fmt(v("wall_s"), "%.0f"),
                      df.fmt(v("iterations_total"), "%.0f"), df.fmt(v("iterations_min"), "%.0f"),
                      df.fmt(v("iterations_max"), "%.0f"), df.fmt(v("cpu_over_cold"), "%.2f"),
                      df.fmt(v("solver_cpu_over_cold"), "%.2f")))
    return "\n".join(out)


def columns(results):
    """The largest difference per table column, against the steady criterion."""
    out = ["| column | largest difference | relative | rows outside the criterion | criterion |",
           "|---|---|---|---|---|"]
    rows = results.rows(COLUMNS)
    if not rows:
        raise df.FigureError("%s: no rows" % COLUMNS)
    for r in rows:
        v = lambda c: df.finite(r[c], COLUMNS)
        out.append("| `%s` | %s | %s %% | %s of %s | %s %% or %s |"
                   % (r["column"], df.fmt(v("max_abs_diff"), "%.3g"), df.fmt(100 * v("max_rel_diff"), "%.2f"),
                      r["outside"], r["rows"], df.fmt(100 * v("rel_tolerance"), "%g"),
                      df.fmt(v("abs_tolerance"), "%g")))
    return "\n".join(out)
