"""plan: the sweep's runs: one curtainCase run per grid point and floor (box), or
one drum segment per repose angle and gas velocity; their folders, arguments
and names; whether a run is finished with these inputs (resume); its result."""

import csv
import hashlib
import itertools
import json
import os

from .. import PROJECT
from ..errors import InputError
from ..messages import g6
from .settings import ARGS, DEFAULT_TEMPLATE, RESULT, RUN_AXES, SEGMENT_TEMPLATE


def floor_of(s, h):
    """The floor a fall height is read at: the lowest at or above it."""
    return min(f for f in s["floors"] if f >= h)


def segment_cases(s):
    """One drum segment per (dynamic angle of repose, gas velocity), named as
    writeSegmentTable records it (phi<deg>_Vg<m/s>)."""
    out = []
    for phi, V in itertools.product(s["grid"]["reposeAngle"], s["grid"]["gasVelocity"]):
        args = ["-scene", "drumSegment", "-flights", s["flights"], "-reposeAngle", g6(phi),
                "-gasVelocity", g6(V), "-level", s["level"], "-ends", s["ends"]]
        if s["iterations"]:
            args += ["-iterations", str(s["iterations"])]
        if s["drag"] != "SchillerNaumann":
            args += ["-drag", s["drag"]]
        if s["stop"] == "fixed" and s["ends"] == "periodic":
            args += ["-stop", "fixed"]
        if s["segmentLength"] is not None:
            args += ["-segmentLength", "%.12g" % s["segmentLength"]]
        for entry, opt in (("particleDensity", "-density"), ("diameter", "-diameters"),
                           ("gasTemperature", "-gasTemperature"), ("gasPressure", "-gasPressure")):
            if s.get(entry) is not None:
                args += [opt, "%.12g" % s[entry]]
        if os.path.realpath(s["template"]) != os.path.realpath(os.path.join(PROJECT, SEGMENT_TEMPLATE)):
            args += ["-template", s["template"]]
        out.append({"name": "phi%s_Vg%s" % (g6(phi), g6(V)), "phi": phi, "V": V, "args": args})
    if s.get("warmStart"):
        # (a segment run keeps its fields: no -keep)
        link_chains(s, out, keep=False)
    return out


def run_axes(s):
    return ["reposeAngle", "gasVelocity"] if s["scene"] == "drumSegment" else RUN_AXES


def cases_of(s):
    if s["scene"] == "drumSegment":
        return segment_cases(s)
    g = s["grid"]
    cases = [box_case(s, V, S, L, rho, Y)
             for V, S, L, rho in itertools.product(g["gasVelocity"], g["spillRate"], g["flightLength"],
                                                   g["particleDensity"])
             for Y in s["floors"]]
    if s.get("warmStart"):
        link_chains(s, cases, keep=True)
    return cases


def link_chains(s, cases, keep):
    """warmStart: each run of a chain starts from the one before it (-startFrom its
    folder), which keeps its fields for it (-keep) where a run would drop them."""
    for chain in chains_of(s, cases):
        for a, b in zip(chain, chain[1:]):
            if keep:
                a["args"] = a["args"] + ["-keep"]
            b["args"] = b["args"] + ["-startFrom", case_dir(s, a)]
            b["parent"] = a["name"]


def units(s, cases):
    """What one worker runs in order: a warm-start chain (warmStart), else one case;
    the local pool's jobs and the Slurm array's tasks."""
    return chains_of(s, cases) if s.get("warmStart") else [[c] for c in cases]


def chains_of(s, cases):
    """warmStart: the runs that share a mesh (a flight length, density and floor; with a
    packed layer also a spill rate, which sets the layer) in one chain, each run
    starting from the one before it: the gas velocities in turn, the spill rates up
    and down in turn (neighbours on the grid). Fixed by the plan, so the local pool,
    -jobs N and Slurm start every run from the same fields. A list of chains, each a
    list of the cases in order."""
    if s["scene"] == "drumSegment":
        # a repose angle's segments release from the same flights: one chain, the gas
        # velocities in turn (the mesh is the section's, the same for every run)
        chains = {}
        for c in cases:
            chains.setdefault(c["phi"], []).append(c)
        return [sorted(chains[k], key=lambda c: c["V"]) for k in sorted(chains)]
    groups = {}
    for c in cases:
        key = (c["L"], c["rho"], c["floor"]) + ((c["S"],) if s.get("layerThickness") == "packed" else ())
        groups.setdefault(key, []).append(c)
    vs = sorted({c["V"] for c in cases})
    out = []
    for key in sorted(groups):
        def order(c):
            i = vs.index(c["V"])
            return (i, c["S"] if i % 2 == 0 else -c["S"])
        out.append(sorted(groups[key], key=order))
    return out


