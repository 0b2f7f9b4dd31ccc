"""main: curtainCase's main: the options checked, DIR locked, the case run;
bad input exits 2 with nothing run, a failed run 1 (the previous result kept),
an interrupt 130 (the run goes on from its last whole time when started again)."""

import os
import shutil
import sys
import time

from ..errors import InputError, RunError
from ..options import parse
from ..processes import Children, acquire_lock, interrupts_raise
from .folders import signature
from .inputs import check_inputs
from .run import run
from .segment import drum_segment, scene_of
from .settings import ARGS, LOCK, LOCK_WAIT, RESULT, say

FLAGS = {"-keep", "-check"}
VALUED = {"-dir", "-gasVelocity", "-spillRate", "-fallHeight", "-flightLength",
          "-density", "-diameters", "-fractions", "-heights", "-level", "-np",
          "-drag", "-iterations", "-template", "-sphericity", "-particleTurbulence",
          "-turbulentDispersion", "-particleParticleDrag", "-turbulence", "-wakeShare", "-releaseVelocity",
          "-layerThickness", "-bulkDensity", "-boxWidth", "-gasTemperature", "-gasPressure", "-startFrom",
          "-steadyFrom"}
REQUIRED = ("-dir", "-gasVelocity", "-spillRate", "-fallHeight", "-flightLength",
            "-density", "-diameters", "-fractions")


def parse_args(argv, usage):
    return parse(argv, FLAGS, VALUED, REQUIRED, "curtainCase", usage)


def main(argv, usage):
    interrupts_raise()
    children = Children()
    try:
        scene, argv = scene_of(argv)
        if scene == "drumSegment":
            drum_segment(argv)
        opts = parse_args(argv, usage)
        s = check_inputs(opts)
        if os.path.exists(s["dir"]) and not os.path.isdir(s["dir"]):
            raise InputError("-dir %s is a file, not a folder" % s["dir"])
    except InputError as e:
        print("curtainCase: bad input: %s" % e, file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        return 130
    for tool in ("foamDictionaryServer", "blockMesh", "curtainFoam", "setpriv"):
        if shutil.which(tool) is None:
            print("curtainCase: %s not on PATH (source etc/bashrc)" % tool, file=sys.stderr)
            return 2
    if s["check"]:
        say("inputs checked: fall %g m (planes at %s m), level %s, solids fraction at the slot %.3g; "
            "nothing run" % (s["Y"], " ".join("%g" % h for h in s["heights"]), s["level"],
                             s["alpha_slot"]))
        print("inputs %s" % signature(s))   # what curtainCase.args.json of such a run holds
        return 0
    s["argv"] = argv
    t0 = time.time()
    lock_fd = None
    try:
        try:
            os.makedirs(s["dir"], exist_ok=True)
        except OSError as e:
            raise RunError("cannot make -dir %s: %s" % (s["dir"], e.strerror))
        lock_fd = acquire_lock(s["dir"], LOCK, "curtainCase", LOCK_WAIT, say)
        say("V_g %g m/s, spill %g kg/(m s), fall %g m (planes at %s m), L %g m, rho_p %g kg/m3, "
            "%d classes, level %s, solids fraction at the slot %.3g"
            % (s["Vg"], s["spill"], s["Y"], " ".join("%g" % h for h in s["heights"]), s["L"],
               s["rho"], len(s["d"]), s["level"], s["alpha_slot"]))
        run(children, s, lock_fd, t0)
        return 0
    except InputError as e:
        print("curtainCase: bad input: %s" % e, file=sys.stderr)
        return 2
    except RunError as e:
        print("curtainCase: FAILED: %s" % e, file=sys.stderr)
        if os.path.exists(os.path.join(s["dir"], RESULT)):
            print("curtainCase: the previous result %s (inputs in %s) is kept"
                  % (os.path.join(s["dir"], RESULT), os.path.join(s["dir"], ARGS)), file=sys.stderr)
        return 1
    except OSError as e:
        print("curtainCase: FAILED: %s: %s" % (getattr(e, "filename", "") or s["dir"],
                                              e.strerror or e), file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        children.stop_all()
        print("curtainCase: interrupted; the run in %s goes on from its last written iteration "
              "when started again with the same inputs; no result written"
              % os.path.join(s["dir"], "case.partial"), file=sys.stderr)
        return 130
    finally:
        children.stop_all()
        if lock_fd is not None:
            os.close(lock_fd)
