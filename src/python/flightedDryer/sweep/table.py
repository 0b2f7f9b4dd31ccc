"""table: the drift table written from the sweep's finished runs: rows per grid
point, fall height and class (a grid point whole or not at all), the tunnel's
reading where the runs are the wind tunnel itself, and the header; the one
writer of the format (writeDriftTable, C++) checks and writes it. A drum-segment
sweep's table is writeSegmentTable's."""

import csv
import json
import math
import os
import subprocess

from .. import PROJECT, foamDictionary
from ..curtain.settings import PACKED_SLOT_FRACTION
from ..errors import InputError
from ..files import atomic_write
from ..messages import g6
from .dictionary import air_properties
from .plan import _find, case_dir, read_result
from .settings import DEFAULT_TEMPLATE, LANDING, ARGS, axes


def in_wind_tunnel(s):
    """Whether the sweep's cases are Sherritt's wind tunnel itself (the default
    template at its own width): then the table carries the tunnel's reading."""
    return (s["boxWidth"] is None
            and os.path.realpath(s["template"]) == os.path.realpath(os.path.join(PROJECT, DEFAULT_TEMPLATE)))


def tunnel_reading(s, c):
    """(fall height, class index) -> what the wind tunnel would record for that class
    of the case: windTunnelDrift -tunnelReading, the one implementation of Sherritt's
    collection rule (1991 section 4.3.1), on the case's landing distribution."""
    landing = os.path.join(case_dir(s, c), LANDING)
    out = os.path.join(case_dir(s, c), "tunnelReading.csv.part")
    try:
        r = subprocess.run(["windTunnelDrift", "-tunnelReading", landing, "-out", out],
                           capture_output=True, text=True)
        if r.returncode != 0:
            raise InputError("%s: %s" % (c["name"], (r.stderr or r.stdout).strip()))
        with open(out, newline="") as f:
            return {(float(x["fall_height_m"]), int(float(x["class_index"]))): float(x["tunnel_drift_m"])
                    for x in csv.DictReader(f)}
    finally:
        if os.path.exists(out):
            os.remove(out)


def _number(text):
    """A number for sorting, words (nan) last."""
    try:
        return (0, float(text))
    except ValueError:
        return (1, 0.0)


def git_version():
    r = subprocess.run(["git", "-C", PROJECT, "describe", "--always", "--dirty", "--tags"],
                       capture_output=True, text=True)
    return r.stdout.strip() if r.returncode == 0 and r.stdout.strip() else "unknown"


def sweep_gas(s, val):
    """The header's gas: the template's air, or air at gasTemperature (20 degC) and gasPressure."""
    if s["gasTemperature"] is None and s["gasPressure"] is None:
        return "air(rho=%s,nu=%s)" % (val("constant/transportProperties", "rho"),
                                      val("constant/transportProperties", "nu"))
    t = 20.0 if s["gasTemperature"] is None else s["gasTemperature"]
    rho, nu = air_properties(t, s["gasPressure"])
    return "air(rho=%s,nu=%s,T=%.6gC%s)" % (rho, nu, t, "" if s["gasPressure"] is None
                                            else ",p=%.6gkPa" % s["gasPressure"])


def sweep_layer(s, val):
    """The header's release layer: the template's, the entry's, or packed at the bulk density."""
    if s["layerThickness"] == "packed":
        return "packed(bulk_density=%.6gkg/m3,max_slot_fraction=%g)" % (s["bulkDensity"], PACKED_SLOT_FRACTION)
    if s["layerThickness"] is not None:
        return "%.6g" % s["layerThickness"]
    return val("system/caseParameters", "thickness")


