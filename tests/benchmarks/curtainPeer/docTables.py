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
PROFILE_EARLIER = "tests/benchmarks/curtainPeer/results/curtainFoamProfile_medium-earlier.csv"
# the solver's own sections (curtainFoam.C) and, inside them, the solves worth naming
SECTIONS = ("curtainFoam::pressure", "curtainFoam::turbulence", "curtainFoam::momentumPredictor",
            "curtainFoam::solidsFractions", "curtainFoam::solidsMomentum", "curtainFoam::localTimeStep",
            "curtainFoam::checkFields")
INSIDE = ("lduMatrix::solver.p_rgh", "lduMatrix::solver.k.air", "lduMatrix::solver.epsilon.air",
          "lduMatrix::solver.alpha.particles")


def profile_table(results, path):
    """Where a medium curtainFoam run's CPU goes: OpenFOAM's profiling of each
    section of the solver's loop (share of the run; its own share besides the
    solves inside it) and the linear solves that weigh most."""
    rows = {r["section"]: r for r in results.rows(path)}
    v = lambda name, c: df.finite(rows[name][c], path)
    total = v("application::main", "total_s")
    iters = int(v("application::main", "iterations"))
    out = ["| section (%d iterations, %s s with profiling) | share of the run | its own (assembly, outside the solves) | per iteration [ms] |"
           % (iters, df.fmt(total, "%.0f")), "|---|---|---|---|"]
    for name in SECTIONS + INSIDE:
        if name not in rows:
            raise df.FigureError("%s: no section %s" % (path, name))
        out.append("| `%s`%s | %s %% | %s %% | %s |" % (
            name, " (in %s)" % rows[name]["parent"].replace("fvMatrix::solve.", "")
            if name in INSIDE else "", df.fmt(100 * v(name, "share_total"), "%.1f"),
            df.fmt(100 * v(name, "share_self"), "%.1f"), df.fmt(1000 * v(name, "total_s") / iters, "%.1f")))
    return "\n".join(out)


def profile(results):
    """The profile with the template's solver settings."""
    return profile_table(results, PROFILE)


def profile_earlier(results):
    """The profile with the template's earlier solver settings (earlierSettings)."""
    return profile_table(results, PROFILE_EARLIER)


LADDER = "tests/benchmarks/curtainPeer/results/ladder_medium.csv"


def ladder(results):
    """Each change of the solver settings in turn (./ladder): the drift, the
    iterations and CPU to a drift steady to 1 %, the CPU per iteration, and the
    change's share of the CPU saved from the first rung to the last."""
    rows = results.rows(LADDER)
    if len(rows) < 2:
        raise df.FigureError("%s: fewer than two rungs" % LADDER)
    v = lambda r, c: df.finite(r[c], LADDER)
    first, last = v(rows[0], "steady_cpu_s"), v(rows[-1], "steady_cpu_s")
    if not first > last:
        raise df.FigureError("%s: the last rung is not faster than the first" % LADDER)
    out = ["| change (each rung keeps the ones above) | drift [m] | V_c/V_g | iterations to 1 %-steady | CPU to 1 %-steady [s] | CPU per iteration [ms] | share of the CPU saved |",
           "|---|---|---|---|---|---|---|"]
    prev = None
    for r in rows:
        share = "" if prev is None else df.fmt(100 * (prev - v(r, "steady_cpu_s")) / (first - last), "%.0f") + " %"
        out.append("| %s | %s | %s | %s | %s | %s | %s |" % (
            r["change"], df.fmt(v(r, "drift_m"), "%.4f"), df.fmt(v(r, "VcByVg"), "%.4f"),
            df.fmt(v(r, "steady_iterations"), "%.0f"), df.fmt(v(r, "steady_cpu_s"), "%.1f"),
            df.fmt(v(r, "cpu_per_iteration_ms"), "%.0f"), share or "–"))
        prev = v(r, "steady_cpu_s")
    return "\n".join(out)
