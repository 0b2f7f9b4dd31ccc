"""segment: the drum-segment scene of a study (study.scene: drumSegment): the
dryer's own cross-section with every releasing flight's curtain at once
(drumSegmentCase), one run per dynamic angle of repose and gas velocity; the
table is writeSegmentTable's and the drum model reads it with drift segmentVc
(V_c/V_g per release angle, lone particles in it). What the description gives
becomes the segment's flight dictionary; the bed depth is the drum model's own
kilning bed at mid-drum (the Eq 142 pass's profile.csv, kiln_depth_m)."""

import csv
import math
import os
import re

import yaml

from .. import PROJECT, foamDictionary
from ..errors import InputError, RunError
from ..files import atomic_write
from ..processes import run_tied
from ..segment.inputs import GAS_VELOCITY_RANGE, REPOSE_RANGE

TEMPLATE = os.path.join(PROJECT, "etc", "templates", "curtain", "drumSegment")
# the repose-angle nodes lie at most this far apart (deg): the hand-made Invicta
# segment table's spacing (etc/defaults/driftTables/invictaSegmentDict)
REPOSE_STEP = 12.0
# CPU per cell and local step, and the steps a statistical stop takes, measured
# on the Invicta segments (tests/benchmarks/segmentStop/results/summary.csv; the
# cells from the shipped table's header)
STOP_BENCHMARK = os.path.join(PROJECT, "tests", "benchmarks", "segmentStop", "results", "summary.csv")
SHIPPED_SEGMENT = os.path.join(PROJECT, "etc", "defaults", "driftTables", "invictaSegment.csv")
RUN_OVERHEAD_S = 10.0   # s per run: meshing, the start-up, foamToVTK, segmentResults


def table_kind(path):
    """segment for a drum-segment table (its magic line), else table."""
    with open(path, errors="replace") as f:
        return "segment" if f.readline().startswith("# dryerSegmentTable") else "table"


def check(desc, sweep=True):
    """What the scene needs of the description, refused before anything runs:
    the compartment model's flight model (the only drum model asking per release
    angle); to sweep, Lee's two-section flights in a drum without a centre fill
    and steps a segment can stop in."""
    m = desc.sections["model"]
    if m.get("type") != "compartment" or m.get("partition") != "flightModel":
        raise InputError("%s: a drum-segment table serves the compartment model with partition flightModel "
                         "(drift per release angle); this description's model is %s%s: use scene box"
                         % (desc.where("study.scene" if sweep else "study.table"), m.get("type"),
                            " (partition %s)" % m["partition"] if "partition" in m else ""))
    if not sweep:
        return
    fl = desc.sections["flights"]
    if "exterior" in fl:
        raise InputError("%s = drumSegment: the segment mesh draws Lee's two-section flights (flights.count, "
                         "baseLength, tipLength, angles), not Sherritt's exterior/interior description"
                         % desc.where("study.scene"))
    it = desc.study["iterations"]
    if it is not None and (int(it) != it or int(it) % 3):
        raise InputError("%s = %s: a drum segment's local steps are a whole multiple of 3 (with stop fixed its "
                         "means are over the last third)" % (desc.where("study.iterations"), it))
    if desc.study["stop"] == "statistical" and it is not None:
        cd = os.path.join(TEMPLATE, "system", "controlDict")
        need = int(float(foamDictionary.value(cd, "functions/statistics/conditions/vc/batch"))) * \
            int(float(foamDictionary.value(cd, "functions/statistics/conditions/vc/minBatches")))
        if it < need:
            raise InputError("%s = %s: a statistical stop needs at least %d local steps (its fewest batches); give "
                             "more, or study.stop: fixed" % (desc.where("study.iterations"), it, need))
    if float(desc.sections["drum"].get("centrefillDiameter", 0) or 0) > 0:
        raise InputError("%s = drumSegment: the segment mesh has no centre fill (drum.centrefillDiameter)"
                         % desc.where("study.scene"))


