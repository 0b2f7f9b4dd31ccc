"""inputs: curtainCase's options checked against the template and the physics
before anything runs; returns the run's settings (a dict, whose keys also make
the inputs' signature: a key is added only when its option is given, so the
signature of other runs stays as it was)."""

import os

from .. import gas
from ..errors import InputError
from ..options import choice, number, number_list, whole
from . import dictionaries as fd
from .settings import (DEFAULT_TEMPLATE, GAS_MODELS, LEVELS, MAX_LAYER, MIN_FALL_CELLS, MIN_LAYER,
                       MIN_SECTION_CELLS, PACKED_SLOT_FRACTION, PARTICLE_PARTICLE_DRAG, PARTICLE_TURBULENCE,
                       TURBULENT_DISPERSION, say)
from .setUp import level_entries, round_up
from ..facts import drag_laws, gas_pressure_range, gas_temperature_range, max_spill_rate, slot_solids_fraction


def air_properties(t, p=None):
    """(rho, nu) of dry air at t degC and p kPa (None: 1 atm) (flightedDryer.gas:
    the project's one air model); a temperature that looks like kelvin is warned."""
    try:
        return gas.air_properties(t, p, warn=lambda w: say("warning: " + w), entry="-gasTemperature")
    except gas.GasError as e:
        raise InputError("-gasTemperature/-gasPressure: %s" % e)


