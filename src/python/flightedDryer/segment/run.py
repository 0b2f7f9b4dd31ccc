"""run: the drum segment's steps, made in DIR.partial and moved to DIR only when
finished: drumSegmentMesh (gmsh) -> gmshToFoam -> walls typed -> createPatch
(periodic ends) -> checkMesh -> foamToVTK -> flights.png (gnuplot); then one
particle class per releasing flight, curtainFoam in local time steps, foamToVTK
and segmentResults (curtains.csv, section.png)."""

import csv
import math
import os
import re
import shutil
import subprocess
import sys

from .. import PROJECT, foamDictionary as fd
from ..errors import InputError, RunError
from ..warmStart import source_time
from .inputs import TOOL

PLATE = "0.02"     # m, flight plate thickness
LIP = "0.04"       # m, width of each flight's release patch (the back face at the lip)
RESULTS = os.path.join(PROJECT, "applications", "utilities", "drumSegmentCase", "segmentResults")


def g6(v):
    """A number as awk prints it (%.6g)."""
    return "%.6g" % v


class Steps:
    """Each step a child in its own process group, its output in run/log.NAME; a
    failed step prints its log's last lines and is a RunError."""

    def __init__(self, run, children):
        self.run, self.children = run, children

    def __call__(self, name, cmd):
        log = os.path.join(self.run, "log." + name)
        with open(log, "w") as out:
            p = self.children.spawn(cmd, out, cwd=self.run)
            rc = p.wait()
            self.children.done(p)
        if rc != 0:
            with open(log, errors="replace") as f:
                sys.stderr.write("".join(f.readlines()[-25:]))
            raise RunError("%s failed (log: %s)" % (name, log))
        return log


def flights(run):
    """The rows of mesh/flights.csv (drumSegmentMesh) as lists of fields."""
    with open(os.path.join(run, "mesh", "flights.csv"), newline="") as f:
        return list(csv.reader(f))[1:]


def yaml_value(path, key):
    """A two-space-indented `key: value` of the flight dictionary (its first)."""
    with open(path) as f:
        for line in f:
            if line.startswith("  %s:" % key):
                return line.split()[1]
    return ""


def section_picture(run, steps):
    """flights.png: the drum wall, the bed surface and the flights (red: releasing,
    with their spill rate)."""
    R = yaml_value(os.path.join(run, "segment.yaml"), "radius")
    h = yaml_value(os.path.join(run, "segment.yaml"), "bedDepth") or "0"
    rows = flights(run)
    with open(os.path.join(run, "flights.dat"), "w") as f:
        f.write("".join("%s %s\n%s %s\n%s %s\n\n\n" % tuple(r[2:8]) for r in rows))
    with open(os.path.join(run, "releasing.dat"), "w") as f:
        f.write("".join("%s %s\n%s %s\n%s %s\n\n\n" % tuple(r[2:8]) for r in rows if float(r[9]) == 1))
    with open(os.path.join(run, "spills.dat"), "w") as f:
        f.write("".join('%s %s "%.1f"\n' % (r[6], r[7], float(r[10])) for r in rows if float(r[9]) == 1))
    script = """set terminal pngcairo size 900,900 font ",11"
set output "flights.png"
set size ratio -1
set title "Drum segment: {n} flights, bed {h} m (red: releasing, spill kg/(m s))"
set xrange [-{R}*1.08:{R}*1.08]; set yrange [-{R}*1.08:{R}*1.08]
set parametric; set trange [0:2*pi]; set samples 400
plot {R}*cos(t), {R}*sin(t) lc rgb "black" lw 2 notitle, \\
     (t/pi - 1)*sqrt({R}**2 - ({R} - {h})**2), -{R} + {h} lc rgb "#b08040" lw 2 title "bed surface", \\
     "flights.dat" using 1:2 with lines lc rgb "gray40" lw 3 title "flights", \\
     "releasing.dat" using 1:2 with lines lc rgb "red" lw 3 title "releasing", \\
     "spills.dat" using 1:2:3 with labels offset 2,1 notitle
""".format(n=len(rows), h=h, R=R)
    with open(os.path.join(run, "log.gnuplot"), "w") as log:
        r = subprocess.run(["gnuplot"], input=script, text=True, cwd=run, stdout=log, stderr=subprocess.STDOUT)
    if r.returncode != 0:
        with open(os.path.join(run, "log.gnuplot")) as f:
            sys.stderr.write(f.read())
        raise RunError("flights.png failed")
    return R