def bed_depth(planner_case, desc):
    """The kilning bed's depth over the drum bottom at mid-drum (the slice nearest
    half the drum's length) of the Eq 142 pass: the level bed of the segment."""
    path = os.path.join(planner_case, "results", "profile.csv")
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows or "kiln_depth_m" not in rows[0]:
        raise RunError("%s: no kiln_depth_m column (drumSolver's compartment profile)" % path)
    mid = float(desc.sections["drum"]["length"]) / 2
    row = min(rows, key=lambda r: abs(float(r["x_m"]) - mid))
    h = float(row["kiln_depth_m"])
    R = float(desc.sections["drum"]["diameter"]) / 2
    if not (math.isfinite(h) and 0 <= h < R):
        raise RunError("%s: kiln_depth_m %s at x = %s m is not a bed depth in [0, %g) m" % (path, h, row["x_m"], R))
    return h, float(row["x_m"])


def flight_dictionary(desc, bed, repose):
    """The flight dictionary (flightUnloading's and drumSegmentMesh's YAML) of the
    description's drum and flights, a level bed `bed` m deep and the angle of
    repose `repose` (each run sets its own with -reposeAngle). Entries the
    description leaves out take the drum model's defaults (drumSolver README:
    baseAngle_deg 90, tipAngle_deg 90, tipLength 0)."""
    dr, fl, mat = desc.sections["drum"], desc.sections["flights"], desc.sections["material"]
    data = {"drum": {"radius": float(dr["diameter"]) / 2, "nFlights": int(fl["count"]),
                     "speed": float(dr["speed_rpm"]), "slope": float(dr.get("slope_deg", 0)),
                     "bedDepth": float("%.6g" % bed)},
            "flight": {"baseLength": float(fl["baseLength"]), "tipLength": float(fl.get("tipLength", 0)),
                       "baseAngle": float(fl.get("baseAngle_deg", 90)), "tipAngle": float(fl.get("tipAngle_deg", 90)),
                       "length": float(dr["length"])},
            "material": {"bulkDensity": float(mat["bulkDensity"]), "dynamicAngleOfRepose": float("%.6g" % repose)}}
    return ("# written by dryerStudy from %s: the segment's flight dictionary (drum, flights, bulk\n"
            "# density; the bed level at the drum model's mid-drum kiln depth; each run sets its\n"
            "# dynamic angle of repose)\n" % desc.path) + yaml.safe_dump(data, sort_keys=False)


def _nodes(lo, hi, step):
    """lo..hi evenly, neighbours at most `step` apart (one node when lo == hi)."""
    if hi - lo < 1e-9:
        return [lo]
    n = max(1, math.ceil((hi - lo) / step - 1e-9))
    return [lo + (hi - lo) * k / n for k in range(n + 1)]


def grid(q, study):
    """The segment runs' grid: dynamic angles of repose (whole degrees around the
    drum model's, at most REPOSE_STEP apart) and gas velocities (the drum model's
    reached beyond by the study's margin, as the box's grid)."""
    if "repose_angle_deg" not in q:
        raise RunError("the drum model's queries carry no repose angle (drift.recordQueries of the flight model)")
    plo, phi = q["repose_angle_deg"]
    lo, hi = max(REPOSE_RANGE[0], math.floor(plo)), min(REPOSE_RANGE[1], math.ceil(phi))
    if plo < REPOSE_RANGE[0] or phi > REPOSE_RANGE[1]:
        raise InputError("the drum model's dynamic angles of repose %.4g-%.4g deg lie outside what a drum segment "
                         "runs, [%g, %g] deg" % (plo, phi, REPOSE_RANGE[0], REPOSE_RANGE[1]))
    m = study["margin"]
    vlo, vhi = q["gas_velocity_m_s"]
    gas = sorted({float("%.3g" % v) for v in (max(GAS_VELOCITY_RANGE[0], vlo / (1 + m)), min(GAS_VELOCITY_RANGE[1], vhi * (1 + m)))})
    if vlo < GAS_VELOCITY_RANGE[0] or vhi > GAS_VELOCITY_RANGE[1]:
        raise InputError("the drum model's gas velocities %.4g-%.4g m/s lie outside what a drum segment runs, "
                         "[%g, %g] m/s" % (vlo, vhi, GAS_VELOCITY_RANGE[0], GAS_VELOCITY_RANGE[1]))
    return {"reposeAngle": [float("%.4g" % v) for v in _nodes(lo, hi, REPOSE_STEP)], "gasVelocity": gas}


