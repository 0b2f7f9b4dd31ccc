"""A run resumes only from a time folder curtainFoam marked whole, with no file
cut short; later (partial) times are removed before the rerun (foamTimes)."""

import os

from flightedDryer import foamTimes as ft

END = b"\n\n// ************************************************************************* //\n"


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
    return ft.WRITTEN_MARK


def test_only_marked_whole_times_count(tmp_path):
    case = str(tmp_path)
    os.makedirs(os.path.join(case, "0"))
    assert ft.latest_time(case, 1) is None
    write_time(case, "50")
    write_time(case, "100", mark=False, drop="U.air")     # a kill inside the write
    assert ft.latest_time(case, 1) == 50
    write_time(case, "150", cut="U.air")                   # marked, a field cut short
    assert ft.latest_time(case, 1) == 50
    assert sorted(ft.drop_times_after(case, 1, 50)) == ["100", "150"]
    assert sorted(os.listdir(case)) == ["0", "50"]


def test_parallel_needs_every_processor(tmp_path):
    case = str(tmp_path)
    for p in ("processor0", "processor1"):
        os.makedirs(os.path.join(case, p, "0"))
        write_time(os.path.join(case, p), "50")
    write_time(os.path.join(case, "processor0"), "100")
    write_time(os.path.join(case, "processor1"), "100", mark=False)
    assert ft.latest_time(case, 2) == 50