def mesh(o, run, steps, say):
    """The section meshed, its walls typed, its ends joined (periodic), checked,
    written for ParaView and pictured."""
    case = os.path.join(run, "case")
    log = steps("drumSegmentMesh", ["drumSegmentMesh", "-dict", "segment.yaml", "-length", o["length"],
                                    "-plateThickness", PLATE, "-releaseWidth", LIP, "-level", o["level"],
                                    "-out", "mesh"])
    print("".join(line for line in open(log) if line.startswith("drumSegmentMesh: ")), end="", flush=True)
    steps("gmshToFoam", ["gmshToFoam", "-case", "case", "mesh/drumSegment.msh"])
    # gmshToFoam makes every patch a plain patch: the drum wall and the flights are
    # walls, and so are the flight tips until a curtain is released there
    b = os.path.join(case, "constant", "polyMesh", "boundary")
    for p in ["wall"] + [r[8] for r in flights(run) if r[8] != "-"]:
        fd.set_value(b, "entry0/%s/type" % p, "wall")
    if o["ends"] == "periodic":
        # the ends become one cyclic pair (createPatch matches and orders the faces)
        with open(os.path.join(o["template"], "system", "createPatchDict.periodic")) as f:
            text = f.read().replace("SEGMENT_LENGTH", o["length"])
        with open(os.path.join(case, "system", "createPatchDict"), "w") as f:
            f.write(text)
        steps("createPatch", ["createPatch", "-case", "case", "-overwrite"])
    log = steps("checkMesh", ["checkMesh", "-case", "case"])
    text = open(log, errors="replace").read()
    for line in text.splitlines():
        if any(k in line for k in ("Max aspect", "Max non-orth", "Max skewness", "Mesh OK", "Failed")) \
                or line.lstrip().startswith("cells:"):
            print("   " + line.lstrip())
    if "Mesh OK" not in text:
        raise RunError("checkMesh failed (log: %s)" % log)
    steps("foamToVTK", ["foamToVTK", "-case", "case", "-noFunctionObjects"])
    return section_picture(run, steps)


def last_line_sub(text, entry):
    """sed '$ s|^}$|<entry>\\n}|': the file's last line, if it is '}' alone, becomes
    the entry and then '}'."""
    lines = text.split("\n")
    k = len(lines) - 2 if text.endswith("\n") else len(lines) - 1
    if k >= 0 and lines[k] == "}":
        lines[k] = entry + "\n}"
    return "\n".join(lines)


def statistics_window(case):
    """The averaging window (local steps) of a run stopped by its statistics (the
    batchMeans conditions vc and drift of the template's `statistics`: the whole
    batches kept after the start-up, up to the final step; the shorter of the two
    windows) and a line saying whether the means were known to their tolerance or
    the run reached its cap."""
    times = [d for d in os.listdir(case) if re.fullmatch(r"[0-9]+", d)]
    last = max(int(t) for t in times)
    props = os.path.join(case, str(last), "uniform", "functionObjects", "functionObjectProperties")

    def result(key):
        v = float(fd.value(props, "results/statistics/scalar/" + key))
        if not math.isfinite(v):
            raise RunError("%s: statistics result %s is %s" % (props, key, v))
        return v
    try:
        start = max(result("vc_windowStart"), result("drift_windowStart"))
        batches = int(min(result("vc_batches"), result("drift_batches")))
        se = [result(k + "_se") for k in ("vc_VcByVg", "drift_drift_bulk")]
        mean = [result(k + "_mean") for k in ("vc_VcByVg", "drift_drift_bulk")]
        known = all(result(k + "_known") == 1 for k in ("vc", "drift"))
    except fd.FoamDictionaryError as e:
        raise RunError("%s: the statistics' window is not recorded (%s)" % (props, e))
    window = last - int(round(start))
    if not window > 0:
        raise RunError("%s: no whole batch of statistics by step %d (the cap, -steps, is too small)" % (props, last))
    return window, ("statistics: %s at step %d; means over the last %d steps (%d batches): V_c/V_g %.4g +- %.2g, "
                    "drift %.4g +- %.2g m (standard errors)"
                    % ("means known to their tolerance" if known else "the cap reached before the means were known",
                       last, window, batches, mean[0], se[0], mean[1], se[1]))


