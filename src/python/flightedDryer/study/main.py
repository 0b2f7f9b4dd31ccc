"""main: dryerStudy's main: the description read (exit 2 on bad input, nothing run),
the drift table planned from the drum model's own queries, swept (or an earlier
sweep of the same inputs reused, or resumed), the drum model run on every route,
and the report written. study.json is written last: a folder without it is not a
finished study."""

import hashlib
import json
import os
import subprocess
import sys
import time

from .. import options
from ..errors import InputError, RunError, SchedulerError
from ..files import WriteError, atomic_write
from ..messages import sayer
from ..processes import Children, interrupts_raise, run_tied
from ..sweep.dictionary import read_sweep
from ..sweep.main import SCHEDULER_OPTIONS, check_scheduler
from ..sweep.plan import box_case
from . import plan, report, routes, segment
from .description import Description

say = sayer("dryerStudy")
FLAGS = {"-plan", "-yes"}
VALUED = {"-dict", "-out", "-jobs"} | set(SCHEDULER_OPTIONS)
DONE = "study.json"


def _sweep(text_of, name, out, jobs, scheduler, children):
    """The table out/table/<name>, its sweep dictionary text_of(table path): reused
    when the dictionary is the same as the finished one there, else swept
    (buildDriftTable resumes finished runs)."""
    tdir = os.path.join(out, "table")
    os.makedirs(tdir, exist_ok=True)
    table = os.path.join(tdir, name)
    text = text_of(table)
    sig = hashlib.sha256(text.encode()).hexdigest()
    sig_file = os.path.join(tdir, "driftTable.inputs")
    if os.path.isfile(table) and os.path.isfile(sig_file) and open(sig_file).read().strip() == sig:
        say("the drift table of these inputs is there already: %s (reused)" % table)
        return table, None
    if os.path.exists(sig_file):
        os.remove(sig_file)
    atomic_write(os.path.join(tdir, "sweepDict"), text)
    t0 = time.time()
    # in a process group of its own, tied to this tool: stopped with it (it stops its runs)
    rc = children.call(["buildDriftTable", "-dict", os.path.join(tdir, "sweepDict"), "-jobs", str(jobs)]
                       + [x for k in SCHEDULER_OPTIONS if k in scheduler for x in (k, scheduler[k])])
    if rc == 2:
        raise RunError("buildDriftTable refused the planned sweep (%s): see its message above"
                       % os.path.join(tdir, "sweepDict"))
    if rc != 0:
        raise RunError("the sweep did not finish (buildDriftTable exit %d; rerun the same command to resume)" % rc)
    atomic_write(sig_file, sig + "\n")
    return table, time.time() - t0


