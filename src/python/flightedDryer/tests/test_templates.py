"""The curtain templates that share settings keep them the same: windTunnelMULES is
the windTunnel template with the shipped box tables' solids transport, and its own
fvSolution may differ from windTunnel's in that transport, the Courant number (the
start-up's too), the steps' smoothing and the momentum systems' relative tolerance
only."""

import os

from flightedDryer import PROJECT
from flightedDryer import foamDictionary as fd

TEMPLATES = os.path.join(PROJECT, "etc", "templates", "curtain")
MAY_DIFFER = {'solvers/"alpha.*"', "PIMPLE/maxCo", "levelMaxCo", "PIMPLE/rDeltaTSmoothingCoeff",
              "PIMPLE/startUp/maxCo", "PIMPLE/startUp/maxCoHold",
              'solvers/"U.*"/relTol'}


def entries(path, scope=None):
    """{scoped name: value} of every entry of a dictionary but the sub-dictionaries
    (which are walked), the header left out."""
    out = {}
    for k in fd.keywords(path, scope):
        name = k if scope is None else scope + "/" + k
        if name == "FoamFile":
            continue
        rc, text, err = fd.run(["-entry", name, "-value"], path)     # a bare keyword has no value
        assert rc == 0, err
        if text.strip().startswith("{"):
            out.update(entries(path, name))
        else:
            out[name] = text.strip()
    return out


def under(name, scopes):
    return any(name == s or name.startswith(s + "/") for s in scopes)


def test_windTunnelMULES_differs_from_windTunnel_in_the_solids_transport_only():
    # (and the settings that go with MULES's limiter: maxCo, the start's
    # smoothing, the momentum tolerance)
    mules = os.path.join(TEMPLATES, "windTunnelMULES")
    for name in sorted(os.listdir(os.path.join(TEMPLATES, "windTunnel"))):
        if name != "system":
            assert os.path.realpath(os.path.join(mules, name)) == os.path.join(TEMPLATES, "windTunnel", name)
    system = os.path.join(mules, "system")
    for name in sorted(os.listdir(system)):
        if name != "fvSolution":
            assert os.path.realpath(os.path.join(system, name)) == \
                os.path.join(TEMPLATES, "windTunnel", "system", name), name
    a = entries(os.path.join(TEMPLATES, "windTunnel", "system", "fvSolution"))
    b = entries(os.path.join(system, "fvSolution"))
    differ = {k for k in set(a) | set(b) if a.get(k) != b.get(k)}
    assert differ and all(under(k, MAY_DIFFER) for k in differ), sorted(differ)
    assert b['solvers/"alpha.*"/MULESCorr'] == "yes" and b["PIMPLE/maxCo"] == "2"
    assert a["PIMPLE/nCorrectors"] == b["PIMPLE/nCorrectors"] == "1"     # a shared setting seen
