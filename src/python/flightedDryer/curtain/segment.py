"""segment: curtainCase -scene drumSegment: every releasing flight's curtain in the
drum's own cross-section, run by drumSegmentCase under curtainCase's option names."""

import os
import shutil
import sys

from ..errors import InputError


# the drum-segment scene: curtainCase's options and drumSegmentCase's (which runs it)
SEGMENT_OPTIONS = {"-dir": "-out", "-flights": "-dict", "-gasVelocity": "-gasVelocity",
                   "-reposeAngle": "-reposeAngle", "-level": "-level", "-np": "-np",
                   "-iterations": "-steps", "-ends": "-ends", "-segmentLength": "-length",
                   "-template": "-template", "-release": "-release", "-drag": "-drag",
                   "-stop": "-stop", "-density": "-density", "-gasTemperature": "-gasTemperature",
                   "-gasPressure": "-gasPressure", "-diameters": "-diameter", "-startFrom": "-startFrom"}
BOX_ONLY = {"-spillRate": "every flight's spill rate comes from the flight model (mesh/flights.csv)",
            "-fallHeight": "every flight's fall height comes from the flight model (mesh/flights.csv)",
            "-heights": "each curtain falls to the bed, measured where it lands",
            "-flightLength": "the flights span the segment (-segmentLength)",
            "-fractions": "one particle size (-diameters, a single value) for every curtain"}


def scene_of(argv):
    """The scene (-scene box|drumSegment, default box) and the other arguments."""
    if "-scene" not in argv:
        return "box", argv
    if argv.count("-scene") > 1:
        raise InputError("option -scene given twice: give it once")
    i = argv.index("-scene")
    if i + 1 >= len(argv):
        raise InputError("option -scene needs a value (box or drumSegment)")
    scene = argv[i + 1]
    if scene not in ("box", "drumSegment"):
        raise InputError("-scene '%s' is not one of box drumSegment" % scene)
    return scene, argv[:i] + argv[i + 2:]


def drum_segment(argv):
    """-scene drumSegment: every releasing flight's curtain in the drum's own
    cross-section, run by drumSegmentCase (which this process becomes)."""
    out = ["drumSegmentCase"]
    i = 0
    for a in set(argv):
        if (a in SEGMENT_OPTIONS or a == "-check") and argv.count(a) > 1:
            raise InputError("option %s given twice: give it once" % a)
    while i < len(argv):
        a = argv[i]
        if a == "-check":
            out.append(a)
            i += 1
        elif a in SEGMENT_OPTIONS:
            if i + 1 >= len(argv):
                raise InputError("option %s needs a value" % a)
            if a == "-diameters" and len(argv[i + 1].split(",")) != 1:
                raise InputError("-diameters '%s': -scene drumSegment takes one diameter (every curtain's)"
                                 % argv[i + 1])
            out += [SEGMENT_OPTIONS[a], argv[i + 1]]
            i += 2
        elif a in BOX_ONLY:
            raise InputError("option %s belongs to -scene box: in a drum segment %s" % (a, BOX_ONLY[a]))
        else:
            raise InputError("unknown option '%s' for -scene drumSegment (allowed: %s -check)"
                             % (a, " ".join(sorted(SEGMENT_OPTIONS))))
    for req in ("-dir", "-flights"):
        if req not in argv:
            raise InputError("missing option %s for -scene drumSegment (see curtainCase -help)" % req)
    if shutil.which("drumSegmentCase") is None:
        raise InputError("drumSegmentCase not on PATH (source etc/bashrc)")
    sys.stdout.flush()
    os.execvp("drumSegmentCase", out)