def _curtain(g, out):
    """One curtain of the table kept and pictured: the sweep's own run of the middle
    grid point at the highest floor (sweep.plan.box_case), with -keep."""
    cdir = os.path.join(out, "curtain")
    V = g["gasVelocity"][len(g["gasVelocity"]) // 2]
    S = g["spillRate"][len(g["spillRate"]) // 2]
    Y = g["floors"][-1]
    s = read_sweep(os.path.join(out, "table", "sweepDict"))
    c = box_case(s, V, S, g["flightLength"][0], g["particleDensity"][0], Y)
    with open(os.path.join(out, "log.curtain"), "w") as log:
        if run_tied(["curtainCase", "-dir", cdir] + c["args"] + ["-keep"], stdout=log,
                    stderr=subprocess.STDOUT).returncode != 0:
            return None
        if run_tied(["plotCurtain", "-case", os.path.join(cdir, "case"), "-out", os.path.join(out, "curtain.png"),
                     "-noVTK"], stdout=log, stderr=subprocess.STDOUT).returncode != 0:
            return None
    return "One curtain of the table: V_g %g m/s, spill %g kg/(m s), fall %g m (curtain/, plotCurtain)." % (V, S, Y)


def _write_plan(info, out):
    atomic_write(os.path.join(out, "plan.json"), json.dumps(info, indent=1) + "\n")


def _record_plan(info, g, study, out):
    """The plan's runs, CPU estimate and grid into info, and plan.json."""
    info.update(runs=plan.runs(g), estimate_s=plan.cpu_estimate_s(g, study),
                grid={k: g[k] for k in ("gasVelocity", "spillRate", "fallHeight", "floors", "diameter")})
    _write_plan(info, out)


def _stop_at_plan(info, study, opts, out):
    """The exit status when the study stops at its plan (-plan: 0; a sweep above
    study.confirmAbove_s without -yes: 3), else None."""
    if opts.get("-plan"):
        say("-plan: nothing swept; the plan is in %s" % os.path.join(out, "plan.json"))
        return 0
    if info["estimate_s"] > study["confirmAbove_s"] and not opts.get("-yes"):
        say("the sweep would take about %.0f s of CPU, above study.confirmAbove_s %g s: give -yes to run it"
            % (info["estimate_s"], study["confirmAbove_s"]))
        return 3
    return None


def _segments(desc, study, q, info, out, opts, jobs, children):
    """The drum-segment scene: the flight dictionary from the description, the
    grid from the drum model's repose angles and gas velocities, the plan and its
    CPU estimate, the sweep. (table, wall time, {grid, report}); (None, exit
    status, None) when it stops at the plan."""
    bed, x = segment.bed_depth(os.path.join(out, "plan", "planner"), desc)
    g = segment.grid(q, study)
    flights = os.path.join(out, "table", "segment.yaml")
    os.makedirs(os.path.dirname(flights), exist_ok=True)
    atomic_write(flights, segment.flight_dictionary(desc, bed, g["reposeAngle"][len(g["reposeAngle"]) // 2]))
    cells, picture = segment.preview(flights, out, say)
    info.update(runs=segment.runs(g), estimate_s=segment.cpu_estimate_s(g, cells, study), grid=g, bedDepth_m=bed,
                cells=cells)
    _write_plan(info, out)
    say("plan: %d drum segments (repose %s deg x V_g %s m/s; %d cells each, a level bed %.3g m deep: the drum "
        "model's kilning bed at x = %g m), about %.0f s of CPU"
        % (info["runs"], g["reposeAngle"], g["gasVelocity"], cells, bed, x, info["estimate_s"]))
    stop = _stop_at_plan(info, study, opts, out)
    if stop is not None:
        return None, stop, None
    table, wall = _sweep(lambda t: segment.sweep_dict(g, desc, study, flights, t, plan.gas_temperature(desc)),
                         "segmentTable.csv", out, int(jobs), opts, children)
    # the segment route asks what the Eq 142 pass asked (the repose angles are the
    # moisture's, the gas velocity the gas rate's): checked, not widened
    name, drift, section = routes.route_settings(table, 0.1, "segment")[0]
    asked = plan.queries(desc, os.path.join(out, "plan", "check", name), say, drift, section,
                         "route %s on the segment table" % name)
    miss = segment.covers(g, asked)
    if miss:
        raise RunError("the segment route asks beyond the segment grid on %s" % ", ".join(miss))
    with open(picture, "rb") as f:
        atomic_write(os.path.join(out, "segmentFlights.png"), f.read())
    d, rho = segment.particle(desc)
    return table, wall, {"grid": g, "report": {
        "cells": cells, "bed": "%.3g m" % bed, "particle": "%g um, %g kg/m3" % (d * 1e6, rho),
        "repose": " ".join("%g" % v for v in g["reposeAngle"]),
        "gas": " ".join("%g" % v for v in g["gasVelocity"])}}


def run(opts, children):
    desc = Description(opts["-dict"])
    study = desc.study
    out = os.path.abspath(opts["-out"])
    if os.path.exists(out) and not os.path.isdir(out):
        raise InputError("-out %s is a file, not a folder" % out)
    jobs = opts.get("-jobs", "1")
    if not jobs.isdigit() or not 1 <= int(jobs) <= 256:
        raise InputError("-jobs = '%s' outside the allowed range [1, 256] (whole number)" % jobs)
    check_scheduler(opts)
    os.makedirs(out, exist_ok=True)
    for mine in (DONE, "report.html"):      # never left looking finished while it is not
        if os.path.exists(os.path.join(out, mine)):
            os.remove(os.path.join(out, mine))
    curve = study["curve"]
    points = [None] + ([(curve["entry"], v) for v in curve["values"]] if curve else [])
    q = plan.queries(desc, os.path.join(out, "plan", "planner"), say)
    for k, pt in enumerate(points[1:]):
        # one table serves the whole curve: the grid covers every point's queries
        q = plan.union(q, plan.queries(desc, os.path.join(out, "plan", "curve%d" % k), say,
                                       what="Eq 142 pass, %s %g" % pt, override=pt))
    sc = ({"scene": "table", "route": "table", "why": "the description gives its drift table (study.table)"}
          if study["table"] else plan.scene(q, desc, study["scene"]))
    say("scene %s: %s" % (sc["scene"], sc["why"]))
    info = {"queries": q, "estimate_s": 0.0, "runs": 0, "scene": sc["scene"], "why": sc["why"]}
    e, e_source = routes.error_band()
    g = seg = None
    kind = "table"
    if study["table"]:
        table, wall = study["table"], None
        kind = segment.table_kind(table)
        say("the drift table is the description's: %s (no sweep)" % table)
    elif sc["route"] == "segment":
        table, wall, seg = _segments(desc, study, q, info, out, opts, jobs, children)
        if table is None:
            return wall
        kind = "segment"
    elif sc["route"] != "table":
        # the scene needs no curtain run: the study's own route is the lone particles'
        table, wall = None, None
        _write_plan(info, out)
        say("plan: no curtain runs (scene %s); the drift is the lone particles'" % sc["scene"])
        if opts.get("-plan"):
            say("-plan: nothing to sweep; the plan is in %s" % os.path.join(out, "plan.json"))
            return 0
    else:
        g = plan.grid(q, desc, study)
        miss = plan.covers(g, q)
        if miss:
            raise RunError("the planned grid misses the queries on %s" % ", ".join(miss))
        _record_plan(info, g, study, out)
        say("plan: %d curtain runs (V_g %s m/s x spill %s kg/(m s) x floors %s m), about %.0f s of CPU"
            % (info["runs"], g["gasVelocity"], g["spillRate"], g["floors"], info["estimate_s"]))
        stop = _stop_at_plan(info, study, opts, out)
        if stop is not None:
            return stop
        # the table's own routes may ask beyond what the Eq 142 pass asked (the drum
        # model's state follows its drift): each is run on the table (clamped,
        # recorded), and the grid widened and swept again until it covers them
        wall = 0.0
        for attempt in range(4):
            table, took = _sweep(lambda t: plan.sweep_dict(g, desc, study, t), "driftTable.csv", out, int(jobs),
                                 opts, children)
            wall += took or 0.0
            asked = q
            for k, pt in enumerate(points):
                for name, drift, section in routes.route_settings(table, e):
                    if drift == "table":
                        asked = plan.union(asked, plan.queries(
                            desc, os.path.join(out, "plan", "check%d" % attempt, "%s%d" % (name, k)), say, drift,
                            dict(section, outside="clamp"), "route %s on the table%s"
                            % (name, ", %s %g" % pt if pt else ""), override=pt))
            miss = plan.covers(g, asked)
            if not miss:
                break
            if attempt == 3:
                raise RunError("the table's routes still ask beyond its grid on %s after 3 widenings"
                               % ", ".join(miss))
            say("the routes ask beyond the grid on %s: widening it" % ", ".join(miss))
            q = asked
            g = plan.grid(q, desc, study)
            _record_plan(info, g, study, out)
        wall = wall or None
    rows = routes.run_routes(desc, table, e, os.path.join(out, "routes"), say, kind=kind)
    routes.write_routes(rows, os.path.join(out, "routes.csv"))
    curve_rows = []
    for k, pt in enumerate(points[1:]):
        r = routes.run_routes(desc, table, e, os.path.join(out, "curve", "%d" % k), say, override=pt, kind=kind)
        curve_rows += [dict(row, value=pt[1]) for row in r]
    if curve_rows:
        routes.write_routes(curve_rows, os.path.join(out, "curve.csv"), ["value"])
        report.curve_figure(curve_rows, curve["entry"], os.path.join(out, "curve.png"))
    curtain = None
    if kind == "segment":
        segment.table_figure(table, os.path.join(out, "segmentTable.png"))
        if seg:
            curtain = segment.picture(os.path.join(out, "table", "work"), seg["grid"], out)
    elif table:
        run_tied(["plotDriftTable", table, os.path.join(out, "driftTable.png")], capture_output=True)
        curtain = _curtain(g, out) if g else None
    planned = {"scene": sc["scene"], "why": sc["why"], "runs": info["runs"], "estimate_s": info["estimate_s"], "swept": wall is not None,
               "wall_s": wall or 0.0, "source": table,
               "level": study["level"], "drag": study["drag"], "box": "%g" % plan.box_width(desc),
               "gas_t": "%g" % plan.gas_temperature(desc),
               "gas": g and " ".join("%g" % v for v in g["gasVelocity"]),
               "spill": g and " ".join("%g" % v for v in g["spillRate"]),
               "falls": g and " ".join("%g" % v for v in g["floors"]),
               "classes": len(desc.sections["material"]["sizes_um"]),
               "queries": "; ".join("%s %.4g-%.4g" % (k, v[0], v[1]) for k, v in q.items())}
    planned["tableFigure"] = "segmentTable.png" if kind == "segment" else "driftTable.png"
    if seg:
        planned.update(seg["report"])
    report.write(desc, out, rows, e, e_source, planned, curtain, curve and curve["entry"])
    atomic_write(os.path.join(out, DONE), json.dumps({"description": desc.path, "table": table,
                                                      "routes": rows, "plan": info}, indent=1) + "\n")
    say("report: %s" % os.path.join(out, "report.html"))
    return 0


def main(argv, usage):
    interrupts_raise()
    children = Children()
    try:
        opts = options.parse(argv, FLAGS, VALUED, ("-dict", "-out"), "dryerStudy", usage)
        return run(opts, children)
    except InputError as e:
        print("dryerStudy: bad input: %s" % e, file=sys.stderr)
        return 2
    except (RunError, SchedulerError, WriteError, OSError) as e:
        print("dryerStudy: FAILED: %s" % e, file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        children.stop_all()
        print("dryerStudy: interrupted; rerun the same command to go on (finished curtain runs are kept)",
              file=sys.stderr)
        return 130
    finally:
        children.stop_all()