def check_inputs(opts):
    """Everything checked before anything runs; returns the settings."""
    s = {}
    s["template"] = os.path.abspath(opts.get("-template", DEFAULT_TEMPLATE))
    for f in ("system/meshParameters", "system/caseParameters", "system/controlDict",
              "constant/curtainProperties", "0.orig"):
        if not os.path.exists(os.path.join(s["template"], f)):
            raise InputError("template %s has no %s" % (s["template"], f))
    mp = os.path.join(s["template"], "system", "meshParameters")
    cp = os.path.join(s["template"], "system", "caseParameters")
    Hmax = fd.scalar(mp, "H")
    Lt = fd.scalar(mp, "Lt")
    xs = fd.scalar(mp, "xs")
    release = number(opts, "-releaseVelocity", 0.1, 5, "m/s", lo_open=False) \
        if "-releaseVelocity" in opts else fd.scalar(cp, "releaseVelocity")
    packed = opts.get("-layerThickness") == "packed"
    if "-bulkDensity" in opts and not packed:
        raise InputError("-bulkDensity belongs to -layerThickness packed (here %s)"
                         % opts.get("-layerThickness", "the template's layer"))
    if packed and "-bulkDensity" not in opts:
        raise InputError("-layerThickness packed needs -bulkDensity (the material's bulk density, kg/m3)")
    thickness = None if packed else \
        number(opts, "-layerThickness", MIN_LAYER, MAX_LAYER, "m", lo_open=False) \
        if "-layerThickness" in opts else fd.scalar(cp, "thickness")
    props = os.path.join(s["template"], "constant", "curtainProperties")
    try:
        alpha_max = float(fd.value(props, "alphaMax"))
    except InputError:
        alpha_max = 0.62
    rho_gas = fd.scalar(os.path.join(s["template"], "constant", "transportProperties"), "rho") \
        if fd.has(os.path.join(s["template"], "constant", "transportProperties"), "rho") else 1.2
    if "-gasTemperature" in opts or "-gasPressure" in opts:
        # keys only when given: the inputs' signature of other runs is unchanged
        s["gasTemperature"] = number(opts, "-gasTemperature", *gas_temperature_range(), "degC", lo_open=False) \
            if "-gasTemperature" in opts else 20.0
        if "-gasPressure" in opts:
            s["gasPressure"] = number(opts, "-gasPressure", *gas_pressure_range(), "kPa", lo_open=False)
        s["gasRho"], s["gasNu"] = air_properties(s["gasTemperature"], s.get("gasPressure"))
        rho_gas = float(s["gasRho"])

    s["dir"] = os.path.abspath(opts["-dir"])
    s["Vg"] = number(opts, "-gasVelocity", 0, 50, "m/s")
    s["spill"] = number(opts, "-spillRate", 0, max_spill_rate(), "kg/(m s)")
    s["Y"] = number(opts, "-fallHeight", 0, Hmax, "m (the template's domain height)")
    # the slot must leave at least 2 m of tunnel downstream
    s["L"] = number(opts, "-flightLength", 0, Lt - xs - 2, "m (template tunnel %g m, slot start %g m)" % (Lt, xs))
    s["rho"] = number(opts, "-density", 10 * rho_gas, 25000, "kg/m3 (above 10x the gas density)")
    s["d"] = number_list(opts, "-diameters", 1e-6, 0.05, "m")
    s["w"] = number_list(opts, "-fractions", -1e-300, 1, "")
    if len(s["w"]) != len(s["d"]):
        raise InputError("-fractions has %d values, -diameters %d: one mass fraction per diameter"
                         % (len(s["w"]), len(s["d"])))
    if abs(sum(s["w"]) - 1) > 1e-3:
        raise InputError("-fractions sum to %g, allowed range [0.999, 1.001]" % sum(s["w"]))
    s["w"] = [w / sum(s["w"]) for w in s["w"]]
    if packed:
        # a key only when given: the inputs' signature of other runs is unchanged
        s["bulkDensity"] = number(opts, "-bulkDensity", 0, s["rho"], "kg/m3")
        thickness = packed_layer(s["spill"], s["rho"], s["bulkDensity"], release)
        if not MIN_LAYER <= thickness <= MAX_LAYER:
            raise InputError("-layerThickness packed: -spillRate %g kg/(m s) at -bulkDensity %g kg/m3 "
                             "and release %g m/s gives a layer of %.4g m, allowed range [%g, %g] m"
                             % (s["spill"], s["bulkDensity"], release, thickness, MIN_LAYER, MAX_LAYER))
    s["names"] = ["c%d" % i for i in range(len(s["d"]))]
    heights = [s["Y"]]
    if "-heights" in opts:
        heights += number_list(opts, "-heights", 0, s["Y"], "m (at most -fallHeight)")
    s["heights"] = sorted(set(round(h, 9) for h in heights))
    s["Hmax"] = Hmax
    s["level"] = opts.get("-level", "coarse")
    levels = list(LEVELS)
    ml = os.path.join(s["template"], "system", "meshLevels")
    if os.path.exists(ml):
        levels = fd.keywords(ml, "levels") or levels
    if s["level"] not in levels:
        raise InputError("-level '%s' is not one of %s" % (s["level"], " ".join(levels)))
    s["np"] = whole(opts, "-np", 1, 64, "processes", lo_open=False) if "-np" in opts else 1
    s["drag"] = choice(opts, "-drag", drag_laws(), "SchillerNaumann")
    s["sphericity"] = number(opts, "-sphericity", 0, 1, "") if "-sphericity" in opts else 1.0
    s["particleTurbulence"] = choice(opts, "-particleTurbulence", PARTICLE_TURBULENCE)
    s["turbulentDispersion"] = choice(opts, "-turbulentDispersion", TURBULENT_DISPERSION)
    s["particleParticleDrag"] = choice(opts, "-particleParticleDrag", PARTICLE_PARTICLE_DRAG)
    if "-wakeShare" in opts and s["particleTurbulence"] != "SimoninCrowe":
        raise InputError("-wakeShare is an entry of -particleTurbulence SimoninCrowe (here %s)"
                         % s["particleTurbulence"])
    s["wakeShare"] = number(opts, "-wakeShare", 0, 1, "", lo_open=False) \
        if "-wakeShare" in opts else None
    tp = os.path.join(s["template"], "constant", "turbulenceProperties.air")
    s["turbulence"] = choice(opts, "-turbulence", GAS_MODELS, fd.value(tp, "RAS/RASModel"))
    endTime = fd.scalar(os.path.join(s["template"], "system", "controlDict"), "endTime")
    s["iterations"] = int(number(opts, "-iterations", 9, 100000, "iterations")) \
        if "-iterations" in opts else int(endTime)
    s["keep"] = bool(opts.get("-keep"))
    if "-startFrom" in opts:
        # a warm start from a finished run on the same mesh (kept with -keep); the
        # signature holds its folder's name (a sweep plans it before it has run)
        if s["np"] > 1:
            raise InputError("-startFrom needs -np 1 (the source's fields are read onto the whole mesh)")
        s["startFromDir"] = os.path.abspath(opts["-startFrom"])
        s["startFrom"] = os.path.basename(s["startFromDir"])
    # steady window, sampling interval (= write interval / 5) and end of the first stage
    n = s["iterations"]
    s["window"] = max(3, min(50, n // 3))
    s["every"] = max(1, s["window"] // 5)
    s["end"] = round_up(2 * n, s["window"])
    # the first iteration the steady window may end the run at (default: one
    # window on, setUp.check_from); at most the first stage's N iterations
    if "-steadyFrom" in opts:
        s["steadyFrom"] = whole(opts, "-steadyFrom", 0, n, "iterations", lo_open=False)
    # solids fraction at the slot: spill/(rho b v) below packing
    alpha_slot = slot_solids_fraction(s["spill"], s["rho"], thickness, release)
    if alpha_slot >= alpha_max:
        raise InputError("-spillRate %g kg/(m s) with -density %g kg/m3 gives a solids fraction %.3g at "
                         "the slot (layer %g m, release %g m/s), allowed range (0, alphaMax %g): "
                         "spill rate at most %.4g kg/(m s)"
                         % (s["spill"], s["rho"], alpha_slot, thickness, release, alpha_max,
                            alpha_max * s["rho"] * thickness * release))
    s["alpha_slot"] = alpha_slot
    check_resolution(s)
    s["check"] = bool(opts.get("-check"))
    s["thickness"] = thickness
    if "-boxWidth" in opts:
        # a key only when given: the inputs' signature of other runs is unchanged
        s["boxWidth"] = number(opts, "-boxWidth", 2 * thickness, 20,
                               "m", lo_open=False)   # from twice the layer
    s["release"] = release
    s["Hmax"] = Hmax
    s["xs"] = xs
    return s


def packed_layer(spill, rho_p, rho_b, release):
    """The release layer that carries the spill S at the bulk density rho_b and the
    release speed v: b = S/(rho_b v), with rho_b/rho_p capped at PACKED_SLOT_FRACTION."""
    return spill / (min(rho_b / rho_p, PACKED_SLOT_FRACTION) * rho_p * release)


def check_resolution(s):
    """The fall height and its planes must be resolved by the level's cells (the
    level's ny over the template's height H, as set_up builds the mesh)."""
    mp = os.path.join(s["template"], "system", "meshParameters")
    level = level_entries(s["template"], s["level"])
    try:
        ny = float(level["ny"]) if "ny" in level else fd.scalar(mp, "ny")
    except ValueError:
        raise InputError("template %s: level %s: ny = '%s' is not a number"
                         % (s["template"], s["level"], level["ny"]))
    if not ny >= 1:
        raise InputError("template %s: level %s has ny = %g cells" % (s["template"], s["level"], ny))
    dy = s["Hmax"] / ny
    ymin = MIN_FALL_CELLS * dy
    if s["Y"] < ymin - 1e-12:
        raise InputError("-fallHeight = %g m is below %d cells of level %s (cell height %.4g m): "
                         "allowed range [%.4g, %g] m" % (s["Y"], MIN_FALL_CELLS, s["level"], dy,
                                                          ymin, s["Hmax"]))
    planes = sorted(set([0.0, s["Y"]] + [s["Y"] - h for h in s["heights"]]))
    for a, b in zip(planes[:-1], planes[1:]):
        if b - a < MIN_SECTION_CELLS * dy - 1e-12:
            raise InputError("-heights: planes %g m and %g m below the release are %.4g m apart, "
                             "less than half a cell of level %s (%.4g m): fall heights must differ "
                             "by at least %.4g m" % (s["Y"] - b, s["Y"] - a, b - a, s["level"], dy,
                                                     MIN_SECTION_CELLS * dy))
