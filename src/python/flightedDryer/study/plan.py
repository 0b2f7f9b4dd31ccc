"""plan: the drift table a dryer needs. The drum model is run once with Eq 142 and
drift.recordQueries, which gives the least and largest value of every table axis
it asks (its own unloading, falls and gas velocity); the grid reaches beyond them
by the study's margin, each fall on a floor of its own (a curtain ends on the bed),
in a box as wide as the drum, in the dryer's gas. The CPU estimate counts each
run's cells from the template's mesh level."""

import csv
import math
import os

from .. import PROJECT, facts, foamDictionary
from ..errors import InputError
from ..files import atomic_write
from ..processes import run_tied

TEMPLATES = os.path.join(PROJECT, "etc", "templates", "curtain")
# drums up to this diameter are laboratory or pilot scale: their falls are below
# what the wind-tunnel template resolves, and the laboratory-drum template (falls
# to 2 m) serves them
LAB_DRUM_DIAMETER = 2.0
# CPU per cell and iteration, and per run (set-up, blockMesh, the steady check),
# of a coarse curtainFoam run: tutorials/curtain/windTunnel/results/meshStudy.csv
# (steady_cpu_s over cells x steady_iterations) and the tools' own start-up
MESH_STUDY = os.path.join(PROJECT, "tutorials", "curtain", "windTunnel", "results", "meshStudy.csv")
# the Invicta box sweep from still gas: the iterations each run took to its steady stop
SWEEP_RUNS = os.path.join(PROJECT, "tests", "benchmarks", "warmStart", "results", "cases.csv")
RUN_OVERHEAD_S = 2.0


def queries(desc, case, say, drift="sherritt", section=None, what="Eq 142 pass", override=None):
    """{axis: (least, largest)} of the drift queries of the drum model on the
    description with the drift route given (drift.recordQueries on; default Eq 142),
    run in `case`; InputError naming the description on anything drumSolver refuses."""
    os.makedirs(case, exist_ok=True)
    atomic_write(os.path.join(case, "drumDict"), desc.drum_dict(drift, dict(section or {}, recordQueries=True),
                                                                override))
    r = run_tied(["drumSolver", "-case", case], capture_output=True, text=True)
    if r.returncode != 0:
        msg = (r.stderr or r.stdout).strip().replace(os.path.join(case, "drumDict"), desc.path)
        raise InputError(msg.replace("drumSolver: input error: ", ""))
    path = os.path.join(case, "results", "driftQueries.csv")
    if not os.path.isfile(path):
        raise InputError("%s: the drum model makes no drift queries (its flights release no curtains): "
                         "nothing for a drift table to serve" % desc.path)
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    say("the drum model's drift queries (%s): %s" % (what, ", ".join(
        "%s %.4g-%.4g" % (r["axis"], float(r["min"]), float(r["max"])) for r in rows)))
    return {r["axis"]: (float(r["min"]), float(r["max"])) for r in rows}


def union(a, b):
    """The extent of two sets of queries (an axis only one of them has, as it has it)."""
    return {k: (min(a[k][0], b[k][0]), max(a[k][1], b[k][1])) if k in a and k in b else a.get(k, b.get(k))
            for k in list(a) + [k for k in b if k not in a]}


def template(desc):
    """The curtain template of the dryer's scene: the wind tunnel's box (made as
    wide as the drum), or for a laboratory or pilot drum the laboratory-drum channel."""
    name = "labDrum" if float(desc.sections["drum"]["diameter"]) <= LAB_DRUM_DIAMETER else "windTunnel"
    return os.path.join("etc", "templates", "curtain", name)


