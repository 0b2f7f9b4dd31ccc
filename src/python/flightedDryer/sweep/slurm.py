"""slurm: the sweep as one Slurm job array (a task per case still to run) and a
collect step after it (sbatch --dependency=afterany) that writes the table as
the local route does; its status from the queue and the case folders."""

import json
import os
import re
import shutil
import subprocess
import time

from .. import PROJECT
from ..errors import SchedulerError
from ..files import atomic_write
from .localPool import curtain_reason, log_lines
from .plan import case_args, finished, units
from .settings import ARGS, RESULT, SLURM_POLL, say


def slurm_dir(s):
    return os.path.join(s["work"], "slurm")


def task_cases(s, cases):
    """The array's tasks: lists of case indices run in order by one task (plan.units:
    a warm-start chain, or one case a task, the task index the case's)."""
    index = {c["name"]: i for i, c in enumerate(cases)}
    return [[index[c["name"]] for c in unit] for unit in units(s, cases)]


def unit_of(s, cases):
    """{case name: its task's index}."""
    return {c["name"]: u for u, unit in enumerate(units(s, cases)) for c in unit}


def write_slurm(s, cases, todo, np_, sched):
    """The job array (one task per case still to run, or per warm-start chain with
    one), its case and task lists and the collect step. Returns (script, collect,
    case list)."""
    d = slurm_dir(s)
    os.makedirs(d, exist_ok=True)
    lst = os.path.join(d, "cases.txt")
    atomic_write(lst, "".join(" ".join(_quote(a) for a in ["curtainCase"] + case_args(s, c, np_)) + "\n"
                              for c in cases))
    tasks = os.path.join(d, "tasks.txt")
    atomic_write(tasks, "".join(" ".join(str(i + 1) for i in unit) + "\n" for unit in task_cases(s, cases)))
    u = unit_of(s, cases)
    array = array_spec(sorted({u[c["name"]] for c in todo}))
    script = os.path.join(d, "driftTable.sbatch")
    opts = "".join("#SBATCH %s\n" % o for o in sbatch_options(sched))
    text = """#!/bin/bash
# Slurm job array: one curtainCase per task (written by buildDriftTable).
# buildDriftTable -scheduler slurm submits it (with the collect step after it);
# by hand:   sbatch {script}   then, when all tasks are done:   bash {collect}
#SBATCH --job-name=driftTable
#SBATCH --array={array}
#SBATCH --ntasks={np}
#SBATCH --cpus-per-task=1
#SBATCH --output={d}/task_%a.out
{opts}set -uo pipefail
. {project}/etc/bashrc
# the task's cases ({tasks}: line numbers of {lst}), run in order: a warm-start chain
# (each from the one before) or one case
numbers=$(sed -n "$((SLURM_ARRAY_TASK_ID + 1))p" {tasks})
[ -n "$numbers" ] || {{ echo "no case for task $SLURM_ARRAY_TASK_ID in {tasks}" >&2; exit 1; }}
for n in $numbers; do
    line=$(sed -n "${{n}}p" {lst})
    [ -n "$line" ] || {{ echo "no case $n in {lst}" >&2; exit 1; }}
    # a case finished with these inputs (curtainCase -check's signature) is not recomputed
    dir=$(echo "$line" | awk '{{for (i = 1; i < NF; i++) if ($i == "-dir") print $(i+1)}}')
    if [ -f "$dir/{result}" ] && [ -f "$dir/{record}" ]; then
        want=$(eval "$line -check" 2>/dev/null | awk '/^inputs /{{print $2}}')
        have=$({read_record})
        if [ -n "$want" ] && [ "$want" = "$have" ]; then echo "already done: $dir"; continue; fi
    fi
    eval "$line"; rc=$?
    # one retry after a failed run (exit 1); bad input (2) or an interrupt would fail again
    if [ $rc -eq 1 ]; then echo "retrying once"; eval "$line"; rc=$?; fi
    [ $rc -eq 0 ] || exit $rc
done
exit 0
""".format(script=script, collect=os.path.join(d, "collect.sh"), array=array,
           np=np_, d=d, project=PROJECT, lst=lst, tasks=tasks, opts=opts, **finished_record(s))
    atomic_write(script, text)
    collect = os.path.join(d, "collect.sh")
    ctext = """#!/bin/bash
# Collect step after the Slurm array: assemble the drift table from the finished cases.
set -e
. {project}/etc/bashrc
buildDriftTable -dict {dict} -work {work} -out {out} -collect "$@"
""".format(project=PROJECT, dict=s["dict"], work=s["work"], out=s["output"])
    atomic_write(collect, ctext)
    os.chmod(collect, 0o755)
    os.chmod(script, 0o755)
    return script, collect, lst


