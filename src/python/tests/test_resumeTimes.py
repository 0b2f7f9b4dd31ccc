"""curtainCase resumes only from a time folder curtainFoam marked whole, with no
file cut short; later (partial) times are removed before the rerun."""

import importlib.machinery
import importlib.util
import os

import pytest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
END = b"\n\n// ************************************************************************* //\n"


@pytest.fixture(scope="module")
def cc():
    path = os.path.join(ROOT, "applications", "utilities", "curtainCase", "curtainCase")
    loader = importlib.machinery.SourceFileLoader("curtainCase", path)
    spec = importlib.util.spec_from_loader("curtainCase", loader)
    mod = importlib.util.module_from_spec(spec)
    loader.exec_module(mod)
    return mod


def write_time(root, t, mark=True, cut=None, drop=None):
    d = os.path.join(root, t)
    os.makedirs(os.path.join(d, "uniform"))
    for f in ("U.air", "p_rgh", "alpha.c0", os.path.join("uniform", "time")):
        if f == drop:
            continue
        with open(os.path.join(d, f), "wb") as fh:
            body = b"FoamFile {}\n" + b"\x00\x01" * 100
            fh.write(body if f == cut else body + END)
    if mark:
        with open(os.path.join(d, cc_mark()), "w") as fh:
            fh.write(t + "\n")


def cc_mark():
    return os.path.join("uniform", "curtainFoam.written")


def test_only_marked_whole_times_count(cc, tmp_path):
    case = str(tmp_path)
    os.makedirs(os.path.join(case, "0"))
    s = {"np": 1}
    assert cc.latest_time(s, case) is None
    write_time(case, "50")
    write_time(case, "100", mark=False, drop="U.air")     # a kill inside the write
    assert cc.latest_time(s, case) == 50
    write_time(case, "150", cut="U.air")                   # marked, a field cut short
    assert cc.latest_time(s, case) == 50
    assert sorted(cc.drop_times_after(s, case, 50)) == ["100", "150"]
    assert sorted(os.listdir(case)) == ["0", "50"]


def test_parallel_needs_every_processor(cc, tmp_path):
    case = str(tmp_path)
    s = {"np": 2}
    for p in ("processor0", "processor1"):
        os.makedirs(os.path.join(case, p, "0"))
        write_time(os.path.join(case, p), "50")
    write_time(os.path.join(case, "processor0"), "100")
    write_time(os.path.join(case, "processor1"), "100", mark=False)
    assert cc.latest_time(s, case) == 50
