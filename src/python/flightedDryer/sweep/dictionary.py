"""dictionary: the sweep dictionary (OpenFOAM format) read strictly into the sweep's
settings: box scene (a grid of gas velocity, spill, flight length, density, fall
height and diameter, with floors, the gas, the layer and the material) or
drumSegment scene (a grid of repose angles and gas velocities)."""

import os
import subprocess

from .. import PROJECT, facts, gas
from ..errors import InputError
from ..messages import g6
from ..strictDict import StrictDict, check_allowed
from ..segment.inputs import GAS_VELOCITY_RANGE, REPOSE_RANGE
from .settings import (DEFAULT_TEMPLATE, GRID_KEYS, SCENES, SEGMENT_GRID_KEYS, SEGMENT_TEMPLATE,
                       SEGMENT_TOP_KEYS, TOP_KEYS, axes, say)


def check_keys(path, top, scene):
    """Unknown or duplicated entries are refused, with the nearest allowed name
    (the allowed entries are the scene's)."""
    top_keys, grid_keys = (TOP_KEYS, GRID_KEYS) if scene == "box" else (SEGMENT_TOP_KEYS, SEGMENT_GRID_KEYS)
    return check_allowed(path, top, top_keys, grid_keys, "grid",
                         note=lambda key: " (an entry of scene box)" if scene != "box" and key in TOP_KEYS else "",
                         sub_note=" (scene %s)" % scene)


def outputs(d, s, default_output):
        """The table (relative to the dictionary's folder) and the work folder (relative to
        the project, default run/driftTable/<dictionary name>) into s."""
        out = d.string("output", default_output)
        if not out.strip():
            raise InputError("%s: entry 'output' is empty: a file name for the table (relative to "
                            "the dictionary's folder)" % d.where("output"))
        s["output"] = os.path.normpath(os.path.join(os.path.dirname(d.path), out))
        s["work"] = os.path.normpath(os.path.join(PROJECT, d.string(
            "work", os.path.join("run", "driftTable", os.path.basename(d.path)))))


def read_gas(d, s):
    """gasTemperature (degC) and gasPressure (kPa) into s (None when not given), in the
    tools' ranges, the air at them asked of airProperties (a temperature that looks
    like kelvin warned, naming the entry)."""
    s["gasTemperature"] = d.scalar("gasTemperature", *facts.gas_temperature_range(), units="degC") \
        if d.has("gasTemperature") else None
    s["gasPressure"] = d.scalar("gasPressure", *facts.gas_pressure_range(), units="kPa") \
        if d.has("gasPressure") else None
    if s["gasTemperature"] is not None or s["gasPressure"] is not None:
        where = d.where("gasTemperature" if s["gasTemperature"] is not None else "gasPressure")
        try:
            gas.air_properties(20.0 if s["gasTemperature"] is None else s["gasTemperature"], s["gasPressure"],
                               entry="gasTemperature", warn=lambda w: say("warning: %s: %s" % (where, w)))
        except gas.GasError as e:
            raise InputError("%s: entries 'gasTemperature', 'gasPressure': %s" % (where, e))


