"""facts: what the C++ side owns, asked of it (dryerFacts) rather than repeated:
the drag laws, Sherritt's Eq 142 constants, the drift table's columns, the
largest spill rate. The slot's solids fraction is the one formula kept on both
sides; tests/test_facts.py ties this copy to the C++ one."""

import functools
import json
import subprocess

from .errors import InputError


@functools.lru_cache(maxsize=None)
def _facts():
    try:
        r = subprocess.run(["dryerFacts"], capture_output=True, text=True)
    except OSError as e:
        raise InputError("dryerFacts is needed (build the project with ./Allwmake, then source "
                         "etc/bashrc): %s" % (e.strerror or e))
    if r.returncode != 0:
        raise InputError("dryerFacts failed: %s" % (r.stderr or r.stdout).strip())
    return json.loads(r.stdout)


def drag_laws():
    """The drag laws' names, in the C++ order (particleDrag::dragLawNames)."""
    return tuple(_facts()["dragLaws"])


def eq142():
    """Sherritt 1991 Eq 142's constants {k, a, b, c}: C_V = k y^a S^-b L^-c."""
    return dict(_facts()["eq142"])


def drift_table_columns():
    """The drift table's columns, in order (case, the six axes, the three values)."""
    return list(_facts()["driftTableColumns"])


def drift_table_axes():
    """The six axis columns of the drift table, in its order."""
    return drift_table_columns()[1:7]


def tunnel_drift_column():
    """The drift table's optional last column (the wind tunnel's reading)."""
    return _facts()["tunnelDriftColumn"]


def max_spill_rate():
    """The largest spill rate a curtain run takes, kg/(m s)."""
    return float(_facts()["maxSpillRate"])


def curtain_edge_solids_fraction():
    """The solids fraction at a curtain's edge (particleDrag::curtainEdgeSolidsFraction)."""
    return float(_facts()["curtainEdgeSolidsFraction"])


def gas_temperature_range():
    """(least, largest) gas temperature, degC, the tools accept (particleDrag::minTemperatureC,
    maxTemperatureC)."""
    return tuple(float(x) for x in _facts()["gasTemperatureRangeC"])


def gas_pressure_range():
    """(least, largest) gas pressure, kPa, the tools accept (particleDrag::minPressureKPa,
    maxPressureKPa)."""
    return tuple(float(x) for x in _facts()["gasPressureRangeKPa"])


def slot_solids_fraction(spill, rho_p, thickness, velocity):
    """Solids fraction at the slot, S/(rho_p b v) (particleDrag::slotSolidsFraction,
    Lee 2008 Eq 5.4): spill kg/(m s), rho_p kg/m3, thickness m, velocity m/s."""
    return spill / (rho_p * thickness * velocity)