def warm_source(o, case):
    """-startFrom: the last time folder of a finished segment run on the same mesh
    (compared file by file), whose fields curtainFoam reads at time 0 (startFields);
    every class of this run must be one of that run's (the same releasing flights)."""
    if not os.path.isfile(os.path.join(o["startFrom"], ".drumSegmentCase")):
        raise RunError("-startFrom %s: not a finished drumSegmentCase run" % o["startFrom"])
    t, last = source_time(o["startFrom"], case)
    print("   warm start from %s (its fields at step %g)" % (o["startFrom"], last), flush=True)
    return t


def curtains(o, run, R, steps, say):
    """One class per releasing flight, released through its tipNN patch at the
    flight's spill rate; curtainFoam in local time steps; the results. Returns the
    averaging window's length in steps."""
    case = os.path.join(run, "case")
    cp, cd, fvs = (os.path.join(case, "system", n) for n in ("caseParameters", "controlDict", "fvSolution"))
    v = {k: fd.value(cp, k) for k in ("releaseVelocity", "rhoP", "diameter", "Vg")}
    # the local steps: -steps, else the template's, doubled at the finer levels and
    # halved with open ends (steady from about step 150)
    end = int(fd.value(cd, "endTime"))
    if o["level"] != "coarse":
        # the finer prisms diverge with the template's maxCo 2: half the local
        # Courant number and twice the steps
        fd.set_value(fvs, "PIMPLE/maxCo", g6(float(fd.value(fvs, "PIMPLE/maxCo")) / 2))
        end = 2 * end
    if o["ends"] != "periodic":
        end = end // 2
    if o["steps"]:
        end = int(o["steps"])
    fd.set_value(cd, "endTime", str(end))
    if o["stop"] == "statistical":
        # the statistics' batches (one swing each) are the restart points too
        batch = int(float(fd.value(cd, "functions/statistics/conditions/vc/batch")))
        fd.set_value(cd, "writeInterval", str(batch))
    else:
        fd.remove(cd, "functions/statistics")
        fd.set_value(cd, "writeInterval", str(end // 3))
    zmid = g6(float(o["length"]) / 2)     # the mid-segment section
    shutil.copytree(os.path.join(o["template"], "constant"), os.path.join(case, "constant"), dirs_exist_ok=True)
    if o["gas"]:
        # air at -gasTemperature and -gasPressure (flightedDryer.gas, as curtainCase's)
        tp = os.path.join(case, "constant", "transportProperties")
        fd.set_value(tp, "rho", o["gas"][0])
        fd.set_value(tp, "nu", o["gas"][1])
    if os.path.exists(os.path.join(case, "constant", "fvOptions.periodic")):
        os.remove(os.path.join(case, "constant", "fvOptions.periodic"))
    os.makedirs(os.path.join(case, "0"), exist_ok=True)
    for f in ("U.air", "p_rgh", "k.air", "epsilon.air", "nut.air"):
        shutil.copy(os.path.join(o["template"], "0.orig", f), os.path.join(case, "0", f))
    if o["ends"] == "periodic":
        # no inlet: meanVelocityForce holds the mean axial gas velocity at V_g; no
        # outlet: the pressure level is set at a point in the open drum above the bed
        shutil.copy(os.path.join(o["template"], "constant", "fvOptions.periodic"),
                    os.path.join(case, "constant", "fvOptions"))
        fd.add(fvs, "PIMPLE/p_rghRefPoint", "(0 %s %s)" % (g6(float(R) / 5), zmid))
        fd.add(fvs, "PIMPLE/p_rghRefValue", "0")
        fd.remove(cd, "functions/gasInCurtain/gasInlet")
        fd.add(cd, "functions/gasInCurtain/Vg", v["Vg"])
        fd.set_value(cd, "functions/drift/landing/lostPatches", "()")
        fd.add(cd, "functions/drift/periodic", "yes")
    fd.set_value(cd, "functions/section/surfaces/mid/pointAndNormalDict/point", "(0 0 %s)" % zmid)
    tips = [r[8] for r in flights(run) if float(r[9]) == 1]
    if not tips:
        raise RunError("no flight releases into the curtains (mesh/flights.csv)")
    if o["release"]:
        for c in o["release"].split(","):
            if c not in tips:
                raise InputError("-release %s: not a releasing flight of this section (mesh/flights.csv: %s)"
                                 % (c, " ".join(tips)))
        tips = sorted(set(o["release"].split(",")), key=lambda t: t.encode())
    with open(os.path.join(case, "constant", "curtainProperties"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object curtainProperties; }\n"
                "// written by %s: one class per releasing flight (mesh/flights.csv)\n"
                "continuousPhase air;\ndrag { type %s; }\nparticles\n{\n" % (TOOL, o["drag"])
                + "".join("    %s { d %s; rho %s; }\n" % (c, v["diameter"], v["rhoP"]) for c in tips)
                + "}\nalphaMax        0.62;\n"
                + ('startFields { dir "%s"; }\n' % warm_source(o, case) if o["startFrom"] else ""))
    spills = {r[8]: r[10] for r in flights(run)}
    for c in tips:
        # the tip's own entry closes the boundaryField (an exact patch name wins
        # over the template's patterns)
        with open(os.path.join(o["template"], "0.orig", "alpha.particles")) as f:
            a = last_line_sub(f.read().replace("particles", c),
                              "    %s { type curtainInlet; spillRate %s; thickness %s; rhoParticle %s; "
                              "massFractions { %s 1; } value uniform 0; }" % (c, spills[c], LIP, v["rhoP"], c))
        with open(os.path.join(case, "0", "alpha." + c), "w") as f:
            f.write(a)
        with open(os.path.join(o["template"], "0.orig", "U.particles")) as f:
            u = last_line_sub(f.read().replace("particles", c),
                              "    %s { type curtainInletVelocity; releaseVelocity %s; value uniform (0 0 0); }"
                              % (c, v["releaseVelocity"]))
        with open(os.path.join(case, "0", "U." + c), "w") as f:
            f.write(u)
    print("   curtains: %d flights (%s), released over %s m at each lip; ends %s, V_g %s m/s"
          % (len(tips), " ".join(tips), LIP, o["ends"], v["Vg"]), flush=True)
    np_ = int(o["np"])
    if np_ > 1:
        dp = os.path.join(case, "system", "decomposeParDict")
        fd.set_value(dp, "numberOfSubdomains", str(np_))
        fd.set_value(dp, "coeffs/n", "(%d 1 1)" % np_)
        steps("decomposePar", ["decomposePar", "-case", "case"])
        steps("curtainFoam", ["mpirun", "--allow-run-as-root", "-np", str(np_), "curtainFoam", "-case", "case",
                              "-parallel"])
        steps("reconstructPar", ["reconstructPar", "-case", "case", "-latestTime"])
        for d in os.listdir(case):
            if d.startswith("processor"):
                shutil.rmtree(os.path.join(case, d))
    else:
        steps("curtainFoam", ["curtainFoam", "-case", "case"])
    balance = [line for line in open(os.path.join(run, "log.curtainFoam"), errors="replace")
               if "(in - out)/in" in line]
    if balance:
        print("   " + balance[-1].lstrip().rstrip("\n"))
    steps("foamToVTK.curtains", ["foamToVTK", "-case", "case", "-latestTime", "-noFunctionObjects"])
    window = end // 3
    if o["stop"] == "statistical":
        window, note = statistics_window(case)
        print("   " + note, flush=True)
    steps("segmentResults", [RESULTS, run, str(window)])
    r = subprocess.run(["column", "-s,", "-t"], stdin=open(os.path.join(run, "curtains.csv")),
                       capture_output=True, text=True)
    print("".join("   " + line + "\n" for line in r.stdout.splitlines()), end="", flush=True)
