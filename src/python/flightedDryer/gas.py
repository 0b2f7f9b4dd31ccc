"""dryerGas: the gas of a curtain case, from the project's one air model.

The density and viscosity of dry air come from the C++ side (airProperties,
particleDrag/gasProperties.hpp), so the curtain tables and the drum model that
reads them use the same air; this module only asks it.
"""

import subprocess


class GasError(Exception):
    """airProperties missing or refusing the temperature."""


def air_properties(t, p=None, warn=None, entry=None):
    """(rho, nu) of dry air at t degC (and p kPa; None: 1 atm) as text (6 digits),
    from airProperties. `warn`, if given, is called with each warning airProperties
    prints (a temperature that looks like kelvin: drum/io/unitSlips.hpp), which
    names the caller's `entry`."""
    cmd = ["airProperties", "-temperature", "%.12g" % t] + ([] if p is None else ["-pressure", "%.12g" % p]) \
        + ([] if entry is None else ["-entry", entry])
    try:
        r = subprocess.run(cmd, capture_output=True, text=True)
    except OSError as e:
        raise GasError("airProperties is needed for a gas temperature (build the project: ./Allwmake): %s" % e)
    if r.returncode != 0:
        raise GasError("%s: %s" % (" ".join(cmd), (r.stderr or r.stdout).strip()))
    if warn:
        for line in r.stderr.splitlines():
            if "warning:" in line:
                warn(line.split("warning:", 1)[1].strip())
    v = dict(line.split() for line in r.stdout.splitlines() if line.strip())
    return v["rho"], v["nu"]
