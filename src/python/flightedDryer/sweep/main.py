"""main: buildDriftTable's main: the options and the dictionary read, every case
checked, then the sweep run locally (a pool of -jobs) or through Slurm, resumed
where it stopped, and the table written from the finished runs."""

import json
import os
import re
import shlex
import signal
import sys
import threading
import time

from .. import PROJECT, foamDictionary, options
from ..errors import InputError, SchedulerError
from ..files import WriteError, atomic_write
from .dictionary import read_sweep
from .localPool import Sweep, check_cases, tail_reason
from .plan import case_log, cases_of, finished, grid_key, read_result, run_axes, units
from .settings import say
from .slurm import print_status, read_submission, run_slurm, slurm_dir, task_reason, unit_of, write_slurm
from .table import write_table


FLAGS = {"-allowIncomplete", "-slurm", "-collect", "-list", "-status", "-noWait"}
VALUED = {"-dict", "-jobs", "-np", "-work", "-out", "-scheduler", "-partition", "-account",
          "-time", "-sbatchOptions"}


def parse(argv, usage):
    """buildDriftTable's options, each given once and checked."""
    opts = dict({"-jobs": "1", "-np": "1", "-scheduler": "local"},
                **options.parse(argv, FLAGS, VALUED, (), "buildDriftTable", usage))
    if "-dict" not in opts and not ("-status" in opts and "-work" in opts):
        raise InputError("missing -dict FILE (or -status -work DIR)")
    for k in ("-jobs", "-np"):
        if not opts[k].isdigit() or not 1 <= int(opts[k]) <= 256:
            raise InputError("%s = '%s' outside the allowed range [1, 256] (whole number)" % (k, opts[k]))
    check_scheduler(opts)
    return opts


SCHEDULER_OPTIONS = ("-scheduler", "-partition", "-account", "-time", "-sbatchOptions")


def check_scheduler(opts):
    """The scheduler's options (-scheduler, and Slurm's -partition, -account, -time,
    -sbatchOptions, -noWait) checked; opts["sbatchExtra"] set. dryerStudy checks
    its own with it before planning."""
    opts.setdefault("-scheduler", "local")
    if opts["-scheduler"] not in ("local", "slurm"):
        raise InputError("-scheduler '%s' is not one of local slurm" % opts["-scheduler"])
    for k in ("-partition", "-account", "-time", "-sbatchOptions", "-noWait"):
        if k in opts and opts["-scheduler"] != "slurm" and not opts.get("-slurm"):
            raise InputError("%s is an option of -scheduler slurm" % k)
    if "-time" in opts and not re.fullmatch(r"(\d+-)?\d+(:\d{1,2}){0,2}", opts["-time"]):
        raise InputError("-time '%s' is not a Slurm time limit (minutes, HH:MM:SS or D-HH:MM:SS)"
                        % opts["-time"])
    try:
        opts["sbatchExtra"] = shlex.split(opts.get("-sbatchOptions", ""))
    except ValueError as e:
        raise InputError("-sbatchOptions: %s" % e)
    for o in opts["sbatchExtra"]:
        if not o.startswith("--") or o.split("=")[0] in ("--array", "--output", "--dependency",
                                                         "--parsable", "--wrap"):
            raise InputError("-sbatchOptions: '%s': give long options (--name=value) other than "
                            "--array, --output, --dependency, --wrap, which buildDriftTable sets" % o)


def main(argv, usage):
    try:
        return run_main(argv, usage)
    except (InputError, foamDictionary.FoamDictionaryError) as e:
        print("buildDriftTable: error: %s" % e, file=sys.stderr)
        return 2
    except WriteError as e:
        print("buildDriftTable: FAILED: %s" % e, file=sys.stderr)
        return 1