def read_sweep(dict_path):
    """The sweep's settings (a dict) from its dictionary; InputError naming the
    file, line and entry on anything not allowed."""
    d = StrictDict(dict_path)
    d.scene = d.word("scene", "box", allowed=SCENES)
    check_keys(d.path, d.lines, d.scene)
    if d.scene == "drumSegment":
        return read_segment_sweep(d)
    s = {"dict": d.path, "scene": "box"}
    s["template"] = d.folder("template", DEFAULT_TEMPLATE)
    s["level"] = d.word("level", "coarse")
    s["drag"] = d.word("drag", "SchillerNaumann", allowed=list(facts.drag_laws()))
    s["particleTurbulence"] = d.word("particleTurbulence", "none",
                                     allowed=["none", "Simonin", "SimoninCrowe"])
    s["turbulence"] = d.word("turbulence", allowed=["kEpsilon", "realizableKE", "kOmegaSST"]) \
        if d.has("turbulence") else None
    s["wakeShare"] = None
    if d.has("wakeShare"):
        if s["particleTurbulence"] != "SimoninCrowe":
            raise InputError("%s: entry 'wakeShare' belongs to particleTurbulence SimoninCrowe (here %s)"
                            % (d.where("wakeShare"), s["particleTurbulence"]))
        s["wakeShare"] = d.scalar("wakeShare", 0, 1)
    read_gas(d, s)
    s["boxWidth"] = d.scalar("boxWidth", 0, 20, "m") if d.has("boxWidth") else None
    # each run of a mesh from its neighbour's fields (plan.chains_of), or from still gas
    s["warmStart"] = d.word("warmStart", "no", allowed=["yes", "no"]) == "yes"
    s["iterations"] = d.whole("iterations", 9, 100000)
    # the first iteration a run may be judged steady at (curtainCase -steadyFrom)
    s["steadyFrom"] = d.whole("steadyFrom", 0, s["iterations"] or 100000)
    s["layerThickness"] = None
    if d.has("layerThickness"):
        # packed or a thickness; curtainCase -check gives each case's final word
        s["layerThickness"] = "packed" if d.value("layerThickness") == "packed" else \
            d.scalar("layerThickness", 0, 0.2, "m (or packed)")
    if d.has("bulkDensity") and s["layerThickness"] != "packed":
        raise InputError("%s: entry 'bulkDensity' belongs to 'layerThickness packed'" % d.where("bulkDensity"))
    ranges = {
        "gasVelocity": (0, 50, "m/s"), "spillRate": (0, facts.max_spill_rate(), "kg/(m s)"),
        "fallHeight": (0, 1000, "m"), "flightLength": (0, 100, "m"),
        "particleDensity": (0, 25000, "kg/m3"), "diameter": (0, 0.05, "m"),
    }
    classes = None
    if d.has("sizeClasses"):
        d.word("sizeClasses", allowed=["material"])
        if not d.has("material"):
            raise InputError("%s: entry 'sizeClasses material' needs the entry 'material' (a material of "
                            "windtunnel_materials.csv)" % d.where("sizeClasses"))
        for e in ("grid/diameter", "massFractions"):
            if d.has(e):
                raise InputError("%s: entry '%s' is what 'sizeClasses material' generates "
                                "(windTunnelDrift -sizeClasses): remove one of them" % (d.where(e), e))
        classes = material_classes(d, d.word("material"))
    s["grid"] = {}
    for name, _, _ in axes():
        lo, hi, units = ranges[name]
        if name == "diameter" and classes:
            s["grid"][name] = classes["diameter"]
            continue
        s["grid"][name] = d.scalar_list("grid/" + name, lo, hi, units)
    if classes and (len(s["grid"]["particleDensity"]) != 1
                    or abs(s["grid"]["particleDensity"][0] - classes["particleDensity"]) > 1e-9 * classes["particleDensity"]):
        raise InputError("%s: entry 'grid/particleDensity' must be the material's own density, %g kg/m3 "
                        "(windtunnel_materials.csv)" % (d.where("grid/particleDensity"), classes["particleDensity"]))
    nd = len(s["grid"]["diameter"])
    s["fractions"] = classes["massFractions"] if classes else \
        d.scalar_list("massFractions", -1e-300, 1, "", increasing=False)
    if len(s["fractions"]) != nd:
        raise InputError("%s: entry 'massFractions' has %d values for %d diameters (one each)"
                        % (d.path, len(s["fractions"]), nd))
    if abs(sum(s["fractions"]) - 1) > 1e-3:
        raise InputError("%s: entry 'massFractions' sums to %g, allowed range [0.999, 1.001]"
                        % (d.path, sum(s["fractions"])))
    s["material"] = None
    if d.has("material"):
        m = d.word("material")
        if not all(ch.isalnum() or ch in "_-." for ch in m):
            raise InputError("%s: entry 'material' = '%s': letters, digits, '_', '-' and '.' only"
                            % (d.path, m))
        if len(s["grid"]["particleDensity"]) != 1:
            raise InputError("%s: entry 'material' names one material, but grid/particleDensity has %d "
                            "values (a material has one density)" % (d.path, len(s["grid"]["particleDensity"])))
        s["material"] = m
    s["bulkDensity"] = None
    if s["layerThickness"] == "packed":
        if classes and d.has("bulkDensity"):
            raise InputError("%s: entry 'bulkDensity' is the material's own with 'sizeClasses material' "
                            "(%g kg/m3, windtunnel_materials.csv): remove it" % (d.where("bulkDensity"),
                                                                                  classes["bulkDensity"]))
        if classes:
            s["bulkDensity"] = classes["bulkDensity"]
        elif d.has("bulkDensity"):
            s["bulkDensity"] = d.scalar("bulkDensity", 0, min(s["grid"]["particleDensity"]),
                                        "kg/m3 (at most the smallest particle density)")
        else:
            raise InputError("%s: entry 'layerThickness packed' needs the entry 'bulkDensity' (kg/m3)"
                            % d.where("layerThickness"))
    s["floors"] = read_floors(d, s["grid"]["fallHeight"])
    outputs(d, s, "driftTable.csv")
    return s


