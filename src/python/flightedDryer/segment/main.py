"""main: drumSegmentCase's main: the options checked (exit 2, nothing run), the
run made in DIR.partial (a folder it did not make is never replaced) and moved to
DIR when finished; a failed step exits 1 naming its log, an interrupt 130, and
DIR is left as it was."""

import os
import re
import shutil
import sys

from .. import foamDictionary as fd
from ..errors import InputError, RunError
from ..processes import Children, interrupts_raise
from .inputs import TOOL, check, parse, signature
from .run import curtains, mesh, Steps


def say(msg):
    print("%s: %s" % (TOOL, msg), flush=True)


def prepare(o, run):
    """A fresh DIR.partial with the template's system/ and the flight dictionary
    (its angle of repose set by -reposeAngle)."""
    shutil.rmtree(run, ignore_errors=True)
    os.makedirs(os.path.join(run, "case"))
    open(os.path.join(run, ".drumSegmentCase.partial"), "w").close()
    shutil.copytree(os.path.join(o["template"], "system"), os.path.join(run, "case", "system"))
    with open(o["dict"]) as f:
        text = f.read()
    if o["reposeAngle"]:
        text = re.sub(r"(?m)^  dynamicAngleOfRepose: .*$", "  dynamicAngleOfRepose: %s   # deg (%s -reposeAngle)"
                      % (o["reposeAngle"], TOOL), text)
    with open(os.path.join(run, "segment.yaml"), "w") as f:
        f.write(text)
    cp = os.path.join(run, "case", "system", "caseParameters")
    for opt, entry in (("gasVelocity", "Vg"), ("density", "rhoP"), ("diameter", "diameter")):
        if o[opt]:
            fd.set_value(cp, entry, o[opt])


def main(argv, usage):
    try:
        o = check(parse(argv, usage))
        sig = signature(o)
        if o["check"]:
            say("inputs checked; nothing run")
            print("inputs %s" % sig)
            return 0
        out, run = o["out"], o["out"] + ".partial"
        if os.path.exists(out) and not os.path.isfile(os.path.join(out, ".drumSegmentCase")):
            raise InputError("-out %s exists and was not made by %s: nothing is replaced" % (out, TOOL))
        if os.path.exists(run) and not os.path.isfile(os.path.join(run, ".drumSegmentCase.partial")):
            raise InputError("%s exists and was not made by %s: nothing is replaced (the run is made there)"
                             % (run, TOOL))
        for tool in ("drumSegmentMesh", "gmshToFoam", "checkMesh", "foamDictionaryServer", "curtainFoam", "gnuplot"):
            if shutil.which(tool) is None:
                raise InputError("%s not on PATH (source etc/bashrc)" % tool)
    except InputError as e:
        print("%s: %s" % (TOOL, e), file=sys.stderr)
        return 2
    o["dict"] = os.path.realpath(o["dict"])
    o["template"] = os.path.realpath(o["template"])
    interrupts_raise()
    children = Children()
    try:
        prepare(o, run)
        steps = Steps(run, children)
        R = mesh(o, run, steps, say)
        if not o["meshOnly"]:
            curtains(o, run, R, steps, say)
        # done: the finished run replaces DIR
        os.remove(os.path.join(run, ".drumSegmentCase.partial"))
        with open(os.path.join(run, ".drumSegmentCase"), "w") as f:
            f.write("inputs %s\n" % sig)
        shutil.rmtree(out, ignore_errors=True)
        os.replace(run, out)
        say("%s (mesh: flights.png, mesh/flights.csv, case/VTK%s)"
            % (out, "" if o["meshOnly"] else "; curtains.csv, section.png"))
        return 0
    except InputError as e:
        # known only once meshed (a -release flight that does not release): nothing
        # of this run is kept
        children.stop_all()
        shutil.rmtree(run, ignore_errors=True)
        print("%s: %s" % (TOOL, e), file=sys.stderr)
        return 2
    except (RunError, fd.FoamDictionaryError, OSError) as e:
        print("%s: %s" % (TOOL, e), file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        children.stop_all()
        print("%s: interrupted; %s left as it was (the partial run: %s)" % (TOOL, out, run), file=sys.stderr)
        return 130
    finally:
        children.stop_all()