def box_case(s, V, S, L, rho, Y):
    """The curtainCase run of one grid point with its floor at Y: a measuring plane at
    every lower fall height; it serves the fall heights read at that floor."""
    g = s["grid"]
    name = "V%s_S%s_L%s_rho%s" % (g6(V), g6(S), g6(L), g6(rho))
    if Y != s["floors"][-1]:
        name += "_H%s" % g6(Y)
    others = [h for h in g["fallHeight"] if h < Y]
    args = ["-gasVelocity", g6(V), "-spillRate", g6(S), "-fallHeight", g6(Y),
            "-flightLength", g6(L), "-density", g6(rho),
            "-diameters", ",".join("%.8g" % x for x in g["diameter"]),
            "-fractions", ",".join("%.8g" % x for x in s["fractions"])]
    if others:
        args += ["-heights", ",".join(g6(h) for h in others)]
    args += ["-level", s["level"], "-drag", s["drag"]]
    if s["particleTurbulence"] != "none":
        args += ["-particleTurbulence", s["particleTurbulence"]]
    if s["wakeShare"] is not None:
        args += ["-wakeShare", "%.12g" % s["wakeShare"]]
    if s["turbulence"]:
        args += ["-turbulence", s["turbulence"]]
    if s["iterations"]:
        args += ["-iterations", str(s["iterations"])]
    if s["steadyFrom"] is not None:
        args += ["-steadyFrom", str(s["steadyFrom"])]
    if s["gasTemperature"] is not None:
        args += ["-gasTemperature", "%.12g" % s["gasTemperature"]]
    if s["gasPressure"] is not None:
        args += ["-gasPressure", "%.12g" % s["gasPressure"]]
    if s["boxWidth"] is not None:
        args += ["-boxWidth", "%.12g" % s["boxWidth"]]
    if s["layerThickness"] == "packed":
        args += ["-layerThickness", "packed", "-bulkDensity", "%.12g" % s["bulkDensity"]]
    elif s["layerThickness"] is not None:
        args += ["-layerThickness", "%.12g" % s["layerThickness"]]
    if os.path.realpath(s["template"]) != os.path.realpath(os.path.join(PROJECT, DEFAULT_TEMPLATE)):
        args += ["-template", s["template"]]
    return {"name": name, "V": V, "S": S, "L": L, "rho": rho, "args": args, "floor": Y,
            "serves": [h for h in g["fallHeight"] if floor_of(s, h) == Y]}


def case_dir(s, c):
    return os.path.join(s["work"], c["name"])


def case_log(s, c):
    """The case's log (a drum segment's folder is drumSegmentCase's own: its log is beside it)."""
    if s["scene"] == "drumSegment":
        return os.path.join(s["work"], c["name"] + ".log")
    return os.path.join(case_dir(s, c), "log.curtainCase")


def case_args(s, c, np_):
    a = ["-dir", case_dir(s, c)] + c["args"]
    if np_ > 1:
        a += ["-np", str(np_)]
    return a


def finished(s, c):
    """A case is finished when its result exists and was made with these inputs."""
    d = case_dir(s, c)
    if s["scene"] == "drumSegment":
        # drumSegmentCase records the inputs' signature of a finished run
        try:
            with open(os.path.join(d, ".drumSegmentCase")) as f:
                have = f.read().split()
        except OSError:
            return False
        if not os.path.isfile(os.path.join(d, "curtains.csv")) or len(have) != 2 or have[0] != "inputs":
            return False
        return "inputs" not in c or have[1] == c["inputs"]
    res = os.path.join(d, RESULT)
    meta = os.path.join(d, ARGS)
    if not (os.path.isfile(res) and os.path.isfile(meta)):
        return False
    try:
        with open(meta) as f:
            info = json.load(f)
        argv = info["argv"]
    except (OSError, ValueError, KeyError, TypeError):
        return False
    if "inputs" in c and info.get("inputs") != c["inputs"]:
        return False
    # -np does not change the answer
    strip = []
    i = 0
    while i < len(argv):
        if argv[i] == "-np":
            i += 2
            continue
        strip.append(argv[i])
        i += 1
    return strip == ["-dir", d] + c["args"]


def read_result(s, c):
    path = os.path.join(case_dir(s, c), RESULT)
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    table = {}
    cells = None
    try:
        with open(os.path.join(case_dir(s, c), ARGS)) as f:
            wall = float(json.load(f).get("wall_time_s", 0))
    except (OSError, ValueError, TypeError):
        wall = 0.0
    for r in rows:
        if r["class"] == "bulk":
            continue
        key = (float(r["fall_height_m"]), float(r["diameter_m"]))
        table[key] = r
        cells = int(r["cells"])
    for h in c["serves"]:
        for dd in s["grid"]["diameter"]:
            if not _find(table, h, dd):
                raise InputError("%s: no row for fall height %g m, diameter %g m" % (path, h, dd))
    return table, cells, wall


def _find(table, h, d):
    for (hh, dd), r in table.items():
        if abs(hh - h) <= 1e-9 * max(1, h) and abs(dd - d) <= 1e-6 * d:
            return r
    return None


def grid_key(cases):
    """The signature of a sweep's runs (their arguments): the sweep's wall time adds
    up over resumed runs of the same grid; another grid starts the count again."""
    return hashlib.sha1(json.dumps([c["args"] for c in cases]).encode()).hexdigest()
