"""facts: the Python side asks the C++ side (dryerFacts) for what it owns; the one
formula kept on both sides, the slot's solids fraction, agrees with the C++ one;
crossValidate's RMS-ln score agrees with windTunnelDrift -score's."""

import csv
import importlib.machinery
import importlib.util
import math
import os
import subprocess

import pytest

from flightedDryer import PROJECT, facts


def test_the_facts_come_from_the_cpp_side():
    assert facts.drag_laws()[0] == "SchillerNaumann" and "LeeSugar" in facts.drag_laws()
    assert facts.drift_table_axes() == ["gas_velocity_m_s", "spill_rate_kg_m_s", "fall_height_m",
                                        "flight_length_m", "particle_density_kg_m3", "particle_diameter_m"]
    assert facts.drift_table_columns()[0] == "case" and facts.drift_table_columns()[-3:] == \
        ["vc_over_vg", "drift_m", "captured_fraction"]
    c = facts.eq142()
    assert set(c) == {"k", "a", "b", "c"} and all(math.isfinite(v) and v > 0 for v in c.values())
    assert facts.max_spill_rate() > 0


def test_the_gas_ranges_are_the_ones_airProperties_holds():
    for lo_hi, option in ((facts.gas_temperature_range(), "-temperature"), (facts.gas_pressure_range(), "-pressure")):
        lo, hi = lo_hi
        assert math.isfinite(lo) and math.isfinite(hi) and lo < hi
        base = [] if option == "-temperature" else ["-temperature", "20"]
        for v, ok in ((lo, True), (hi, True), (hi * 1.01 + 1, False)):
            r = subprocess.run(["airProperties"] + base + [option, "%.17g" % v], capture_output=True, text=True)
            assert (r.returncode == 0) == ok, (option, v, r.stderr)


@pytest.mark.parametrize("args", [(20, 2650, 0.05, 1), (0.3, 1200, 0.008, 0.67), (999, 1590, 0.2, 5)])
def test_the_slot_fraction_is_the_cpp_one(args):
    r = subprocess.run(["dryerFacts", "-slotSolidsFraction"] + ["%.17g" % a for a in args],
                       capture_output=True, text=True, check=True)
    assert facts.slot_solids_fraction(*args) == float(r.stdout)


def test_the_rms_ln_score_is_windTunnelDrift_score(tmp_path):
    path = os.path.join(PROJECT, "validation", "windTunnelDrift", "crossValidate")
    loader = importlib.machinery.SourceFileLoader("crossValidate", path)
    cv = importlib.util.module_from_spec(importlib.util.spec_from_loader("crossValidate", loader))
    loader.exec_module(cv)
    tests_file = os.path.join(PROJECT, "data", "windtunnel_tests.csv")
    pred_file = os.path.join(PROJECT, "validation", "windTunnelDrift", "results", "predictions",
                             "sherritt.csv")
    tests = cv.read_tests(tests_file, "mean_advance_m")
    pred = cv.read_predictions(pred_file, tests, "advance")
    rows = [t for t in pred if tests[t]["measured"] is not None]
    py = cv.score(pred, tests, rows)
    out = tmp_path / "scores.csv"
    subprocess.run(["windTunnelDrift", "-score", "-tests", tests_file, "-predictions", "sherritt=" + pred_file,
                    "-out", str(out)], capture_output=True, check=True)
    cpp = [r for r in csv.DictReader(open(out)) if r["model"] == "sherritt" and r["fall_height_m"] == "all"][0]
    assert int(cpp["count"]) == py["count"]
    for key in ("rms_ln", "bias_ln", "within25"):
        assert math.isclose(float(cpp[key]), py[key], rel_tol=1e-3), key