def covers(g, q):
    """The axes on which the segment grid misses a query (empty: it covers them;
    the release angles are the runs' own flights, read with outside: clamp)."""
    miss = []
    for axis, key in (("repose_angle_deg", "reposeAngle"), ("gas_velocity_m_s", "gasVelocity")):
        if axis in q:
            lo, hi = q[axis]
            if lo < g[key][0] * (1 - 1e-9) or hi > g[key][-1] * (1 + 1e-9):
                miss.append(axis)
    return miss


def runs(g):
    return len(g["reposeAngle"]) * len(g["gasVelocity"])


def particle(desc):
    """The curtains' one particle size (the size distribution's mass-weighted
    median, sieve size times sphericity, as the drum model's classes) and density."""
    mat = desc.sections["material"]
    sph = float(mat.get("sphericity", 1.0))
    pairs = sorted(zip((float(s) * 1e-6 * sph for s in mat["sizes_um"]), (float(x) for x in mat["fractions_pct"])))
    total, acc = sum(w for _, w in pairs), 0.0
    for d, w in pairs:
        acc += w
        if acc >= total / 2 * (1 - 1e-12):
            break
    return float("%.6g" % d), float(mat["particleDensity"])


def sweep_dict(g, desc, study, flights, output, gas_t):
    """The buildDriftTable dictionary (scene drumSegment) of the grid."""
    d, rho = particle(desc)
    lines = ["FoamFile { version 2.0; format ascii; class dictionary; object dryerStudySegments; }",
             "// written by dryerStudy from %s" % desc.path,
             "scene drumSegment;", 'flights "%s";' % flights, "level %s;" % study["level"],
             "ends periodic;", "stop %s;" % study["stop"], "drag %s;" % study["drag"],
             "segmentLength %.6g;" % float(desc.sections["flights"]["axialLength"]),
             "particleDensity %.6g;" % rho, "diameter %.6g;" % d, "gasTemperature %.6g;" % gas_t]
    if "pressure_kPa" in desc.sections["gas"]:
        lines.append("gasPressure %.6g;" % float(desc.sections["gas"]["pressure_kPa"]))
    if study["iterations"] is not None:
        lines.append("iterations %d;" % study["iterations"])
    lines += ["grid", "{", "    reposeAngle (%s);" % " ".join("%.6g" % v for v in g["reposeAngle"]),
              "    gasVelocity (%s);" % " ".join("%.6g" % v for v in g["gasVelocity"]), "}",
              'output "%s";' % output, 'work "%s";' % os.path.join(os.path.dirname(output), "work")]
    return "\n".join(lines) + "\n"


def preview(flights, out, say):
    """The section meshed once (drumSegmentCase -meshOnly, a second or two): its
    cells for the CPU estimate and flights.png for the report."""
    run = os.path.join(out, "plan", "segmentMesh")
    r = run_tied(["drumSegmentCase", "-dict", flights, "-out", run, "-meshOnly"], capture_output=True, text=True)
    if r.returncode != 0:
        msg = (r.stderr or r.stdout).strip()
        if r.returncode == 2:
            raise InputError("the segment's flight dictionary %s: %s" % (flights, msg))
        raise RunError("meshing the drum segment failed: %s" % msg)
    m = re.search(r"(\d+) cells", r.stdout)
    if not m:
        raise RunError("drumSegmentCase -meshOnly printed no cell count (%s)" % run)
    for line in r.stdout.splitlines():
        if line.startswith("drumSegmentMesh: "):
            say(line)
    return int(m.group(1)), os.path.join(run, "flights.png")


