"""processes: a child group is stopped as a whole; a folder's lock is held by one
live run, a stale lock (its holder gone) is taken over and its solver group
stopped; a termination signal becomes KeyboardInterrupt."""

import os
import signal
import subprocess
import sys
import time

import pytest

from flightedDryer import processes as pr
from flightedDryer.errors import Busy

# a run holding a folder's lock: python with 'fakeTool' on its command line, and
# its solver (its own process group) which inherits the lock's descriptor
HOLD = ("import fcntl, json, os, subprocess, sys, time\n"
        "fd = os.open(sys.argv[1], os.O_RDWR | os.O_CREAT)\n"
        "fcntl.flock(fd, fcntl.LOCK_EX)\n"
        "solver = subprocess.Popen(['sleep', '60'], start_new_session=True, pass_fds=(fd,))\n"
        "os.write(fd, (json.dumps({'pid': os.getpid(), 'pgid': solver.pid}) + '\\n').encode())\n"
        "print(solver.pid, flush=True)\n"
        "time.sleep(60)\n")


def hold(path, tool="fakeTool"):
    """(the run, its solver's pid)"""
    p = subprocess.Popen([sys.executable, "-c", HOLD, path, tool], stdout=subprocess.PIPE, text=True)
    return p, int(p.stdout.readline())


def test_children_are_stopped_as_a_group(tmp_path):
    kids = pr.Children()
    with open(tmp_path / "log", "w") as out:
        p = kids.spawn(["bash", "-c", "sleep 60 & sleep 60"], out)
    time.sleep(0.3)
    assert pr.group_alive(p.pid)
    kids.stop_all()
    assert not pr.group_alive(p.pid) and kids.running() == []


def test_a_live_run_holds_the_folder(tmp_path):
    h, solver = hold(str(tmp_path / ".lock"))
    try:
        t0 = time.time()
        with pytest.raises(Busy, match=r"is in use by fakeTool \(pid %d\): one run per folder" % h.pid):
            pr.acquire_lock(str(tmp_path), ".lock", "fakeTool", 0.5, print)
        assert time.time() - t0 >= 0.5
    finally:
        h.kill()
        h.wait()
        pr.stop_group(solver)


def test_a_stale_lock_is_taken_over_and_its_solver_stopped(tmp_path):
    h, solver = hold(str(tmp_path / ".lock"))
    h.kill()              # the run is killed; its solver (own group) keeps the lock
    h.wait()
    assert pr.group_alive(solver)
    said = []
    t0 = time.time()
    fd = pr.acquire_lock(str(tmp_path), ".lock", "fakeTool", 5, said.append)
    os.close(fd)
    assert time.time() - t0 < 5                # not waited for: the run is gone
    assert not pr.group_alive(solver)
    assert said and "stale run in %s (fakeTool pid %d is gone)" % (tmp_path, h.pid) in said[0]


def test_termination_signals_raise_keyboard_interrupt():
    old = {s: signal.getsignal(s) for s in (signal.SIGTERM, signal.SIGHUP, signal.SIGINT)}
    try:
        pr.interrupts_raise()
        with pytest.raises(KeyboardInterrupt):
            os.kill(os.getpid(), signal.SIGTERM)
            time.sleep(1)
    finally:
        for s, h in old.items():
            signal.signal(s, h)