def run_main(argv, usage):
    opts = parse(argv, usage)
    if "-dict" not in opts:
        # -status -work DIR: the dictionary of the last submission
        sub = read_submission({"work": os.path.abspath(opts["-work"])})
        if not sub:
            raise InputError("-status -work %s: no Slurm submission there (give -dict FILE)" % opts["-work"])
        opts["-dict"] = sub["dict"]
        opts.setdefault("-out", sub["output"])
    s = read_sweep(opts["-dict"])
    if "-work" in opts:
        s["work"] = os.path.abspath(opts["-work"])
    if "-out" in opts:
        s["output"] = os.path.abspath(opts["-out"])
    for what, path in (("-work", s["work"]), ("-out", os.path.dirname(s["output"]))):
        if os.path.exists(path) and not os.path.isdir(path):
            raise InputError("%s %s is a file, not a folder" % (what, path))
    if os.path.isdir(s["output"]):
        raise InputError("-out %s is a folder, not a file" % s["output"])
    jobs, np_ = int(opts["-jobs"]), int(opts["-np"])
    if s["scene"] == "drumSegment" and opts.get("-allowIncomplete"):
        raise InputError("-allowIncomplete is not available for scene drumSegment (a segment table "
                         "is written whole)")
    if s.get("warmStart") and np_ > 1:
        raise InputError("%s: entry 'warmStart yes' needs -np 1 (a run reads its neighbour's fields onto "
                         "the whole mesh)" % s["dict"])
    cases = cases_of(s)
    if opts.get("-status"):
        n = print_status(s, cases)
        return 0 if n["failed"] == 0 else 1
    if not opts.get("-list") or s["scene"] == "drumSegment":
        # (a drum segment's check is quick, and its inputs' signature is what tells
        # a finished run from a stale one)
        check_cases(s, cases, np_)
    try:
        os.makedirs(s["work"], exist_ok=True)
    except OSError as e:
        raise WriteError("cannot make the work folder %s: %s" % (s["work"], e.strerror))
    if opts.get("-list"):
        for c in cases:
            print(c["name"], "done" if finished(s, c) else "todo")
        if s["scene"] != "drumSegment":
            say("%d cases listed; their curtainCase inputs (level, drag, fall heights against the "
                "mesh) were not checked (-list skips that check; the sweep makes it first)" % len(cases))
        return 0
    sched = {"partition": opts.get("-partition"), "account": opts.get("-account"),
             "time": opts.get("-time", "01:00:00"), "extra": opts["sbatchExtra"]}
    if opts.get("-slurm"):
        # every case: the tasks skip the ones finished when they run
        script, collect, lst = write_slurm(s, cases, cases, np_, sched)
        say("wrote %s (array of %d tasks), %s and %s; nothing run" % (script, len(units(s, cases)), lst, collect))
        return 0

    state_path = os.path.join(s["work"], "sweep.json")
    state = {}
    if os.path.exists(state_path):
        try:
            with open(state_path) as f:
                state = json.load(f)
        except ValueError:
            state = {}
    # the sweep's wall time adds up over resumed runs of the same grid; another
    # grid (or other case settings) starts the count again
    key = grid_key(cases)
    if state.get("grid") != key:
        state = {"grid": key}
    elapsed_before = float(state.get("elapsed_s", 0))

    done = [c for c in cases if finished(s, c)]
    todo = [c for c in cases if not finished(s, c)]
    say("%s: %d cases (%s), %d finished in %s, %d to run; %d at once, %d MPI each"
        % (os.path.relpath(s["dict"], PROJECT), len(cases),
           " x ".join(["%d %s" % (len(s["grid"][a]), a) for a in run_axes(s)]
                      + (["%d floors" % len(s["floors"])] if len(s.get("floors", [])) > 1 else [])),
           len(done), s["work"],
           0 if opts.get("-collect") else len(todo), jobs, np_))
    if opts["-scheduler"] == "slurm" and not opts.get("-collect"):
        try:
            sub = run_slurm(s, cases, todo, np_, sched, opts)
        except SchedulerError as e:
            print("buildDriftTable: FAILED: %s" % e, file=sys.stderr)
            return 1
        except KeyboardInterrupt:
            return 130
        if sub is not None:
            if opts.get("-noWait"):
                return 0
            # the collect step has run: it wrote the table, or said why not
            n = print_status(s, cases)
            fresh = os.path.exists(s["output"]) and os.path.getmtime(s["output"]) >= sub["submitted"]
            if n["done"] == len(cases) and fresh:
                say("wrote %s (collect step %s, %s)" % (s["output"], sub["gather"],
                                                        os.path.join(slurm_dir(s), "collect.out")))
                return 0
            say("table NOT written%s; rerun the same command to run the failed cases again"
                % (" (written without the missing cases: -allowIncomplete)" if fresh else ""))
            return 0 if fresh and opts.get("-allowIncomplete") else 1
    sweep = Sweep(s, cases, jobs, np_)
    t0 = time.time()

    def on_signal(signum, frame):
        if not sweep.stopping:
            say("interrupted: stopping the running cases (finished cases are kept; rerun to resume)")
            threading.Thread(target=sweep.stop).start()

    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        signal.signal(sig, on_signal)

    if not opts.get("-collect") and todo:
        sweep.run(todo)
        state["elapsed_s"] = elapsed_before + (time.time() - t0)
        atomic_write(state_path, json.dumps(state))
    elif not opts.get("-collect"):
        state["elapsed_s"] = elapsed_before
    if sweep.stopping:
        say("interrupted; table not written")
        return 1

    ok = {c["name"] for c in cases if finished(s, c)}
    failed = dict(sweep.failed)
    sub = read_submission(s)
    index = unit_of(s, cases)
    for c in cases:   # failures of earlier runs of the sweep, from the case logs or Slurm tasks
        log = case_log(s, c)
        if c["name"] in ok or c["name"] in failed:
            continue
        if sub and index[c["name"]] in sub["indices"]:
            failed[c["name"]] = task_reason(s, index[c["name"]])
        elif os.path.exists(log):
            failed[c["name"]] = tail_reason(log)
    missing = [c["name"] for c in cases if c["name"] not in ok]
    if opts.get("-collect") and "elapsed_s" not in state:
        # elapsed: the cases' own wall times (a cluster's sweep time is not known here;
        # a drum segment records none)
        elapsed = 0.0
        for c in cases:
            if c["name"] in ok and s["scene"] == "box":
                elapsed += read_result(s, c)[2]
    else:
        elapsed = state["elapsed_s"]
    if not ok:
        say("no case finished; table NOT written")
        return 1
    if missing and not opts.get("-allowIncomplete"):
        for n in missing:
            say("missing case %s: %s" % (n, failed.get(n, "not run")))
        say("%d of %d cases failed or missing; table NOT written (rerun to retry them, or "
            "-allowIncomplete to write the grid without them)" % (len(missing), len(cases)))
        return 1
    try:
        n = write_table(s, cases, ok, failed, elapsed, s["output"])
    except InputError as e:
        print("buildDriftTable: FAILED: %s" % e, file=sys.stderr)
        return 1
    say("wrote %s: %d rows, %d cases (%d missing), sweep %.0f s"
        % (s["output"], n, len(cases), len(missing), elapsed))
    return 0