def finished_record(s):
    """What a task reads to tell a finished case (plan.finished's rule, in the task's shell):
    its result file, the file recording its inputs' signature and the command that prints it."""
    if s["scene"] == "drumSegment":
        # drumSegmentCase writes `inputs SIGNATURE` to .drumSegmentCase of a finished run
        return {"result": "curtains.csv", "record": ".drumSegmentCase",
                "read_record": "awk '/^inputs /{print $2}' \"$dir/.drumSegmentCase\" 2>/dev/null"}
    return {"result": RESULT, "record": ARGS,
            "read_record": "python3 -c 'import json, sys; print(json.load(open(sys.argv[1])).get(\"inputs\", \"\"))' "
                           "\"$dir/%s\" 2>/dev/null" % ARGS}


def array_spec(indices):
    """Slurm's --array list: runs of consecutive indices as ranges (0-3,5,7-8)."""
    parts = []
    for i in indices:
        if parts and parts[-1][1] == i - 1:
            parts[-1][1] = i
        else:
            parts.append([i, i])
    return ",".join("%d" % a if a == b else "%d-%d" % (a, b) for a, b in parts)


def sbatch_options(sched):
    out = []
    for key, opt in (("partition", "--partition"), ("account", "--account"), ("time", "--time")):
        if sched.get(key):
            out.append("%s=%s" % (opt, sched[key]))
    return out + list(sched.get("extra", []))


def sbatch(args):
    r = subprocess.run(["sbatch", "--parsable"] + args, capture_output=True, text=True)
    if r.returncode != 0:
        raise SchedulerError("sbatch %s failed: %s" % (" ".join(args),
                                                       (r.stderr or r.stdout).strip()))
    return r.stdout.strip().split(";")[0]


def queue_states(job):
    """{array task index or None: Slurm state} of a job still in the queue."""
    if not job:
        return {}
    r = subprocess.run(["squeue", "-h", "-r", "-j", str(job), "-o", "%K %T"],
                       capture_output=True, text=True)
    out = {}
    if r.returncode != 0:
        return out          # no longer known: finished
    for line in r.stdout.splitlines():
        parts = line.split()
        if len(parts) == 2:
            out[int(parts[0]) if parts[0].isdigit() else None] = parts[1]
    return out


def read_submission(s):
    try:
        with open(os.path.join(slurm_dir(s), "submission.json")) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def sweep_status(s, cases, sub):
    """Per case: done, running, queued, failed (with a reason) or todo. In a running
    chain the first unfinished case runs and the later ones wait."""
    u = unit_of(s, cases)
    array = queue_states(sub["array"]) if sub else {}
    status = {}
    first = set()    # tasks whose running case is already named
    for c in cases:
        i = u[c["name"]]
        if finished(s, c):
            status[c["name"]] = ("done", "")
        elif i in array:
            st = array[i]
            running = st in ("RUNNING", "COMPLETING") and i not in first
            first.add(i)
            status[c["name"]] = ("running" if running else "queued", st.lower())
        elif sub and i in sub["indices"]:
            status[c["name"]] = ("failed", task_reason(s, i))
        else:
            status[c["name"]] = ("todo", "")
    return status


