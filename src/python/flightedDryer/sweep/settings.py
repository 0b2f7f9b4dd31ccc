"""settings: the sweep dictionary's entries, the table's axes and file names.
The axes' column names are the drift table's own (C++, asked through facts)."""

import functools
import os

from .. import facts
from ..messages import sayer

say = sayer("buildDriftTable")

# the curtain template curtainCase uses when given no -template (relative to the project)
DEFAULT_TEMPLATE = "etc/templates/curtain/windTunnel"
SEGMENT_TEMPLATE = "etc/templates/curtain/drumSegment"
# the dictionary's grid entries and curtainCase's options, in the table's axis order
GRID_ENTRIES = ("gasVelocity", "spillRate", "fallHeight", "flightLength", "particleDensity", "diameter")
GRID_OPTIONS = ("-gasVelocity", "-spillRate", None, "-flightLength", "-density", None)
RUN_AXES = ["gasVelocity", "spillRate", "flightLength", "particleDensity"]
SLURM_POLL = float(os.environ.get("DRYER_SLURM_POLL", "5"))   # s between queue checks
RESULT = "curtainResult.csv"
LANDING = "curtainLanding.csv"
ARGS = "curtainCase.args.json"
TOP_KEYS = ("FoamFile", "scene", "template", "level", "iterations", "drag", "particleTurbulence", "grid",
            "massFractions", "material", "sizeClasses", "output", "work", "turbulence", "wakeShare",
            "gasTemperature", "gasPressure", "boxWidth", "layerThickness", "bulkDensity", "floors", "warmStart",
            "steadyFrom")
GRID_KEYS = GRID_ENTRIES
# the drum-segment scene (scene drumSegment): one curtainCase -scene drumSegment run
# (drumSegmentCase) per dynamic angle of repose and gas velocity, every releasing
# flight's curtain at once; the table is writeSegmentTable's
SEGMENT_TOP_KEYS = ("FoamFile", "scene", "flights", "template", "level", "iterations", "ends",
                    "segmentLength", "drag", "stop", "grid", "output", "work", "particleDensity", "diameter",
                    "gasTemperature", "gasPressure", "warmStart")
SEGMENT_GRID_KEYS = ("reposeAngle", "gasVelocity")
SCENES = ("box", "drumSegment")


@functools.lru_cache(maxsize=None)
def axes():
    """(dictionary entry, table column, curtainCase option) of the six axes."""
    return list(zip(GRID_ENTRIES, facts.drift_table_axes(), GRID_OPTIONS))


def columns():
    """The table's columns without the optional tunnel reading."""
    return facts.drift_table_columns()


def case_option_entries():
    """The sweep dictionary's entries behind curtainCase's options, for messages."""
    return [("grid/" + a[0], a[2]) for a in axes() if a[2]] + [
        ("grid/fallHeight", "-fallHeight"), ("grid/fallHeight", "-heights"), ("grid/diameter", "-diameters"),
        ("massFractions", "-fractions"), ("level", "-level"), ("drag", "-drag"), ("gasTemperature", "-gasTemperature"),
        ("gasPressure", "-gasPressure"), ("boxWidth", "-boxWidth"), ("layerThickness", "-layerThickness"),
        ("bulkDensity", "-bulkDensity"), ("iterations", "-iterations"), ("steadyFrom", "-steadyFrom"), ("turbulence", "-turbulence"),
        ("particleTurbulence", "-particleTurbulence"), ("wakeShare", "-wakeShare"), ("template", "-template")]
