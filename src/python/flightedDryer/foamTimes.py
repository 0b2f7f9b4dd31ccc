"""foamTimes: the time folders of a case, and which of them is a whole restart point.

OpenFOAM writes a time folder file by file; a kill or a full disk can leave one
in part (uniform/time may be there before the fields). A time counts only when
curtainFoam marked it whole after closing every field (uniform/curtainFoam.written)
and no file of it is cut short (each OpenFOAM file ends with its divider).
"""

import os
import shutil

FOAM_FILE_END = b"// ************************************************************************* //"
WRITTEN_MARK = os.path.join("uniform", "curtainFoam.written")   # curtainFoam: this time is whole


def times(root):
    """(value, folder name) of the time folders of root, in order."""
    out = []
    for d in os.listdir(root):
        try:
            t = float(d)
        except ValueError:
            continue
        if os.path.isdir(os.path.join(root, d)):
            out.append((t, d))
    return sorted(out)


def whole(path):
    """An OpenFOAM file written to its end: OpenFOAM closes every file it writes
    (ascii or binary) with its end divider, so a file cut short by a kill or a
    full disk lacks it."""
    try:
        with open(path, "rb") as f:
            f.seek(0, os.SEEK_END)
            n = f.tell()
            f.seek(max(0, n - 2 * len(FOAM_FILE_END)))
            return f.read().rstrip().endswith(FOAM_FILE_END)
    except OSError:
        return False


def time_complete(root, d):
    """Is time folder root/d a whole restart point: marked by curtainFoam after it
    wrote and closed every field of that time (WRITTEN_MARK), and no file of it cut
    short (the end divider of every OpenFOAM file)?"""
    t = os.path.join(root, d)
    if not os.path.isfile(os.path.join(t, WRITTEN_MARK)):
        return False
    for dirpath, _, files in os.walk(t):
        for f in files:
            p = os.path.join(dirpath, f)
            if p != os.path.join(t, WRITTEN_MARK) and not whole(p):
                return False
    return True


def roots(case, np_):
    """Where a case's time folders are: the case, or its processor folders."""
    return [case] if np_ == 1 else [os.path.join(case, "processor%d" % i) for i in range(np_)]


def latest_time(case, np_):
    """Latest written time (> 0) complete on every processor (time_complete), None
    if none."""
    common = None
    for root in roots(case, np_):
        if not os.path.isdir(root):
            return None
        ts = {t for t, d in times(root) if t > 0 and time_complete(root, d)}
        common = ts if common is None else common & ts
    return max(common) if common else None


def drop_times_after(case, np_, start):
    """Remove the time folders later than `start` (written in part when the run was
    stopped): the solver starts from the latest time on disk (startFrom latestTime),
    which must be the complete one. Returns the names removed."""
    gone = []
    for root in roots(case, np_):
        for t, d in times(root):
            if t > (start or 0) + 1e-9:
                shutil.rmtree(os.path.join(root, d))
                gone.append(os.path.relpath(os.path.join(root, d), case))
    return gone


def last_time_in_log(path):
    """The last 'Time = ' a solver log shows, as text; None if none."""
    last = None
    try:
        with open(path, errors="replace") as f:
            for line in f:
                if line.startswith("Time = "):
                    last = line.split("=", 1)[1].strip()
    except OSError:
        pass
    return last
