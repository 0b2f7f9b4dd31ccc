"""The bad-input sweep (cases.py): every bad input stops with a clear message
naming the file and the entry (or the option), never a Python traceback or a
crash; a legal value that looks like a unit mix-up runs with a warning naming
the entry. Nothing the case had is changed by a refused run.

Run by ./Alltest (CTest python.badInputSweep): tests/python/run tests/badInput
"""

import os
import subprocess

import pytest

from cases import CASES

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def make(case, where):
    for rel, maker in case.files.items():
        path = os.path.join(where, rel)
        if maker is None:
            os.makedirs(path, exist_ok=True)
            continue
        os.makedirs(os.path.dirname(path), exist_ok=True)
        data = maker(ROOT)
        with open(path, "wb") as f:
            f.write(data if isinstance(data, bytes) else data.encode())


def snapshot(where):
    out = {}
    for d, _, fs in os.walk(where):
        for f in fs:
            p = os.path.join(d, f)
            with open(p, "rb") as fh:
                out[os.path.relpath(p, where)] = fh.read()
    return out


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_bad_input(case, tmp_path):
    make(case, str(tmp_path))
    before = snapshot(str(tmp_path))
    argv = [a.replace("{root}", ROOT) for a in case.argv]
    r = subprocess.run(argv, cwd=str(tmp_path), capture_output=True, timeout=300,
                       env=dict(os.environ, PWD=str(tmp_path), **case.env))
    out = (r.stdout + r.stderr).decode("utf-8", errors="replace")
    assert "Traceback" not in out, out
    assert r.returncode >= 0, "killed by signal %d: %s" % (-r.returncode, out)
    if case.kind == "warning":
        assert r.returncode == 0, out
    else:
        assert r.returncode != 0, "accepted:\n" + out
        after = snapshot(str(tmp_path))
        changed = [k for k in before if after.get(k) != before[k]]
        assert not changed, "a refused run changed %s" % changed
    missing = [n for n in (x.replace("{root}", ROOT) for x in case.needles) if n not in out]
    assert not missing, "the message does not name %s:\n%s" % (missing, out)