def template_fixed(s):
    def val(rel, entry):
        return foamDictionary.value(os.path.join(s["template"], rel), entry, default="?")
    turb = s["turbulence"] or val("constant/turbulenceProperties.air", "RAS/RASModel")
    if turb == "?":
        turb = val("constant/turbulenceProperties.air", "simulationType")
    return {
        "release_velocity_m_s": val("system/caseParameters", "releaseVelocity"),
        "layer_thickness_m": sweep_layer(s, val),
        "gas": sweep_gas(s, val),
        "drag": s["drag"],
        "turbulence": turb,
        "particle_turbulence": s["particleTurbulence"] + (
            "(Cp=%.6g)" % s["wakeShare"] if s["wakeShare"] is not None else ""),
        "class_mass_fractions": ",".join("%.6g" % w for w in s["fractions"]),
        "template": os.path.relpath(s["template"], PROJECT),
        "domain": "halfTunnel(length=%s,width=2x%s,slotStart=%s,height=%s)"
                  % (val("system/meshParameters", "Lt"),
                     val("system/meshParameters", "W") if s["boxWidth"] is None else "%.6g" % (0.5 * s["boxWidth"]),
                     val("system/meshParameters", "xs"),
                     "maxFallHeight" if len(s["floors"]) == 1
                     else "floors(%s)" % ",".join(g6(f) for f in s["floors"])),
        "iterations": str(s["iterations"] or "template"),
    }


def outlet_distance(s, L):
    mp = os.path.join(s["template"], "system", "meshParameters")
    def val(entry):
        return foamDictionary.scalar(mp, entry)
    return val("Lt") - (val("xs") + 0.5 * L)


def write_segment_table(s, cases, ok, out):
    """The drum model's segment table of the finished segments (writeSegmentTable: the
    one writer of the dryerSegmentTable format, whole or not at all)."""
    runs = [case_dir(s, c) for c in cases if c["name"] in ok]
    r = subprocess.run(["writeSegmentTable", "-o", out] + runs, capture_output=True, text=True)
    if r.returncode != 0:
        raise InputError((r.stderr or r.stdout).strip())
    with open(out) as f:
        return sum(1 for line in f if line.strip() and not line.startswith("#")) - 1


