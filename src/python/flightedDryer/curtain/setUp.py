"""setUp: the case folder made from the template at the run's operating point:
the mesh level and the geometry (a face plane at every fall height), the inlet,
the gas, the particles and their closures, and the run control (the steady state
decided inside the run by runTimeControl with the library's steadyWindow)."""

import os
import shutil

from .. import foamDictionary
from ..errors import InputError, RunError
from . import dictionaries as fd
from .dictionaries import set_entry
from .settings import (CAPTURED_GATE, DRIFT_ABS_TOL, LANDING_BIN, REL_TOL, VC_ABS_TOL, VC_REL_TOL,
                       STEADY_FROM_WINDOWS)


def copy_template(src, dst):
    """Only what a case needs: 0.orig, constant (without a mesh), system, into the
    folder dst (made if missing)."""
    os.makedirs(dst, exist_ok=True)
    for d in ("0.orig", "constant", "system"):
        try:
            shutil.copytree(os.path.join(src, d), os.path.join(dst, d),
                            ignore=shutil.ignore_patterns("polyMesh", "log.*", "*.foam"))
        except shutil.Error as e:
            first = e.args[0][0] if e.args and e.args[0] else ("", dst, str(e))
            raise RunError("cannot copy the template into %s: %s" % (first[1], first[2]))


def level_entries(case, level):
    """Mesh-parameter entries of a mesh level, from the template if it defines levels."""
    mp = os.path.join(case, "system", "meshParameters")
    for source in (os.path.join(case, "system", "meshLevels"), mp):
        if os.path.exists(source) and fd.has(source, "levels/" + level):
            keys = fd.keywords(source, "levels/" + level)
            return {k: fd.value(source, "levels/%s/%s" % (level, k)) for k in keys}
    if level == "coarse" and not os.path.exists(os.path.join(case, "system", "meshLevels")):
        return {}   # a template without levels: its own mesh is the coarse one
    raise InputError("-level %s: the template defines no such mesh level (%s)"
                     % (level, os.path.join(case, "system", "meshLevels")))


def vertical_sections(Y, heights, dy):
    """Multi-grading of the height: sections from the floor (y = 0) to the release
    (y = Y) with a face plane at Y - h for every fall height h; uniform cell height
    near dy, at least one cell per section."""
    planes = sorted(set([0.0, Y] + [Y - h for h in heights]))
    secs = []
    for a, b in zip(planes[:-1], planes[1:]):
        n = max(1, int(round((b - a) / dy)))
        secs.append((b - a, n))
    ny = sum(n for _, n in secs)
    grading = "(" + " ".join("(%.12g %d 1)" % (length / Y, n) for length, n in secs) + ")"
    return ny, grading


