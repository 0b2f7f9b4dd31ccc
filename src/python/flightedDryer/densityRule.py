"""densityRule: a material's particle (envelope) density where the printed one cannot
be right, from its bulk density and the packings the seeds measure.

The rule (data/README.md, "Particle density rule"), the same for every material:

- A loose bulk of grains cannot hold more solids than random close packing of equal
  spheres, about 0.64 (Scott and Kilgour 1969); angular grains pack looser. A printed
  pair whose bulk/particle ratio exceeds RANDOM_CLOSE_PACKING is not a grain density
  and a bulk density of the same grains.
- The reference packings are the loose packings of the seeds' granular minerals whose
  printed pair is possible: Sherritt 1991 Table A.1's sand and Lee 2008 Table 5.2's
  three rig materials (their unconsolidated bulk density).
- Such a material's particle density is its bulk density over the reference packing:
  the mean packing gives the central value, the largest packing the low end of the
  range and the smallest packing the high end.

Everything is read from the project's data files; nothing here is chosen by a score.
"""

import csv
import io
import os

from . import PROJECT
from .errors import InputError
from .files import atomic_write

RANDOM_CLOSE_PACKING = 0.64   # solids fraction of randomly close-packed equal spheres


def _rows(path):
    try:
        with open(path, newline="") as f:
            return list(csv.DictReader(f))
    except OSError as e:
        raise InputError("%s: cannot read (%s)" % (path, e.strerror))


def _number(path, row, column):
    try:
        v = float(row[column])
    except (KeyError, TypeError, ValueError):
        raise InputError("%s: entry %s = %r of material %s is not a number"
                         % (path, column, row.get(column), row.get("material")))
    if not (v > 0 and v < 1e5):
        raise InputError("%s: entry %s = %r of material %s is outside (0, 1e5) kg/m3"
                         % (path, column, row.get(column), row.get("material")))
    return v


def printed_pairs(data=None):
    """[(source, material, particle density, loose bulk density)] of every material of
    the seeds with both printed: the wind tunnel's three (Sherritt 1991 Table A.1)
    and Lee 2008 Table 5.2's three (unconsolidated bulk density)."""
    data = data or os.path.join(PROJECT, "data")
    out = []
    path = os.path.join(data, "windtunnel_materials.csv")
    seen = set()
    for r in _rows(path):
        if r.get("material") in seen:
            continue
        seen.add(r.get("material"))
        out.append(("Sherritt 1991 Table A.1", r["material"], _number(path, r, "particle_density_kg_m3"),
                    _number(path, r, "bulk_density_kg_m3")))
    path = os.path.join(data, "lee_materials.csv")
    for r in _rows(path):
        out.append(("Lee 2008 Table 5.2", r["material"], _number(path, r, "particle_density_kg_m3"),
                    _number(path, r, "bulk_density_unconsolidated_kg_m3")))
    if not out:
        raise InputError("%s: no material rows" % data)
    return out


def reference_packings(data=None):
    """{material: loose packing} of the printed pairs that are possible (at most random
    close packing)."""
    ref = {m: rb / rp for _, m, rp, rb in printed_pairs(data) if rb / rp <= RANDOM_CLOSE_PACKING}
    if not ref:
        raise InputError("no material of the seeds has a possible bulk/particle pair")
    return ref


def particle_density(particle, bulk, data=None):
    """(central, low, high, applied) particle density in kg/m3 of a material printed with
    `particle` and `bulk`: the printed value three times when the pair is possible
    (applied False), else bulk over the mean, largest and smallest reference packing."""
    if not (0 < particle < 1e5 and 0 < bulk < 1e5):
        raise InputError("particle density %r and bulk density %r must be numbers in (0, 1e5) kg/m3" % (particle, bulk))
    if bulk / particle <= RANDOM_CLOSE_PACKING:
        return particle, particle, particle, False
    ref = sorted(reference_packings(data).values())
    mean = sum(ref) / len(ref)
    return bulk / mean, bulk / ref[-1], bulk / ref[0], True


def ruled_materials(src, out, which="central", data=None):
    """Writes a copy of the wind-tunnel materials file `src` with each material's
    particle density by the rule (`which`: central, low or high); returns
    {material: (printed, ruled)}. The other columns are copied as they are."""
    pick = {"central": 0, "low": 1, "high": 2}
    if which not in pick:
        raise InputError("density rule value '%s' is not one of central low high" % which)
    rows = _rows(src)
    if not rows:
        raise InputError("%s: no material rows" % src)
    changed = {}
    for r in rows:
        rp, rb = _number(src, r, "particle_density_kg_m3"), _number(src, r, "bulk_density_kg_m3")
        v = particle_density(rp, rb, data)
        changed[r["material"]] = (rp, v[pick[which]])
        r["particle_density_kg_m3"] = "%.6g" % v[pick[which]]
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=list(rows[0].keys()), lineterminator="\n")
    w.writeheader()
    w.writerows(rows)
    atomic_write(out, buf.getvalue())
    return changed