def write_table(s, cases, ok, failed, elapsed, out):
    if s["scene"] == "drumSegment":
        return write_segment_table(s, cases, ok, out)
    g = s["grid"]
    varied = [a for a in axes() if len(g[a[0]]) > 1]
    rows = []
    cells = {}   # floor -> cells of its runs
    iterations = set()
    n_bound = 0
    n_dilute = 0
    tunnel = in_wind_tunnel(s)
    # a grid point is written whole or not at all: a failed run of one floor leaves out
    # its other floors' rows too (the missing line names the failed run)
    incomplete = {(c["V"], c["S"], c["L"], c["rho"]) for c in cases if c["name"] not in ok}
    for c in cases:
        if (c["V"], c["S"], c["L"], c["rho"]) in incomplete:
            continue
        table, cells_c, _ = read_result(s, c)
        reading = tunnel_reading(s, c) if tunnel else None
        cells.setdefault(c["floor"], cells_c)
        for h in c["serves"]:
            for d in g["diameter"]:
                r = _find(table, h, d)
                iterations.add(r["iterations"])
                drift = float(r["drift_m"])
                if not math.isfinite(drift):
                    # nothing of the class crosses this height inside the domain: it
                    # left by the outlet first. Its drift is at least the distance
                    # from the slot's centre to the outlet (the wind tunnel's own
                    # convention for lost material, Sherritt 1991 section 4.3.1)
                    if float(r["captured_fraction"]) > 1e-3:
                        raise InputError("%s: drift nan with captured fraction %s at %g m, %g m"
                                        % (c["name"], r["captured_fraction"], h, d))
                    drift = outlet_distance(s, c["L"])
                    n_bound += 1
                vc = float(r["vc_over_vg"])
                if not math.isfinite(vc):
                    # no cell as dense as the curtain edge: nothing shields the gas
                    vc = 1.0
                    n_dilute += 1
                rows.append([c["name"], c["V"], c["S"], h, c["L"], c["rho"],
                             d, vc, drift, float(r["captured_fraction"])])
                if tunnel:
                    hits = [v for (hh, i), v in reading.items()
                            if abs(hh - h) <= 1e-9 * max(1, h) and "c%d" % i == r["class"]]
                    if len(hits) != 1:
                        raise InputError("%s: %s has no tunnel reading of class %s at %g m"
                                        % (c["name"], LANDING, r["class"], h))
                    rows[-1].append(hits[0])
    # the header as (key, value) pairs, in the format's order; the one drift-table
    # writer (C++, src/drum/drift/driftTableFile.hpp) adds the magic line, checks the
    # table as its reader would and writes it atomically
    header = [["generator", "buildDriftTable %s ; solver curtainFoam ; OpenFOAM v1912" % git_version()],
              ["dictionary", os.path.relpath(s["dict"], PROJECT)]]
    if s["material"]:
        header.append(["material", s["material"]])
    header.append(["axes", " ".join(a[1] for a in varied)])
    for name, col, _ in axes():
        header.append(["range " + col, "%.8g %.8g" % (min(g[name]), max(g[name]))])
    fixed = template_fixed(s)
    for name, col, _ in axes():
        if len(g[name]) == 1:
            fixed[col] = "%.8g" % g[name][0]
    header.append(["fixed", " ".join("%s=%s" % kv for kv in fixed.items())])
    floors = sorted(cells)
    if len(floors) > 1:
        mesh = "%s (%s cells at the floors %s m)" % (s["level"], ", ".join(str(cells[f]) for f in floors),
                                                     ", ".join(g6(f) for f in floors))
    else:
        mesh = "%s (%s cells)" % (s["level"], cells[floors[0]] if floors else "?")
    header.append(["mesh", mesh])
    n_fail = len(cases) - len(ok)
    header.append(["cases", "%d (%d converged, %d failed)" % (len(cases), len(ok), n_fail)])
    edges = set()
    for c in cases:
        if c["name"] in ok:
            try:
                with open(os.path.join(case_dir(s, c), ARGS)) as f:
                    edges.add("%g" % float(json.load(f)["alpha_edge"]))
            except (OSError, ValueError, KeyError, TypeError):
                edges.add("?")
    edge = "/".join(sorted(edges))
    header.append(["vc_over_vg", "solids-weighted mean gas velocity along the flow inside the curtain "
                   "(solids fraction >= %s) between the release and that fall height, over V_g" % edge])
    header.append(["drift_m", "mass-weighted mean displacement along the gas flow of the part of the class "
                   "crossing that fall height inside the domain; captured_fraction: that part's share of "
                   "the class's slot flux (below 1: the rest left by the outlet first and went further)"])
    header.append(["iterations", "%s ; converged: drift steady to 1 %%, V_c/V_g to 5 %% (curtainCase)%s"
                   % (",".join(sorted(iterations, key=_number)),
                      " ; warm start: each run of a mesh from the fields of the one before it (warmStart yes)"
                      if s.get("warmStart") else "")])
    header.append(["drift_bound", "where drift is undefined (captured_fraction below 1e-3, %d rows) the class left "
                   "the domain before that height and drift_m is the distance from the slot centre to the outlet, "
                   "a lower bound" % n_bound])
    if len(s["floors"]) > 1:
        header.append(["floors", "%s m: each the floor of runs of its own (case suffix _H<floor>, the largest none); "
                       "a fall height is read at the lowest floor at or above it" % " ".join(g6(f) for f in s["floors"])])
    if tunnel:
        header.append(["tunnel_drift_m", "the class's advance as Sherritt's wind tunnel would have recorded it "
                       "(1991 section 4.3.1): what crossed that fall height over the first 7.5 m at its centre of "
                       "gravity, over the next 3.8 m at 9.4 m, the rest of the slot flux (left by the outlet) at "
                       "11.3 m, minus the release centre (windTunnelDrift -tunnelReading on the case's %s)"
                       % LANDING])
    header.append(["vc_dilute", "where no cell reaches the curtain edge (solids fraction %s; %d rows) "
                   "the curtain does not shield the gas and vc_over_vg is 1" % (edge, n_dilute)])
    miss = ["%s gas_velocity_m_s=%s spill_rate_kg_m_s=%s flight_length_m=%s particle_density_kg_m3=%s (%s)"
            % (c["name"], g6(c["V"]), g6(c["S"]), g6(c["L"]), g6(c["rho"]),
               failed.get(c["name"], "not run").replace(";", ","))
            for c in cases if c["name"] not in ok]
    if miss:
        header.append(["missing", " ; ".join(miss)])
    sweep = out + ".sweep.json"
    atomic_write(sweep, json.dumps({"header": header, "rows": rows}) + "\n")
    try:
        r = subprocess.run(["writeDriftTable", "-in", sweep, "-out", out], capture_output=True, text=True)
    finally:
        os.remove(sweep)
    if r.returncode != 0:
        raise InputError((r.stderr or r.stdout).strip())
    return len(rows)
