"""inputs: drumSegmentCase's options checked before anything runs, and the
inputs' signature (every option that changes the answer, the flight
dictionary's and the template's content): buildDriftTable's resume test."""

import hashlib
import os
import re

from .. import PROJECT, facts, gas
from ..errors import InputError

TOOL = "drumSegmentCase"
FLAGS = {"-meshOnly", "-check"}
VALUED = {"-dict", "-out", "-level", "-ends", "-gasVelocity", "-reposeAngle", "-length", "-np", "-steps",
          "-template", "-release", "-drag", "-stop", "-density", "-diameter", "-gasTemperature", "-gasPressure",
          "-startFrom"}
# the segment's axes: the dynamic angle of repose (deg) and the mean axial gas
# velocity (m/s) a segment runs at (also a sweep's grid and a study's plan)
REPOSE_RANGE = (20.0, 70.0)
GAS_VELOCITY_RANGE = (0.05, 10.0)
NUMBER = re.compile(r"^[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?$")


def parse(argv, usage):
    """The options as text, with the tool's defaults; -help prints usage. A later
    value of an option given twice wins, as the shell tool did; curtainCase
    -scene drumSegment refuses repeated options before."""
    o = {"dict": "", "out": "", "level": "coarse", "ends": "periodic", "gasVelocity": "", "reposeAngle": "",
         "length": "1.133", "np": "1", "steps": "", "template": os.path.join(PROJECT, "etc", "templates",
                                                                            "curtain", "drumSegment"),
         "release": "", "drag": "SchillerNaumann", "stop": "", "density": "", "diameter": "", "gasTemperature": "",
         "gasPressure": "", "startFrom": "", "meshOnly": False, "check": False}
    i = 0
    while i < len(argv):
        a = argv[i]
        if a in VALUED:
            if i + 1 >= len(argv):
                raise InputError("option %s needs a value" % a)
            o[a[1:]] = argv[i + 1]
            i += 2
        elif a in FLAGS:
            o[a[1:]] = True
            i += 1
        elif a in ("-h", "-help", "--help"):
            print(usage)
            raise SystemExit(0)
        else:
            raise InputError("unknown option '%s' (see %s -help)" % (a, TOOL))
    return o


def in_range(name, value, lo, hi):
    if not NUMBER.match(value) or not lo <= float(value) <= hi:
        raise InputError("%s = '%s': a number in [%g, %g] is needed" % (name, value, lo, hi))


