"""docTables: curtainFoam against the packaged twoPhaseEulerFoam, the table of
docs/performance.md, written from results/curtainPeer.csv (docs/figures -update
calls it). Ratios are the peer's over curtainFoam's, both to a drift steady to 1 %."""

from flightedDryer import docFigures as df

PEER = "tests/benchmarks/curtainPeer/results/curtainPeer.csv"


def peer(results):
    """Per mesh level: time to a steady drift of each solver, their ratio, and the drift difference."""
    rows = results.rows(PEER)
    out = ["| level | cells | curtainFoam: steady after [s CPU / s wall], iterations | twoPhaseEulerFoam: steady after [s CPU / s wall] | CPU ratio | wall ratio | drift: curtainFoam / peer [m] | difference |",
           "|---|---|---|---|---|---|---|---|"]
    for level in ("coarse", "medium"):
        cf = results.row(PEER, {"level": level, "np": "1", "solver": "curtainFoam"})
        tp = results.row(PEER, {"level": level, "np": "1", "solver": "twoPhaseEulerFoam"})
        v = lambda r, c: df.finite(r[c], PEER)
        out.append("| %s | %s | %s / %s, %s | %s / %s | %sx | %sx | %s / %s | %s %% |" % (
            level, cf["cells"], df.fmt(v(cf, "steady_cpu_s"), "%.1f"), df.fmt(v(cf, "steady_wall_s"), "%.0f"),
            cf["steady_steps"], df.fmt(v(tp, "steady_cpu_s"), "%.0f"), df.fmt(v(tp, "steady_wall_s"), "%.0f"),
            df.fmt(v(tp, "steady_cpu_s") / v(cf, "steady_cpu_s"), "%.1f"),
            df.fmt(v(tp, "steady_wall_s") / v(cf, "steady_wall_s"), "%.1f"),
            df.fmt(v(cf, "drift_m"), "%.3f"), df.fmt(v(tp, "drift_m"), "%.3f"),
            df.fmt(100 * (v(cf, "drift_m") / v(tp, "drift_m") - 1), "%+.1f")))
    if len(rows) < 2:
        raise df.FigureError("%s: fewer than two rows" % PEER)
    return "\n".join(out)