def read_floors(d, heights):
    """The entry floors: fall heights of the grid, increasing; the largest fall height
    is always one (added when not listed)."""
    top = max(heights)
    if not d.has("floors"):
        return [top]
    floors = d.scalar_list("floors", 0, 1000, "m")
    for f in floors:
        if not any(abs(f - h) <= 1e-9 * max(1, h) for h in heights):
            raise InputError("%s: entry 'floors': %g m is not a fall height of grid/fallHeight (%s)"
                            % (d.where("floors"), f, " ".join(g6(h) for h in heights)))
    floors = [min(heights, key=lambda h: abs(h - f)) for f in floors]
    return floors if floors[-1] == top else floors + [top]


def floor_of(s, h):
    """The floor a fall height is read at: the lowest at or above it."""
    return min(f for f in s["floors"] if f >= h)


def read_segment_sweep(d):
    """scene drumSegment: the flight dictionary, the segment's settings and the grid of
    dynamic angles of repose and gas velocities (drumSegmentCase's ranges)."""
    s = {"dict": d.path, "scene": "drumSegment", "material": None}
    s["flights"] = os.path.normpath(os.path.join(PROJECT, d.string("flights")))
    if not os.path.isfile(s["flights"]):
        raise InputError("%s: entry 'flights': no flight dictionary %s" % (d.where("flights"), s["flights"]))
    s["template"] = d.folder("template", SEGMENT_TEMPLATE)
    s["level"] = d.word("level", "coarse", allowed=["coarse", "medium", "fine"])
    s["ends"] = d.word("ends", "periodic", allowed=["periodic", "open"])
    s["drag"] = d.word("drag", "SchillerNaumann", allowed=list(facts.drag_laws()))
    # periodic ends stop when their means are known (drumSegmentCase -stop statistical)
    s["stop"] = d.word("stop", "statistical" if s["ends"] == "periodic" else "fixed",
                       allowed=["statistical", "fixed"])
    if s["stop"] == "statistical" and s["ends"] != "periodic":
        raise InputError("%s: entry 'stop' statistical needs ends periodic (open ends have a steady state)"
                         % d.where("stop"))
    s["iterations"] = d.whole("iterations", 30, 100000, multiple=3,
                              why=": the most steps; with stop fixed the means over the last third")
    s["segmentLength"] = None
    if d.has("segmentLength"):
        s["segmentLength"] = d.scalar("segmentLength", 0.1, 100, "m")
    # the particles and the gas (default: the template's: the Invicta crystal in air at 80 degC)
    s["particleDensity"] = d.scalar("particleDensity", 10, 25000, "kg/m3") if d.has("particleDensity") else None
    s["diameter"] = d.scalar("diameter", 1e-6, 0.05, "m") if d.has("diameter") else None
    read_gas(d, s)
    # each segment of a repose angle from the one at the gas velocity before it
    s["warmStart"] = d.word("warmStart", "no", allowed=["yes", "no"]) == "yes"
    s["grid"] = {"reposeAngle": d.scalar_list("grid/reposeAngle", *REPOSE_RANGE, "deg", lo_closed=True),
                 "gasVelocity": d.scalar_list("grid/gasVelocity", *GAS_VELOCITY_RANGE, "m/s", lo_closed=True)}
    outputs(d, s, "segmentTable.csv")
    return s


def air_properties(t, p=None):
    """(rho, nu) of dry air at t degC and p kPa (None: 1 atm) as text (flightedDryer.gas,
    as curtainCase -gasTemperature/-gasPressure)."""
    try:
        return gas.air_properties(t, p)
    except gas.GasError as e:
        raise InputError("entries 'gasTemperature', 'gasPressure': %s" % e)


def material_classes(d, material):
    """A wind-tunnel material's size classes and density, as the C++ side computes
    them (windTunnelDrift -sizeClasses: Table A.1, open bins closed, 6 digits)."""
    r = subprocess.run(["windTunnelDrift", "-sizeClasses", material], capture_output=True, text=True)
    if r.returncode != 0:
        raise InputError("%s: entry 'material': %s" % (d.where("material"), (r.stderr or r.stdout).strip()))
    out = {}
    for line in r.stdout.splitlines():
        key, _, value = line.partition(":")
        if key in ("diameter", "massFractions"):
            out[key] = [float(x) for x in value.split()]
        elif key in ("particleDensity", "bulkDensity"):
            out[key] = float(value)
    if set(out) != {"diameter", "massFractions", "particleDensity", "bulkDensity"}:
        raise InputError("%s: windTunnelDrift -sizeClasses %s gave no classes: %s" % (d.path, material, r.stdout))
    return out