def scene(q, desc, requested="box"):
    """What the drift needs, from the drum model's queries: {scene, route, why}.
    - none: no gas flows (every query at V_g 0): the gas drifts nothing, the drift
      along the drum is the incline's alone and no curtain run can change it;
    - lone: the densest release (the largest spill asked) leaves the flight below the
      solids fraction of a curtain's edge (particleDrag::curtainEdgeSolidsFraction):
      no part of any curtain shields the gas (a table would hold V_c/V_g 1 throughout),
      so lone particles are the curtain's answer;
    - box: the curtain shields the gas: a drift table of box curtains as wide as the drum;
    - drumSegment (on request, study.scene): the curtain shields the gas: a table of
      the drum's own cross-section, every releasing flight's curtain at once."""
    vmax = q["gas_velocity_m_s"][1]
    if not vmax > 0:
        return {"scene": "none", "route": "isolated",
                "why": "no gas flows (the drum model asks V_g %g m/s at most): the gas drifts nothing, so no "
                       "curtain run is needed; every drift route gives the incline's drift alone" % vmax}
    tpl = template(desc)
    cp = os.path.join(PROJECT, tpl, "system", "caseParameters")
    b, v = foamDictionary.scalar(cp, "thickness"), foamDictionary.scalar(cp, "releaseVelocity")
    smax, rho = q["spill_rate_kg_m_s"][1], q["particle_density_kg_m3"][1]
    alpha = facts.slot_solids_fraction(smax, rho, b, v)
    edge = facts.curtain_edge_solids_fraction()
    if alpha < edge:
        return {"scene": "lone", "route": "isolated",
                "why": "the densest release (spill %.4g kg/(m s) through the %g m layer at %g m/s) leaves the "
                       "flight at solids fraction %.3g, below a curtain's edge (%.3g): no curtain shields the gas, "
                       "so lone particles are the curtain's answer and no curtain run is needed"
                       % (smax, b, v, alpha, edge)}
    if requested == "drumSegment":
        return {"scene": "drumSegment", "route": "segment",
                "why": "the densest release (spill %.4g kg/(m s) through the %g m layer at %g m/s) leaves the flight at "
                       "solids fraction %.3g, above a curtain's edge (%.3g): the curtain shields the gas; the "
                       "description asks for the drum segment (study.scene), so the drift comes from the drum's own "
                       "cross-section, every releasing flight's curtain at once, V_c/V_g per release angle"
                       % (smax, b, v, alpha, edge)}
    return {"scene": "box", "route": "table",
            "why": "the densest release (spill %.4g kg/(m s) through the %g m layer at %g m/s) leaves the flight at "
                   "solids fraction %.3g, above a curtain's edge (%.3g): the curtain shields the gas, so the drift "
                   "comes from a table of box curtains (template %s) as wide as the drum"
                   % (smax, b, v, alpha, edge, os.path.basename(tpl))}


def _level(tpl, level):
    """The template's mesh entries of a level (nx, nz counts, ny and the height H)."""
    ml = os.path.join(PROJECT, tpl, "system", "meshLevels")
    keys = ("nxUp", "nxSlot", "nxDown", "ny", "nzSheet", "nzOut")
    v = {k: float(foamDictionary.value(ml, "levels/%s/%s" % (level, k))) for k in keys}
    v["H"] = foamDictionary.scalar(os.path.join(PROJECT, tpl, "system", "meshParameters"), "H")
    return v


def _log_nodes(lo, hi, ratio):
    """Nodes from lo to hi, evenly in ln, neighbours at most `ratio` apart."""
    if hi <= lo * (1 + 1e-9):
        return [lo]
    n = max(1, math.ceil(math.log(hi / lo) / math.log(ratio)))
    return [lo * (hi / lo) ** (k / n) for k in range(n + 1)]


def _round(v):
    return float("%.3g" % v)


def grid(q, desc, study):
    """The sweep's grid: gas velocity, spill rate, fall height (every fall a floor),
    the material's classes and density, the flight stagger."""
    m = study["margin"]
    tpl = template(desc)
    level = _level(tpl, study["level"])
    dy = level["H"] / level["ny"]
    D = float(desc.sections["drum"]["diameter"])
    vlo, vhi = q["gas_velocity_m_s"]
    slo, shi = q["spill_rate_kg_m_s"]
    ylo, yhi = q["fall_height_m"]
    gas = sorted({_round(v) for v in (vlo / (1 + m), vhi * (1 + m))})
    spill = sorted({_round(v) for v in _log_nodes(slo / (1 + m), min(shi * (1 + m), facts.max_spill_rate()),
                                                  study["spillRatio"])})
    top = min(yhi * (1 + m), D, level["H"])
    bottom = max(ylo / (1 + m), 2.05 * dy)
    if top <= bottom:
        raise InputError("%s: the falls %g-%g m lie below what the %s mesh resolves (%.3g m)"
                         % (desc.path, ylo, yhi, study["level"], 2.05 * dy))
    nf = max(2, math.ceil((top - bottom) / study["fallStep"]) + 1)
    falls = sorted({_round(bottom + (top - bottom) * k / (nf - 1)) for k in range(nf)})
    d = sorted({float("%.6g" % v) for v in (q["particle_diameter_m"])})
    mat = desc.sections["material"]
    sph = float(mat.get("sphericity", 1.0))
    # the table's diameters increase; each class keeps its mass fraction
    pairs = sorted(zip((float("%.6g" % (s * 1e-6 * sph)) for s in mat["sizes_um"]),
                       (float(x) / 100.0 for x in mat["fractions_pct"])))
    # normalised, as the drum model takes them (a printed distribution may sum to 99.8 %)
    sizes, fractions = [p[0] for p in pairs], [p[1] / sum(p[1] for p in pairs) for p in pairs]
    if min(sizes) > d[0] * (1 + 1e-6) or max(sizes) < d[-1] * (1 - 1e-6):
        raise InputError("%s: the drum model asks diameters %g-%g m outside the material's classes %g-%g m"
                         % (desc.path, d[0], d[-1], min(sizes), max(sizes)))
    return {"gasVelocity": gas, "spillRate": spill, "flightLength": [float("%.8g" % q["flight_length_m"][0])],
            "particleDensity": [q["particle_density_kg_m3"][0]], "fallHeight": falls,
            "diameter": sizes, "massFractions": fractions, "floors": falls, "level": level, "dy": dy,
            "template": tpl}


