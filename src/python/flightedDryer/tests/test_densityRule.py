"""The particle density rule (data/README.md): reference packings read from the data
files, a possible pair kept, an impossible one replaced, bad values refused."""
import csv
import math
import os

import pytest

from flightedDryer import densityRule
from flightedDryer.errors import InputError


def test_reference_packings_are_the_seeds_possible_pairs():
    ref = densityRule.reference_packings()
    # Sherritt's sand and Lee's three rig materials; the shales (0.72) are not possible
    assert sorted(ref) == ["filter_sand", "river_sand", "sand", "zeolite"]
    assert ref["sand"] == pytest.approx(1600 / 2650, rel=1e-12)
    assert ref["zeolite"] == pytest.approx(1075 / 2200, rel=1e-12)
    assert all(0.45 < v <= densityRule.RANDOM_CLOSE_PACKING for v in ref.values())


def test_shales_get_bulk_over_packing_sand_is_kept():
    central, low, high, applied = densityRule.particle_density(1200, 860)
    ref = densityRule.reference_packings().values()
    assert applied
    assert central == pytest.approx(860 / (sum(ref) / len(ref)), rel=1e-12)
    assert low == pytest.approx(860 / max(ref), rel=1e-12)
    assert high == pytest.approx(860 / min(ref), rel=1e-12)
    assert 1400 < low < central < high < 1800
    assert densityRule.particle_density(2650, 1600) == (2650, 2650, 2650, False)


@pytest.mark.parametrize("rp, rb", [(float("nan"), 860), (1200, float("nan")), (-1, 860), (1200, 0),
                                    (float("inf"), 860)])
def test_bad_densities_refused(rp, rb):
    with pytest.raises(InputError):
        densityRule.particle_density(rp, rb)


def test_ruled_materials_file(tmp_path):
    src = os.path.join(os.path.dirname(densityRule.__file__), "..", "..", "..", "data", "windtunnel_materials.csv")
    out = tmp_path / "m.csv"
    changed = densityRule.ruled_materials(src, str(out), "high")
    assert changed["sand"] == (2650, 2650)
    assert changed["raw_shale"][0] == 1200 and changed["raw_shale"][1] > 1700
    with open(src, newline="") as f:
        before = list(csv.DictReader(f))
    with open(out, newline="") as f:
        after = list(csv.DictReader(f))
    assert len(after) == len(before)
    for a, b in zip(after, before):
        for k in b:
            if k != "particle_density_kg_m3":
                assert a[k] == b[k]
        assert math.isfinite(float(a["particle_density_kg_m3"]))
    with pytest.raises(InputError):
        densityRule.ruled_materials(src, str(tmp_path / "x.csv"), "middle")
    bad = tmp_path / "bad.csv"
    bad.write_text(open(src).read().replace("1600.0", "nan", 1))
    with pytest.raises(InputError, match="bulk_density_kg_m3"):
        densityRule.ruled_materials(str(bad), str(tmp_path / "y.csv"))
    assert not (tmp_path / "y.csv").exists()
