"""docTables: the warm-start benchmark's tables of docs/performance.md, written from
results/summary.csv and results/columns.csv (docs/figures -update calls them)."""

from flightedDryer import docFigures as df

SUMMARY = "tests/benchmarks/warmStart/results/summary.csv"
COLUMNS = "tests/benchmarks/warmStart/results/columns.csv"


TABLES = {"cold": "from still gas, against the shipped table's sweep",
          "warm": "warm start, against the shipped table's sweep",
          "warm_vs_cold": "warm start, against from still gas"}
NAMES = {"earlier": "as the shipped table was swept", "cold": "the dictionary now, from still gas",
         "warm": "the dictionary now, warm start"}


def sweeps(results):
    """The three sweeps: CPU, wall time, iterations, and CPU against the shipped table's sweep."""
    out = ["| sweep | runs (warm-started) | CPU [s] | of it curtainFoam [s] | wall [s] | iterations: total, per run | CPU / reference | curtainFoam CPU / reference |",
           "|---|---|---|---|---|---|---|---|"]
    rows = results.rows(SUMMARY)
    if [r["sweep"] for r in rows] != list(NAMES):
        raise df.FigureError("%s: not the sweeps %s" % (SUMMARY, ", ".join(NAMES)))
    for r in rows:
        v = lambda c: df.finite(r[c], SUMMARY)
        out.append("| %s | %s (%s) | %s | %s | %s | %s, %s–%s | %s | %s |"
                   % (NAMES[r["sweep"]], r["runs"], r["warm_started"],
                      df.fmt(v("cpu_s"), "%.0f"), df.fmt(v("solver_cpu_s"), "%.0f"), df.fmt(v("wall_s"), "%.0f"),
                      df.fmt(v("iterations_total"), "%.0f"), df.fmt(v("iterations_min"), "%.0f"),
                      df.fmt(v("iterations_max"), "%.0f"), df.fmt(v("cpu_over_earlier"), "%.2f"),
                      df.fmt(v("solver_cpu_over_earlier"), "%.2f")))
    return "\n".join(out)


def columns(results):
    """The largest difference per table column against the shipped table's sweep, and the rows
    outside the steady criterion."""
    out = ["| table | column | largest difference | relative | rows outside the criterion | criterion |",
           "|---|---|---|---|---|---|"]
    rows = results.rows(COLUMNS)
    if not rows or any(r["table"] not in TABLES for r in rows):
        raise df.FigureError("%s: no rows, or a table other than %s" % (COLUMNS, ", ".join(TABLES)))
    for r in rows:
        v = lambda c: df.finite(r[c], COLUMNS)
        out.append("| %s | `%s` | %s | %s %% | %s of %s | %s %% or %s |"
                   % (TABLES[r["table"]], r["column"], df.fmt(v("max_abs_diff"), "%.3g"),
                      df.fmt(100 * v("max_rel_diff"), "%.2f"), r["outside"], r["rows"],
                      df.fmt(100 * v("rel_tolerance"), "%g"), df.fmt(v("abs_tolerance"), "%g")))
    return "\n".join(out)