def round_up(n, m):
    return ((n + m - 1) // m) * m


def check_from(s):
    """The first iteration the steady window may end at: -steadyFrom, by default
    STEADY_FROM_WINDOWS windows (a window's samples all from this run)."""
    return s["steadyFrom"] if s.get("steadyFrom") is not None else STEADY_FROM_WINDOWS * s["window"]


def set_up(s, case):
    copy_template(s["template"], case)
    mp = os.path.join(case, "system", "meshParameters")
    cp = os.path.join(case, "system", "caseParameters")
    props = os.path.join(case, "constant", "curtainProperties")
    cd = os.path.join(case, "system", "controlDict")

    # mesh level, then geometry
    for k, v in level_entries(case, s["level"]).items():
        set_entry(mp, k, v)     # explicit entries override the level's (blockMeshDict)
    if fd.has(mp, "level"):
        set_entry(mp, "level", s["level"])
    ny0 = fd.scalar(mp, "ny")
    H0 = fd.scalar(mp, "H")
    gy0 = fd.value(mp, "gy")
    try:
        if abs(float(gy0) - 1) > 1e-12:
            raise ValueError
    except ValueError:
        raise RunError("template %s: vertical grading gy = %s; curtainCase needs a uniform "
                       "height grading (gy 1) to place the fall-height planes" % (mp, gy0))
    dy = H0 / ny0
    ny, grading = vertical_sections(s["Y"], s["heights"], dy)
    set_entry(mp, "H", "%.12g" % s["Y"])
    set_entry(mp, "xe", "%.12g" % (s["xs"] + s["L"]))
    # the layer: caseParameters' thickness (the inlet) and the mesh's half-layer zs
    set_entry(cp, "thickness", "%.12g" % s["thickness"])
    set_entry(mp, "zs", "%.12g" % (0.5 * s["thickness"]))
    if "boxWidth" in s:
        set_entry(mp, "W", "%.12g" % (0.5 * s["boxWidth"]))
    set_entry(mp, "ny", str(ny))
    set_entry(mp, "gy", grading)

    # operating point (the inlet turbulence: the template's k and epsilon inlet patches)
    set_entry(cp, "Vg", "%.12g" % s["Vg"])
    set_entry(cp, "releaseVelocity", "%.12g" % s["release"])
    set_entry(cp, "spillRate", "%.12g" % s["spill"])
    if "gasTemperature" in s:
        tp = os.path.join(case, "constant", "transportProperties")
        set_entry(tp, "rho", s["gasRho"])
        set_entry(tp, "nu", s["gasNu"])
    set_entry(cp, "rhoP", "%.12g" % s["rho"])
    names = s["names"]
    set_entry(cp, "massFractions",
              "{ " + " ".join("%s %.12g;" % (n, w) for n, w in zip(names, s["w"])) + " }")
    set_entry(props, "particles",
              "{ " + " ".join("%s { d %.12g; rho %.12g; }" % (n, d, s["rho"])
                              for n, d in zip(names, s["d"])) + " }")
    drag = "{ type %s; }" % s["drag"]
    if s["drag"] == "HaiderLevenspiel":
        drag = "{ type HaiderLevenspiel; sphericity %.12g; }" % s["sphericity"]
    set_entry(props, "drag", drag)
    if s["turbulentDispersion"] != "none":
        # the solver's own defaults for sigma and Cbeta (createFields.H)
        set_entry(props, "turbulentDispersion", "{ type %s; }" % s["turbulentDispersion"])
    if s["particleParticleDrag"] != "none":
        # the model's literature constants (its header in src/curtainModels)
        set_entry(props, "particleParticleDrag", "{ type %s; }" % s["particleParticleDrag"])
    set_entry(os.path.join(case, "constant", "turbulenceProperties.air"), "RAS/RASModel", s["turbulence"])
    if s["particleTurbulence"] != "none":
        coeffs = ""
        if s["wakeShare"] is not None:
            coeffs = "    %sCoeffs { Cp %.12g; }\n" % (s["particleTurbulence"], s["wakeShare"])
        with open(os.path.join(case, "constant", "fvOptions"), "w") as f:
            f.write("FoamFile { version 2.0; format ascii; class dictionary; object fvOptions; }\n"
                    "// written by curtainCase -particleTurbulence %s\n"
                    "particleTurbulence\n{\n    type            particleTurbulenceInteraction;\n"
                    "    active          yes;\n    model           %s;\n%s}\n"
                    % (s["particleTurbulence"], s["particleTurbulence"], coeffs))

    # run control and the measuring planes: the steady state is decided inside the
    # run (runTimeControl + steadyWindow), the latest iteration written every window
    n = s["iterations"]
    set_entry(cd, "startFrom", "latestTime")
    set_entry(cd, "stopAt", "endTime")
    set_entry(cd, "endTime", str(s["end"]))
    set_entry(cd, "writeControl", "timeStep")
    set_entry(cd, "writeInterval", str(s["window"]))
    set_entry(cd, "purgeWrite", "2")
    set_entry(cd, "writeFormat", "binary")
    set_entry(cd, "runTimeModifiable", "false")
    for fo in fd.keywords(cd, "functions"):
        foamDictionary.run(["-entry", "functions/" + fo, "-remove"], cd)
    conditions = []
    for i, h in enumerate(s["heights"]):
        floor = s["Y"] - h
        set_entry(cd, "functions/drift%d" % i,
                  "{ type curtainDrift; libs (curtainModels); releasePatch slot; "
                  "floorHeight %.12g; flowDirection (1 0 0); tolerance %.6g; "
                  "landing { binWidth %g; lostPatches (outlet); } "
                  "writeControl timeStep; writeInterval %d; }"
                  % (floor, min(1e-4, 0.01 * dy), LANDING_BIN, s["every"]))
        set_entry(cd, "functions/gas%d" % i,
                  "{ type curtainGasVelocity; libs (curtainModels); flowDirection (1 0 0); "
                  "gasInlet inlet; heights (%.12g %.12g); "
                  "writeControl timeStep; writeInterval %d; }"
                  % (floor, s["Y"], s["every"]))
        fields = ["drift_bulk"] + ["drift_" + c for c in names]
        gates = " ".join("drift_%s captured_%s;" % (c, c) for c in ["bulk"] + names)
        conditions.append(
            "drift%d { type steadyWindow; functionObject drift%d; fields (%s); "
            "gates { %s } gateMin %g; requireChecked yes; window %d; tolerance %g; "
            "absTolerance %g; startTime %d; groupID 1; }"
            % (i, i, " ".join(fields), gates, CAPTURED_GATE, s["window"], REL_TOL,
               DRIFT_ABS_TOL, check_from(s)))
        conditions.append(
            "gas%d { type steadyWindow; functionObject gas%d; fields (VcByVg); "
            "gates { VcByVg solidsVolume; } gateMin %g; window %d; tolerance %g; "
            "absTolerance %g; startTime %d; groupID 1; }"
            % (i, i, 1e-300, s["window"], VC_REL_TOL, VC_ABS_TOL, check_from(s)))
    set_entry(cd, "functions/massBalance",
              "{ type solidsMassBalance; libs (curtainModels); writeControl timeStep; "
              "writeInterval %d; }" % s["every"])
    set_entry(cd, "functions/steady",
              "{ type runTimeControl; libs (utilityFunctionObjects curtainModels); "
              "executeControl timeStep; executeInterval %d; writeControl writeTime; "
              "conditions { %s } }" % (s["every"], " ".join(conditions)))
    if s["np"] > 1:
        dp = os.path.join(case, "system", "decomposeParDict")
        set_entry(dp, "numberOfSubdomains", str(s["np"]))
        set_entry(dp, "method", "simple")
        set_entry(dp, "coeffs", "{ n (%d 1 1); }" % s["np"])
        set_entry(dp, "simpleCoeffs", "{ n (%d 1 1); }" % s["np"])
