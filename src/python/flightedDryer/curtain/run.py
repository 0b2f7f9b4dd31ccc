"""run: the curtainFoam run of a case and its resume. The steady state is decided
inside the run; a run not steady by its end, or diverging, goes on once from its
last whole written time with half the Courant numbers (the gentle stage); an
interrupted run started again with the same inputs goes on from its last whole
time and ends with the same result."""

import json
import os
import re
import shutil
import subprocess
import time

from ..errors import Diverged, RunError
from ..foamTimes import drop_times_after, last_time_in_log, latest_time
from ..warmStart import source_time
from ..messages import time_or_none
from ..processes import write_lock_info
from . import dictionaries as fd
from .dictionaries import set_entry
from .folders import all_files, atomic_write, install_case, prune, signature
from .results import count_cells, dat_header_value, landing_text, result_text, window_results
from .settings import ARGS, INPUTS, LANDING, MANIFEST, RESULT, STAGE, say
from .setUp import check_from, round_up, set_up


def solver_command(s):
    if s["np"] > 1:
        return ["mpirun", "--allow-run-as-root", "-np", str(s["np"]), "curtainFoam", "-parallel"]
    return ["curtainFoam"]


def run_logged(children, cmd, case, log, what, lock_fd):
    with open(os.path.join(case, log), "a") as f:
        p = children.spawn(cmd, f, cwd=case, pass_fds=(lock_fd,))
        p.wait()
        children.done(p)
    if p.returncode != 0:
        raise RunError("%s failed (exit %d); see %s" % (what, p.returncode, os.path.join(case, log)))


def solve(children, s, case, lock_fd, end):
    """Run curtainFoam from its latest time to `end` (or until runTimeControl stops
    it steady), printing progress. Returns the last iteration of the run."""
    log = os.path.join(case, "log.curtainFoam")
    with open(log, "a") as f:
        p = children.spawn(solver_command(s), f, cwd=case, pass_fds=(lock_fd,))
        write_lock_info(lock_fd, {"pid": os.getpid(), "pgid": p.pid})
        shown = -1
        while p.poll() is None:
            try:
                p.wait(2)
            except subprocess.TimeoutExpired:
                pass
            t = last_time_in_log(log)
            try:
                it = int(float(t))
            except (TypeError, ValueError):
                continue
            if it // max(1, end // 5) != shown:
                shown = it // max(1, end // 5)
                say("  iteration %d/%d" % (it, end))
        children.done(p)
        write_lock_info(lock_fd, {"pid": os.getpid(), "pgid": None})
    if p.returncode != 0:
        with open(log, errors="replace") as f:
            lines = [l.rstrip() for l in f if l.strip()]
        text = "\n".join(lines[-400:])
        tail = ""
        if "FOAM FATAL" in text:
            # an input error is not a divergence (no gentler second stage)
            i = max(k for k, l in enumerate(lines) if "FOAM FATAL" in l)
            tail = " ".join(lines[i + 1:i + 3])
        elif "sigFpe" in text or "residual = nan" in text or re.search(
                r"^Floating point exception(?! trapping)", text, re.M):
            tail = "floating-point exception: the solution diverged"
        elif lines:
            tail = lines[-1]
        good = latest_time(case, s["np"])
        raise (Diverged if diverging(tail) else RunError)(
            "curtainFoam failed (exit %d) at iteration %s; last good time on disk: %s; "
            "log: %s%s" % (p.returncode, last_time_in_log(log), time_or_none(good), log,
                           ("; " + tail) if tail else ""))
    t = last_time_in_log(log)
    return int(round(float(t))) if t is not None else None


def diverging(cause):
    """Is curtainFoam's stated cause of a stop a diverging iteration (worth a
    gentler second stage), rather than an input it refuses? Its own field check
    (checkFields.H) stops a NaN or Inf and a gas too fast ("the iteration
    diverges"); the floating-point trap is named here ("the solution diverged"); a
    solver's NaN residual shows as OpenFOAM failing to read it back from the
    solver-performance data ("expected scalar value, found ... word 'nan'")."""
    if re.search(r"expected scalar value, found .*word '[-+]?(nan|inf)'", cause, re.IGNORECASE):
        return True
    return any(k in cause for k in ("diverged", "diverges", "NaN or Inf"))


