"""warmStart: what curtainCase -startFrom and drumSegmentCase -startFrom share: the
source run's last whole time folder, after checking that its mesh is the new run's,
file by file (curtainFoam reads that folder's internal fields at time 0:
constant/curtainProperties startFields)."""

import os

from .errors import RunError
from .foamTimes import latest_time, times

MESH_FILES = ("points", "faces", "owner", "neighbour", "boundary")


def source_time(source, case, kept_hint=""):
    """The last whole time folder of the finished run in `source` (its case/), whose
    mesh must be the one of `case`; RunError naming the cause otherwise."""
    src = os.path.join(source, "case")
    last = latest_time(src, 1) if os.path.isdir(src) else None
    if not last or not os.path.isdir(os.path.join(src, "constant", "polyMesh")):
        raise RunError("-startFrom %s: no fields and mesh kept%s" % (source, kept_hint))
    for f in MESH_FILES:
        a, b = (os.path.join(c, "constant", "polyMesh", f) for c in (src, case))
        with open(a, "rb") as fa, open(b, "rb") as fb:
            if fa.read() != fb.read():
                raise RunError("-startFrom %s: its mesh is not this run's (constant/polyMesh/%s differs): a warm "
                               "start needs the same mesh" % (source, f))
    return os.path.join(src, next(d for v, d in times(src) if v == last)), last