def covers(g, q):
    """The axes on which the grid misses a query (empty: it covers them all)."""
    miss = []
    for axis, key in (("gas_velocity_m_s", "gasVelocity"), ("spill_rate_kg_m_s", "spillRate"),
                      ("fall_height_m", "fallHeight")):
        lo, hi = q[axis]
        # below the smallest fall the table anchors the drift to 0 at y = 0
        if (key != "fallHeight" and lo < g[key][0] * (1 - 1e-9)) or hi > g[key][-1] * (1 + 1e-9):
            miss.append(axis)
    return miss


def runs(g):
    """The number of curtain runs: a grid point per gas velocity and spill, a run per floor."""
    return len(g["gasVelocity"]) * len(g["spillRate"]) * len(g["floors"])


def cpu_estimate_s(g, study):
    """The sweep's CPU time: each run's cells (the level's counts, the height scaled
    to its floor) times the iterations to a steady drift (the mean of the Invicta
    box sweep's runs from still gas, at most the limit) at the mesh study's cost
    per cell and iteration, plus a start-up per run."""
    with open(MESH_STUDY, newline="") as f:
        coarse = [r for r in csv.DictReader(f) if r["level"] == "coarse"][0]
    k = float(coarse["steady_cpu_s"]) / (float(coarse["cells"]) * float(coarse["steady_iterations"]))
    lv = g["level"]
    per_m = (lv["nxUp"] + lv["nxSlot"] + lv["nxDown"]) * (lv["nzSheet"] + lv["nzOut"]) / g["dy"]
    points = len(g["gasVelocity"]) * len(g["spillRate"])
    with open(SWEEP_RUNS, newline="") as f:
        taken = [float(r["cold_iterations"]) for r in csv.DictReader(f)]
    if not taken or not all(math.isfinite(x) and x > 0 for x in taken):
        raise InputError("%s: column cold_iterations must hold positive finite numbers (rerun "
                         "tests/benchmarks/warmStart/run)" % SWEEP_RUNS)
    its = min(sum(taken) / len(taken), study["iterations"])
    return points * sum(RUN_OVERHEAD_S + k * per_m * y * its for y in g["floors"])


def _list(values, form="%.6g"):
    return "(" + " ".join(form % v for v in values) + ")"


def box_width(desc):
    """The box's full width: the drum's diameter (a sheet in the drum has no more
    room to go round), at most curtainCase's 20 m."""
    return min(float(desc.sections["drum"]["diameter"]), 20.0)


def gas_temperature(desc):
    """The dryer's gas temperature, degC (the drum model's default 20 when not given)."""
    return float(desc.sections["gas"].get("temperature_C", 20.0))


def sweep_dict(g, desc, study, output):
    """The buildDriftTable dictionary of the grid."""
    gas = desc.sections["gas"]
    lines = ["FoamFile { version 2.0; format ascii; class dictionary; object dryerStudyTable; }",
             "// written by dryerStudy from %s" % desc.path,
             'template "%s";' % g["template"], "level %s;" % study["level"], "drag %s;" % study["drag"],
             "iterations %d;" % study["iterations"],
             "gasTemperature %.6g;" % gas_temperature(desc)]
    if "pressure_kPa" in gas:
        lines.append("gasPressure %.6g;" % float(gas["pressure_kPa"]))
    lines += ["boxWidth %.6g;" % box_width(desc),
              "grid", "{",
              "    gasVelocity %s;" % _list(g["gasVelocity"]), "    spillRate %s;" % _list(g["spillRate"]),
              "    flightLength %s;" % _list(g["flightLength"]),
              "    particleDensity %s;" % _list(g["particleDensity"]),
              "    fallHeight %s;" % _list(g["fallHeight"]), "    diameter %s;" % _list(g["diameter"]), "}",
              "massFractions %s;" % _list(g["massFractions"], "%.8g"), "floors %s;" % _list(g["floors"]),
              'output "%s";' % output, 'work "%s";' % os.path.join(os.path.dirname(output), "work")]
    return "\n".join(lines) + "\n"