def stopped_steady(case):
    """Did runTimeControl end the last run on the steady condition?"""
    steady = False
    with open(os.path.join(case, "log.curtainFoam"), errors="replace") as f:
        for line in f:
            if line.startswith("Starting time loop"):
                steady = False
            elif "Stopping calculation" in line:
                steady = True
    return steady


def worst_spread(case):
    """The last unsteady window the steadyWindow conditions logged, for messages."""
    worst = None
    with open(os.path.join(case, "log.curtainFoam"), errors="replace") as f:
        for line in f:
            if "steadyWindow:" in line and not line.rstrip().endswith("; steady"):
                worst = line.strip()
    return worst or "no steadiness check ran"


def go_gentler(s, case, why):
    """Half the local-time-step Courant numbers (the start-up phase's too), 4N more
    iterations from the latest written time (the initial fields if none)."""
    fvs = os.path.join(case, "system", "fvSolution")
    cd = os.path.join(case, "system", "controlDict")
    co = fd.scalar(fvs, "PIMPLE/maxCo")
    cop = fd.scalar(fvs, "PIMPLE/maxCoParticles")
    start_co = fd.scalar(fvs, "PIMPLE/startUp/maxCo") if fd.has(fvs, "PIMPLE/startUp/maxCo") else None
    start = latest_time(case, s["np"]) or 0
    gone = drop_times_after(case, s["np"], start)
    if gone:
        say("time folder(s) %s written in part: removed" % " ".join(gone))
    end = round_up(int(round(start)) + 4 * s["iterations"], s["window"])
    say("%s; going on from iteration %g with half the Courant numbers (maxCo %g -> %g, %s"
        "maxCoParticles %g -> %g) up to iteration %d"
        % (why, start, co, co / 2,
           "" if start_co is None else "start-up maxCo %g -> %g, " % (start_co, start_co / 2),
           cop, cop / 2, end))
    set_entry(fvs, "PIMPLE/maxCo", "%.12g" % (co / 2))
    set_entry(fvs, "PIMPLE/maxCoParticles", "%.12g" % (cop / 2))
    if start_co is not None:
        set_entry(fvs, "PIMPLE/startUp/maxCo", "%.12g" % (start_co / 2))
    set_entry(cd, "endTime", str(end))
    for c in fd.keywords(cd, "functions/steady/conditions"):
        # judge the window of the gentler run only
        set_entry(cd, "functions/steady/conditions/%s/startTime" % c,
                  str(int(round(start)) + s["window"]))
    write_stage(case, {"stage": "gentle", "end": end})
    return end


def read_stage(case):
    try:
        with open(os.path.join(case, STAGE)) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def write_stage(case, stage):
    atomic_write(os.path.join(case, STAGE), json.dumps(stage) + "\n")


def prepare(children, s, part, lock_fd):
    """A fresh case in `part`, or the interrupted one of the same inputs resumed.
    Returns (cells, end iteration of the current stage, resumed from)."""
    sig = signature(s)
    if os.path.isdir(part):
        try:
            with open(os.path.join(part, INPUTS)) as f:
                same = f.read().strip() == sig
        except OSError:
            raise RunError("%s exists and was not made by curtainCase: move it away" % part)
        stage = read_stage(part)
        if same and stage and os.path.isfile(os.path.join(part, "log.blockMesh")):
            start = latest_time(part, s["np"])
            if start is not None:
                gone = drop_times_after(part, s["np"], start)
                if gone:
                    say("time folder(s) %s written in part: removed" % " ".join(gone))
                say("resuming the interrupted run in %s from iteration %g" % (part, start))
                return count_cells(part), stage["end"], start
        say("removing the unfinished run of %s in %s" % ("the same inputs" if same else "other inputs",
                                                        part))
        shutil.rmtree(part)
    # the folder is marked as this tool's (with the inputs it is for) before
    # anything goes in: a set-up cut short by a signal is then removed and done
    # again by the next run, not refused as a stranger's folder
    os.makedirs(part)
    atomic_write(os.path.join(part, INPUTS), sig + "\n")
    set_up(s, part)
    shutil.copytree(os.path.join(part, "0.orig"), os.path.join(part, "0"))
    run_logged(children, ["blockMesh"], part, "log.blockMesh", "blockMesh", lock_fd)
    if "startFromDir" in s:
        warm_start(s, part)
    if s["np"] > 1:
        run_logged(children, ["decomposePar", "-force"], part, "log.decomposePar", "decomposePar", lock_fd)
    write_stage(part, {"stage": "first", "end": s["end"]})
    return count_cells(part), s["end"], None