def task_reason(s, i):
    path = os.path.join(slurm_dir(s), "task_%d.out" % i)
    lines = log_lines(path)
    if lines is None:
        return "no output of its Slurm task (%s)" % path
    for l in reversed(lines):   # Slurm's own word first: cancelled, time limit, node failure
        if "CANCELLED" in l or "DUE TO TIME LIMIT" in l or "NODE_FAIL" in l:
            return re.sub(r"^slurmstepd[^:]*: error: ", "", l).strip("* ")
    return curtain_reason(lines, "task output empty")


def count_status(status):
    n = {k: 0 for k in ("done", "running", "queued", "failed", "todo")}
    for st, _ in status.values():
        n[st] += 1
    return n


def run_slurm(s, cases, todo, np_, sched, opts):
    """Submit the cases still to run as one job array and the collect step after it;
    unless -noWait, follow the array until the collect step has run."""
    for tool in ("sbatch", "squeue"):
        if not shutil.which(tool):
            raise SchedulerError("%s not on PATH: -scheduler slurm needs Slurm's client commands "
                                 "(and SLURM_CONF if the cluster's configuration is not the default)" % tool)
    d = slurm_dir(s)
    if not todo:
        say("every case is finished; collecting the table")
        return None
    script, collect, _ = write_slurm(s, cases, todo, np_, sched)
    array = sbatch(["--chdir=%s" % d, script])
    gather_args = ["--job-name=driftTableCollect", "--dependency=afterany:%s" % array,
                   "--ntasks=1", "--output=%s" % os.path.join(d, "collect.out"), "--chdir=%s" % d]
    gather_args += sbatch_options(dict(sched, extra=[o for o in sched.get("extra", [])
                                                     if not o.startswith("--array")]))
    gather_args += ["--wrap", "bash %s%s" % (collect, " -allowIncomplete" if opts.get("-allowIncomplete")
                                             else "")]
    gather = sbatch(gather_args)
    u = unit_of(s, cases)
    sub = {"array": array, "gather": gather, "dict": s["dict"], "output": s["output"],
           "indices": sorted({u[c["name"]] for c in todo}), "submitted": time.time()}
    atomic_write(os.path.join(d, "submission.json"), json.dumps(sub) + "\n")
    say("submitted %d case(s) as Slurm job array %s%s, collect step %s (after it); follow with "
        "buildDriftTable -status -work %s; cancel with scancel %s %s"
        % (len(todo), array, " (%d warm-start chain(s))" % len(sub["indices"]) if s.get("warmStart") else "",
           gather, s["work"], array, gather))
    if opts.get("-noWait"):
        return sub
    shown = None
    try:
        while True:
            status = sweep_status(s, cases, sub)
            n = count_status(status)
            line = "%d/%d done, %d running, %d queued, %d failed" % (
                n["done"], len(cases), n["running"], n["queued"], n["failed"])
            if line != shown:
                say("slurm: " + line)
                shown = line
            if not queue_states(array) and not queue_states(gather):
                break
            time.sleep(SLURM_POLL)
    except KeyboardInterrupt:
        say("stopped following; the sweep goes on in Slurm (jobs %s, %s): "
            "buildDriftTable -status -work %s" % (array, gather, s["work"]))
        raise
    return sub


def print_status(s, cases):
    sub = read_submission(s)
    status = sweep_status(s, cases, sub)
    for c in cases:
        st, why = status[c["name"]]
        print("%-28s %-8s %s" % (c["name"], st, why))
    n = count_status(status)
    print("%d cases: %d done, %d running, %d queued, %d failed, %d not submitted%s"
          % (len(cases), n["done"], n["running"], n["queued"], n["failed"], n["todo"],
             "" if not sub else "; job array %s, collect step %s%s" % (
                 sub["array"], sub["gather"],
                 " (in the queue)" if queue_states(sub["gather"]) else "")))
    return n


def _quote(a):
    return a if all(ch.isalnum() or ch in "-_.,/=+:" for ch in a) else "'" + a.replace("'", "'\\''") + "'"