def check(o):
    """Every option against its range; the run's folders resolved."""
    if not o["dict"]:
        raise InputError("-dict FILE is needed (the flight dictionary)")
    if not os.path.isfile(o["dict"]):
        raise InputError("-dict %s: no such file" % o["dict"])
    if not o["out"]:
        raise InputError("-out DIR is needed")
    if o["level"] not in ("coarse", "medium", "fine"):
        raise InputError("-level '%s': coarse, medium or fine" % o["level"])
    if o["ends"] not in ("periodic", "open"):
        raise InputError("-ends '%s': periodic or open" % o["ends"])
    if o["gasVelocity"]:
        in_range("-gasVelocity", o["gasVelocity"], *GAS_VELOCITY_RANGE)
    if o["reposeAngle"]:
        in_range("-reposeAngle", o["reposeAngle"], *REPOSE_RANGE)
    in_range("-length", o["length"], 0.1, 100)
    if not o["np"].isdigit():
        raise InputError("-np '%s': a whole number in [1, 64]" % o["np"])
    if not 1 <= int(o["np"]) <= 64:
        raise InputError("-np %s: a whole number in [1, 64]" % o["np"])
    if o["steps"]:
        if not o["steps"].isdigit():
            raise InputError("-steps '%s': a whole number in [30, 100000], a multiple of 3" % o["steps"])
        if not (30 <= int(o["steps"]) <= 100000 and int(o["steps"]) % 3 == 0):
            raise InputError("-steps %s: a whole number in [30, 100000], a multiple of 3 (the averaging "
                             "window is the last third)" % o["steps"])
    if o["release"] and not re.fullmatch(r"tip[0-9]{2,}(,tip[0-9]{2,})*", o["release"]):
        raise InputError("-release '%s': tip patch names tipNN, separated by commas (mesh/flights.csv)"
                         % o["release"])
    if o["stop"] not in ("", "statistical", "fixed"):
        raise InputError("-stop '%s': statistical or fixed" % o["stop"])
    if o["stop"] == "statistical" and o["ends"] != "periodic":
        raise InputError("-stop statistical needs -ends periodic (open ends have a steady state: fixed)")
    # periodic ends stop when their means are known; open ends run their steps
    o["stop"] = o["stop"] or ("statistical" if o["ends"] == "periodic" else "fixed")
    # the material and the gas (default: the template's caseParameters and
    # transportProperties, the Invicta crystal in air at 80 degC)
    if o["gasTemperature"]:
        in_range("-gasTemperature", o["gasTemperature"], *facts.gas_temperature_range())
    if o["gasPressure"]:
        in_range("-gasPressure", o["gasPressure"], *facts.gas_pressure_range())
    o["gas"] = None
    if o["gasTemperature"] or o["gasPressure"]:
        try:
            o["gas"] = gas.air_properties(float(o["gasTemperature"] or 20), float(o["gasPressure"])
                                          if o["gasPressure"] else None, entry="-gasTemperature",
                                          warn=lambda w: print("%s: warning: %s" % (TOOL, w), flush=True))
        except gas.GasError as e:
            raise InputError("-gasTemperature/-gasPressure: %s" % e)
    if o["diameter"]:
        in_range("-diameter", o["diameter"], 1e-6, 0.05)
    if o["density"]:
        rho_gas = float(o["gas"][0]) if o["gas"] else 1.0
        in_range("-density", o["density"], 10 * rho_gas, 25000)
    if o["startFrom"]:
        if int(o["np"]) > 1:
            raise InputError("-startFrom needs -np 1 (the source's fields are read onto the whole mesh)")
        o["startFrom"] = os.path.abspath(o["startFrom"])
    laws = facts.drag_laws()
    if o["drag"] not in laws:
        raise InputError("-drag '%s' is not one of %s" % (o["drag"], " ".join(laws)))
    for d in ("0.orig", "constant", "system"):
        if not os.path.isdir(os.path.join(o["template"], d)):
            raise InputError("-template %s: no %s/ (a case template: 0.orig, constant, system)"
                             % (o["template"], d))
    if o["reposeAngle"]:
        with open(o["dict"], errors="replace") as f:
            if not any(line.startswith("  dynamicAngleOfRepose:") for line in f):
                raise InputError("-dict %s: no material.dynamicAngleOfRepose entry for -reposeAngle to set"
                                 % o["dict"])
    o["out"] = os.path.abspath(o["out"])
    if o["out"] == os.path.realpath(os.getcwd()):
        raise InputError("-out %s is the current folder; give a folder of its own" % o["out"])
    return o


def _sha1_file(path):
    with open(path, "rb") as f:
        return hashlib.sha1(f.read()).hexdigest()


def signature(o):
    """SHA1 of the options that change the answer (not -np, not -out), the flight
    dictionary's and the template's content (as `sha1sum` lists them)."""
    text = ("level=%s ends=%s gasVelocity=%s reposeAngle=%s length=%s steps=%s meshOnly=%s release=%s\n"
            % (o["level"], o["ends"], o["gasVelocity"], o["reposeAngle"], o["length"], o["steps"],
               1 if o["meshOnly"] else 0, o["release"]))
    if o["stop"] == "statistical":
        text += "stop=statistical\n"
    if o["drag"] != "SchillerNaumann":
        # (the default leaves the signature of runs made before the option as it was)
        text += "drag=%s\n" % o["drag"]
    for k in ("density", "diameter", "gasTemperature", "gasPressure"):
        if o[k]:
            text += "%s=%s\n" % (k, o[k])
    if o["startFrom"]:
        # the source's folder name (a sweep plans it before the source has run)
        text += "startFrom=%s\n" % os.path.basename(o["startFrom"])
    text += "%s  -\n" % _sha1_file(o["dict"])
    files = []
    for root, _, names in os.walk(o["template"]):
        for n in names:
            files.append("./" + os.path.relpath(os.path.join(root, n), o["template"]))
    for rel in sorted(files, key=lambda p: p.encode()):
        text += "%s  %s\n" % (_sha1_file(os.path.join(o["template"], rel)), rel)
    return hashlib.sha1(text.encode()).hexdigest()