def warm_start(s, part):
    """-startFrom: the source's last time folder named in constant/curtainProperties
    (startFields, read by curtainFoam at time 0), after checking that the source is
    a finished run kept with its mesh and that its mesh is this one, file by file."""
    if not os.path.isfile(os.path.join(s["startFromDir"], ARGS)):
        raise RunError("-startFrom %s: not a finished curtainCase run (no %s)" % (s["startFromDir"], ARGS))
    t, last = source_time(s["startFromDir"], part, " (run it with -keep)")
    set_entry(os.path.join(part, "constant", "curtainProperties"), "startFields", '{ dir "%s"; }' % t)
    say("warm start from %s (its fields at iteration %g; steady check from iteration %d)"
        % (s["startFromDir"], last, check_from(s)))


def run(children, s, lock_fd, t0):
    part = os.path.join(s["dir"], "case.partial")
    case = os.path.join(s["dir"], "case")
    cells, end, start = prepare(children, s, part, lock_fd)
    say("mesh: %d cells (%s); %d iterations" % (cells, part, s["iterations"]))
    last = None
    if start is not None and stopped_steady(part):
        t = last_time_in_log(os.path.join(part, "log.curtainFoam"))
        if t is not None and abs(float(t) - start) < 1e-9:
            last = int(round(start))   # it had stopped steady there; only the writing was lost
    while last is None:
        gentle = read_stage(part)["stage"] == "gentle"
        try:
            ran = solve(children, s, part, lock_fd, end)
        except Diverged as e:
            if gentle:
                raise
            end = go_gentler(s, part, "diverged (%s)" % e)
            continue
        if ran is not None and stopped_steady(part):
            last = ran
        elif gentle:
            raise RunError("not converged after %s iterations (also with half the Courant numbers): "
                           "%s; last good time on disk: %s; log: %s"
                           % (ran, worst_spread(part), time_or_none(latest_time(part, s["np"])),
                              os.path.join(part, "log.curtainFoam")))
        else:
            end = go_gentler(s, part, "not steady by iteration %s (%s)" % (ran, worst_spread(part)))
    results = window_results(s, part, last)
    edge = dat_header_value(part, "gas0", "alphaEdge")
    text = result_text(s, results, cells, last)
    landing = landing_text(s, part, last)
    prune(s, part)
    atomic_write(os.path.join(part, MANIFEST), json.dumps(sorted(all_files(part) | {MANIFEST})) + "\n")
    user = install_case(part, case)
    wall = time.time() - t0
    atomic_write(os.path.join(s["dir"], RESULT), text)
    atomic_write(os.path.join(s["dir"], LANDING), landing)
    atomic_write(os.path.join(s["dir"], ARGS),
                 json.dumps({"argv": s["argv"], "inputs": signature(s), "iterations": last,
                             "cells": cells, "wall_time_s": round(wall, 1),
                             "alpha_edge": edge}) + "\n")
    for h, mean, vc in results:
        say("fall %g m: bulk drift %.4g m, captured %.3g, V_c/V_g %.3g"
            % (h, mean["drift_bulk"], mean["captured_bulk"], vc))
    if user:
        say("kept %d file(s) of yours in %s: %s" % (len(user), case, ", ".join(user[:5])
                                                   + (" ..." if len(user) > 5 else "")))
    say("converged after %d iterations, %.1f s; wrote %s" % (last, wall, os.path.join(s["dir"], RESULT)))
