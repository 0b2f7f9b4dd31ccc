"""processes: a tool's solvers and child tools, each in a process group of its
own, stopped as a whole with the tool; one run per folder through a lock.

- Children: the processes a tool started (setpriv --pdeathsig TERM: a child is
  sent SIGTERM when the tool dies, even by SIGKILL; start_new_session: each
  leads its own group, so a stop reaches what it started in turn);
- stop_group: SIGTERM a group, SIGKILL what is left after a grace time;
- acquire_lock: hold a folder's lock for the life of a run (the solver inherits
  the descriptor); a lock held by a tool that is gone is a stale run, whose
  solver group is stopped and the lock taken over;
- interrupts_raise: SIGTERM, SIGHUP and SIGINT become KeyboardInterrupt.
"""

import fcntl
import json
import os
import signal
import subprocess
import threading
import time

from .errors import Busy


def _signal_reaches(kill, target):
    """Would a signal reach the target (signal 0: nothing is sent)?"""
    try:
        kill(target, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True         # there, but another user's
    return True


def pid_alive(pid):
    """Is there a process of that id (ours or another user's)?"""
    return _signal_reaches(os.kill, pid)


def group_alive(pgid):
    """Is any process of that process group left?"""
    return _signal_reaches(os.killpg, pgid)


def stop_group(pgid, wait=10, child=None):
    """SIGTERM a process group, then SIGKILL what is left after `wait` seconds.
    `child`: the group leader if it is our own child (reaped here)."""
    for sig, limit in ((signal.SIGTERM, wait), (signal.SIGKILL, 5)):
        try:
            os.killpg(pgid, sig)
        except ProcessLookupError:
            return
        t0 = time.time()
        while time.time() - t0 < limit:
            if child is not None:
                child.poll()           # a finished child is reaped, not left a zombie
            if not group_alive(pgid):
                return
            time.sleep(0.05)


class Children:
    """The processes a tool started, each the leader of its own group (thread-safe)."""

    def __init__(self):
        self._lock = threading.Lock()
        self._running = []

    def spawn(self, cmd, out, cwd=None, pass_fds=()):
        """Start cmd with its output to `out`, in its own process group, sent
        SIGTERM if this tool dies; registered until done() or stop_all()."""
        p = subprocess.Popen(["setpriv", "--pdeathsig", "TERM", "--"] + cmd, cwd=cwd, stdout=out,
                             stderr=subprocess.STDOUT, start_new_session=True, pass_fds=pass_fds)
        with self._lock:
            self._running.append(p)
        return p

    def call(self, cmd, out=None, cwd=None):
        """spawn() and wait; the exit status. Interrupted while waiting, the child
        stays registered for stop_all()."""
        p = self.spawn(cmd, out, cwd=cwd)
        rc = p.wait()
        self.done(p)
        return rc

    def done(self, p):
        with self._lock:
            if p in self._running:
                self._running.remove(p)

    def running(self):
        with self._lock:
            return list(self._running)

    def stop_all(self):
        """Stop every registered group (SIGTERM, then SIGKILL) and forget it."""
        for p in self.running():
            stop_group(p.pid, child=p)
            self.done(p)

    def terminate_all(self, wait=30):
        """SIGTERM every registered group (each stops its own children), then
        SIGKILL a group that has not ended after `wait` seconds."""
        procs = self.running()
        for p in procs:
            if p.poll() is None:
                try:
                    os.killpg(p.pid, signal.SIGTERM)
                except ProcessLookupError:
                    pass
        for p in procs:
            try:
                p.wait(wait)
            except subprocess.TimeoutExpired:
                try:
                    os.killpg(p.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass


def run_tied(cmd, **kwargs):
    """subprocess.run of cmd, the child sent SIGTERM should this tool die (even by
    SIGKILL): a short child left behind cannot outlive its caller."""
    return subprocess.run(["setpriv", "--pdeathsig", "TERM", "--"] + list(cmd), **kwargs)


def interrupts_raise():
    """SIGTERM, SIGHUP and SIGINT raise KeyboardInterrupt in the main thread."""
    def on_signal(signum, frame):
        raise KeyboardInterrupt
    for sig in (signal.SIGTERM, signal.SIGHUP, signal.SIGINT):
        signal.signal(sig, on_signal)


def _runs_tool(pid, tool):
    try:
        with open("/proc/%d/cmdline" % pid, "rb") as f:
            return tool.encode() in f.read()
    except OSError:
        return False


def write_lock_info(fd, info):
    """Record the run holding a lock (its pid and its solver's group) in the lock file."""
    os.lseek(fd, 0, os.SEEK_SET)
    os.ftruncate(fd, 0)
    os.write(fd, (json.dumps(info) + "\n").encode())


def acquire_lock(folder, name, tool, wait, say):
    """Hold folder/name for the life of this run (and of its solver, which inherits
    the descriptor). A lock held by a `tool` process that is alive waits up to
    `wait` seconds, then Busy; a lock held by anything else is a stale run of a
    killed `tool`: its solver's process group is stopped and the lock taken over."""
    path = os.path.join(folder, name)
    fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
    t0 = time.time()
    while True:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            write_lock_info(fd, {"pid": os.getpid(), "pgid": None})
            return fd
        except BlockingIOError:
            pass
        try:
            info = json.loads(os.pread(fd, 4096, 0).decode() or "{}")
        except ValueError:
            info = {}
        owner = info.get("pid")
        if not (isinstance(owner, int) and pid_alive(owner) and _runs_tool(owner, tool)):
            break
        # a run that is stopping (its caller was killed) lets go within seconds
        if time.time() - t0 > wait:
            os.close(fd)
            raise Busy("%s is in use by %s (pid %d): one run per folder; wait for it, "
                       "or stop it (kill %d)" % (folder, tool, owner, owner))
        time.sleep(0.2)
    # the lock is held, but not by a live run of the tool: a stale run (the tool
    # was killed); stop what is left of its solver and take the lock over
    pgid = info.get("pgid")
    say("stale run in %s (%s pid %s is gone); stopping its solver (process group %s)"
        % (folder, tool, owner, pgid))
    if isinstance(pgid, int):
        stop_group(pgid)
    t0 = time.time()
    while True:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            break
        except BlockingIOError:
            if time.time() - t0 > 30:
                os.close(fd)
                raise Busy("%s: the lock of a stale run is still held after 30 s "
                           "(see fuser %s)" % (folder, path))
            time.sleep(0.2)
    write_lock_info(fd, {"pid": os.getpid(), "pgid": None})
    return fd
