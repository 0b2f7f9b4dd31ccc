"""localPool: the sweep's runs on this machine, -jobs at a time (threads, each
waiting on one curtainCase in its own process group), each tried twice unless
its failure would repeat; every case is checked with curtainCase -check first."""

import os
import re
import subprocess
import threading
import time

from ..errors import InputError
from ..processes import Children
from .plan import case_args, case_log, finished, units
from .settings import case_option_entries, say


def check_cases(s, cases, np_):
    """curtainCase -check on every case: a bad level, drag, fall height or spill
    rate stops the sweep before anything runs (exit 2)."""
    for c in cases:
        r = subprocess.run(["curtainCase"] + case_args(s, c, np_) + ["-check"],
                           capture_output=True, text=True)
        if r.returncode != 0:
            lines = [l for l in (r.stderr + r.stdout).splitlines() if l.strip()]
            why = lines[-1].replace("curtainCase: ", "") if lines else "exit %d" % r.returncode
            # the sweep dictionary's entry behind the curtainCase option the check names
            named = [entry for entry, opt in case_option_entries() if re.search(r"(^|\s)%s\b" % opt, why)]
            raise InputError("%s: case %s%s: %s" % (s["dict"], c["name"],
                                                   " (entry %s)" % named[0] if named else "", why))
        # the inputs' signature (settings and template content): a finished case made
        # with another template or curtainCase settings is not taken as finished
        for line in r.stdout.splitlines():
            if line.startswith("inputs "):
                c["inputs"] = line.split()[1]


class Sweep:
    """The runs on this machine, -jobs at a time, each tried twice unless its
    failure would repeat (bad input, a run unsteady to its end)."""

    def __init__(self, s, cases, jobs, np_):
        self.s, self.cases, self.jobs, self.np = s, cases, jobs, np_
        self.lock = threading.Lock()
        self.children = Children()
        self.stopping = False
        self.failed = {}
        self.done_times = []
        self.t0 = time.time()

    def run_case(self, c):
        log = case_log(self.s, c)
        os.makedirs(os.path.dirname(log), exist_ok=True)
        for attempt in (1, 2):
            if self.stopping:
                return False
            t = time.time()
            with open(log, "a") as f:
                f.write("=== attempt %d: curtainCase %s\n" % (attempt, " ".join(case_args(self.s, c, self.np))))
                f.flush()
                # own process group (stopped as a whole); SIGTERM if this tool dies
                p = self.children.spawn(["curtainCase"] + case_args(self.s, c, self.np), f)
                rc = p.wait()
                self.children.done(p)
            if self.stopping:
                return False
            if rc == 0 and finished(self.s, c):
                with self.lock:
                    self.done_times.append(time.time() - t)
                return True
            reason = tail_reason(log)
            # a retry cannot change bad input or a run that ran to its end unsteady
            deterministic = rc == 2 or "not converged" in reason
            if attempt == 1 and not deterministic:
                say("case %s failed (%s); retrying once" % (c["name"], reason))
            else:
                with self.lock:
                    self.failed[c["name"]] = reason
                say("case %s FAILED%s: %s (log %s)"
                    % (c["name"], " (not retried: it would fail again)" if deterministic and attempt == 1
                       else " twice", reason, log))
                break
        return False

    def progress(self, n_done, n_todo):
        el = time.time() - self.t0
        with self.lock:
            mean = sum(self.done_times) / len(self.done_times) if self.done_times else None
        left = n_todo - n_done
        eta = "?" if mean is None else "%.0f s" % (mean * left / max(1, min(self.jobs, left or 1)))
        return "%d/%d cases done this run, %.0f s elapsed, about %s left" % (n_done, n_todo, el, eta)

    def run_chain(self, chain, finished_cases):
        """The cases of one unit in order (a warm-start chain: each from the one before;
        otherwise a single case); the rest of a chain is not run once one fails."""
        for k, c in enumerate(chain):
            say("starting %s%s" % (c["name"], " (from %s)" % c["parent"] if c.get("parent") else ""))
            c["ok"] = self.run_case(c)
            finished_cases.append(c)
            if not c["ok"]:
                for later in chain[k + 1:]:
                    if not self.stopping:
                        with self.lock:
                            self.failed[later["name"]] = "not run: its warm start's source %s failed" % c["name"]
                    later["ok"] = False
                    finished_cases.append(later)
                return

    def run(self, todo):
        names = {c["name"] for c in todo}
        queue = [u for u in ([c for c in unit if c["name"] in names] for unit in units(self.s, self.cases)) if u]
        active = []
        ended = []
        n_done = 0
        while queue or active:
            while queue and len(active) < self.jobs and not self.stopping:
                unit = queue.pop(0)
                th = threading.Thread(target=lambda u=unit: self.run_chain(u, ended))
                th.start()
                active.append(th)
            time.sleep(0.5)
            active = [th for th in active if th.is_alive()]
            while ended:    # (after the threads that ended: what they reported is all here)
                c = ended.pop(0)
                n_done += 1
                say("%s %s; %s" % (c["name"], "done" if c.get("ok") else
                                   ("stopped" if self.stopping else "failed"), self.progress(n_done, len(todo))))
            if self.stopping and not active:
                break

    def stop(self):
        self.stopping = True
        self.children.terminate_all()   # each curtainCase stops its solver


def log_lines(path):
    """The non-empty lines of a log, None if it cannot be read."""
    try:
        with open(path, errors="replace") as f:
            return [l.strip() for l in f if l.strip()]
    except OSError:
        return None


def curtain_reason(lines, empty):
    """curtainCase's last word in a log: its bad-input, FAILED or interrupted line
    (or drumSegmentCase's: its lines name it)."""
    for l in reversed(lines):
        if l.startswith("curtainCase: bad input") or l.startswith("curtainCase: FAILED") \
                or "interrupted" in l:
            return l[len("curtainCase: "):] if l.startswith("curtainCase: ") else l
        if l.startswith("drumSegmentCase: ") and not l.startswith("drumSegmentCase: inputs"):
            return l
    return lines[-1] if lines else empty


def tail_reason(log):
    lines = log_lines(log)
    return "no log" if lines is None else curtain_reason(lines, "no output")