def cpu_estimate_s(g, cells, study):
    """The sweep's CPU: each run's cells times its local steps at the Invicta
    segments' measured cost per cell and step; the steps a statistical stop took
    there (on average) or the cap, whichever is fewer, plus a start-up per run."""
    with open(STOP_BENCHMARK, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["case"] != "total"]
    with open(SHIPPED_SEGMENT) as f:
        head = next(line for line in f if line.startswith("# mesh:"))
    shipped_cells = [int(c) for c in re.findall(r"(\d+) cells", head)]
    if not rows or not shipped_cells:
        raise RunError("%s or %s: no measured segment cost" % (STOP_BENCHMARK, SHIPPED_SEGMENT))
    def num(r, col):
        try:
            v = float(r[col])
        except (KeyError, TypeError, ValueError):
            v = float("nan")
        if not math.isfinite(v):
            raise RunError("%s: %s = '%s' of %s is not a number" % (STOP_BENCHMARK, col, r.get(col), r.get("case")))
        return v
    per_cell_step = sum(num(r, "fixed_cpu_s") / num(r, "fixed_steps") for r in rows) / len(rows) \
        / (sum(shipped_cells) / len(shipped_cells))
    steps = sum(num(r, "statistical_steps") for r in rows) / len(rows)
    cap = float(foamDictionary.value(os.path.join(TEMPLATE, "system", "controlDict"), "endTime"))
    if study["level"] != "coarse":
        cap *= 2          # drumSegmentCase: twice the steps at the finer levels
    steps = min(steps * cap / 900.0, cap if study["iterations"] is None else study["iterations"])
    estimate = runs(g) * (RUN_OVERHEAD_S + per_cell_step * cells * steps)
    if not (math.isfinite(estimate) and estimate > 0):
        raise RunError("%s, %s: the measured segment cost gives an estimate of %s s" % (STOP_BENCHMARK, SHIPPED_SEGMENT,
                                                                                   estimate))
    return estimate


def picture(work, g, out):
    """The middle run's section (segmentResults' section.png) as the report's
    curtain picture; its caption, or None."""
    phi = g["reposeAngle"][len(g["reposeAngle"]) // 2]
    V = g["gasVelocity"][len(g["gasVelocity"]) // 2]
    src = os.path.join(work, "phi%.6g_Vg%.6g" % (phi, V), "section.png")
    if not os.path.isfile(src):
        return None
    with open(src, "rb") as f:
        atomic_write(os.path.join(out, "curtain.png"), f.read())
    return ("The drum segment at a dynamic angle of repose of %g deg and V_g %g m/s: every releasing flight's "
            "curtain at once (table/work/phi%g_Vg%g, segmentResults)." % (phi, V, phi, V))


def table_figure(table, out):
    """segmentTable.png: V_c/V_g against the release angle, a curve per run."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from .. import files
    runs_ = {}
    with open(table, newline="") as f:
        for r in csv.DictReader(line for line in f if not line.startswith("#")):
            runs_.setdefault(r["case"], []).append((float(r["release_angle_deg"]), float(r["vc_over_vg"])))
    if not runs_:
        raise RunError("%s: no rows" % table)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for name, pts in sorted(runs_.items()):
        pts.sort()
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "-o", ms=3, label=name)
    ax.set_xlabel("release angle: the flight's root angle from the drum bottom [deg]")
    ax.set_ylabel("V_c / V_g in the flight's curtain")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("The drum segment table: the gas in each curtain, every flight releasing")
    fig.tight_layout()
    files.save_figure(fig, out, 100)
