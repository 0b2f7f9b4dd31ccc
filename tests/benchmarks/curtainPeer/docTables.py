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


PROFILE = "tests/benchmarks/curtainPeer/results/curtainFoamProfile_medium.csv"
# the solver's own sections (curtainFoam.C) and, inside them, the solves worth naming
SECTIONS = ("curtainFoam::pressure", "curtainFoam::turbulence", "curtainFoam::momentumPredictor",
            "curtainFoam::solidsFractions", "curtainFoam::solidsMomentum", "curtainFoam::localTimeStep",
            "curtainFoam::checkFields")
INSIDE = ("lduMatrix::solver.p_rgh", "lduMatrix::solver.k.air", "lduMatrix::solver.epsilon.air",
          "lduMatrix::solver.alpha.particles")


def profile(results):
    """Where a medium curtainFoam run's CPU goes: OpenFOAM's profiling of each
    section of the solver's loop (share of the run; its own share besides the
    solves inside it) and the linear solves that weigh most."""
    rows = {r["section"]: r for r in results.rows(PROFILE)}
    v = lambda name, c: df.finite(rows[name][c], PROFILE)
    total = v("application::main", "total_s")
    iters = int(v("application::main", "iterations"))
    out = ["| section (%d iterations, %s s with profiling) | share of the run | its own (assembly, outside the solves) | per iteration [ms] |"
           % (iters, df.fmt(total, "%.0f")), "|---|---|---|---|"]
    for name in SECTIONS + INSIDE:
        if name not in rows:
            raise df.FigureError("%s: no section %s" % (PROFILE, name))
        out.append("| `%s`%s | %s %% | %s %% | %s |" % (
            name, " (in %s)" % rows[name]["parent"].replace("fvMatrix::solve.", "")
            if name in INSIDE else "", df.fmt(100 * v(name, "share_total"), "%.1f"),
            df.fmt(100 * v(name, "share_self"), "%.1f"), df.fmt(1000 * v(name, "total_s") / iters, "%.1f")))
    return "\n".join(out)
