"""study: a description is read strictly (a key given twice, an unknown section or
study entry, a value out of range, model.drift set by hand: each refused naming the
file and the entry); the grid of a plan covers the queries it was made from."""

import pytest

from flightedDryer.errors import InputError
from flightedDryer.study import plan, routes, segment
from flightedDryer.study.description import Description

GOOD = """drum: {length: 12, diameter: 5, slope_deg: 2.8, speed_rpm: 3}
flights: {count: 28, baseLength: 0.195, tipLength: 0.183, baseAngle_deg: 90, tipAngle_deg: 117, axialLength: 1.133}
material: {feedRate: 27.2, bulkDensity: 940, particleDensity: 1590, sizes_um: [600, 900], fractions_pct: [40, 60]}
gas: {flow: counterCurrent, massRate: 20, temperature_C: 80}
"""


def write(tmp_path, text):
    p = tmp_path / "dryer.yaml"
    p.write_text(text)
    return str(p)


def test_defaults_are_named(tmp_path):
    d = Description(write(tmp_path, GOOD))
    entries = [e for e, _, _ in d.defaults]
    assert "model" in entries and "rtd" in entries and "study.level" in entries
    assert d.sections["model"]["type"] == "compartment" and d.study["margin"] == 0.25
    text = d.drum_dict("table", {"table": "/t.csv", "scale": 1.4})
    assert "drift: table" in text and "scale: 1.4" in text and "study" not in text


@pytest.mark.parametrize("extra,match", [
    ("gas: {flow: coCurrent}\n", r"dryer.yaml:5: entry 'gas' given twice \(first on line 4\)"),
    ("studdy: {level: coarse}\n", r"dryer.yaml:5: unknown section 'studdy' \(did you mean 'study'\?\)"),
    ("study: {levl: fine}\n", r"entry 'study.levl': unknown \(did you mean 'study.level'\?\)"),
    ("study: {margin: 5}\n", r"entry 'study.margin' = 5 outside the allowed range \[0, 2\]"),
    ("study: {scene: drum}\n", r"entry 'study.scene' = 'drum' is not one of box drumSegment"),
    ("study: {scene: drumSegment, stop: fixed, iterations: 100}\n", r"entry 'study.iterations' = 100: a drum "
     r"segment's local steps are a whole multiple of 3"),
    ("study: {scene: drumSegment, iterations: 300}\n", r"entry 'study.iterations' = 300: a statistical stop needs "
     r"at least 450 local steps"),
    ("study: {stop: fixed}\n", r"entry 'study.stop' belongs to scene drumSegment"),
    ("model: {type: twoPhase}\nstudy: {scene: drumSegment}\n", r"entry 'study.scene': a drum-segment table serves "
     r"the compartment model with partition flightModel"),
    ("study: {table: nothere.csv}\n", r"entry 'study.table': no such table"),
    ("model: {type: compartment, drift: table}\n", r"entry 'model.drift': the study sets the drift per route"),
    ("study: {curve: {entry: gas.massRate, values: [10]}}\n", r"entry 'study.curve.values' must be a list of 2"),
    ("study: {curve: {entry: drum.length, values: [10, 12]}}\n", r"entry 'study.curve.entry' = 'drum.length' is not"),
    ("study: {curve: {entry: gas.massRate}}\n", r"entry 'study.curve' must be \{entry"),
])
def test_bad_descriptions_are_refused_naming_the_entry(tmp_path, extra, match):
    with pytest.raises(InputError, match=match):
        Description(write(tmp_path, GOOD + extra))


def test_a_curve_point_overrides_its_entry(tmp_path):
    d = Description(write(tmp_path, GOOD + "study: {curve: {entry: flights.count, values: [20, 28]}}\n"))
    assert d.study["curve"] == {"entry": "flights.count", "values": [20.0, 28.0]}
    assert "count: 20," in d.drum_dict("sherritt", {}, ("flights.count", 20.0))


def test_a_missing_section_or_bad_yaml_is_refused(tmp_path):
    with pytest.raises(InputError, match=r"section 'gas' is missing"):
        Description(write(tmp_path, GOOD.replace("gas: {flow: counterCurrent, massRate: 20, temperature_C: 80}\n", "")))
    with pytest.raises(InputError, match=r"not YAML"):
        Description(write(tmp_path, GOOD + "study: {level: [\n"))


def test_the_grid_covers_its_queries(tmp_path):
    d = Description(write(tmp_path, GOOD))
    q = {"gas_velocity_m_s": (1.0, 1.0), "spill_rate_kg_m_s": (4.9, 29.4), "fall_height_m": (1.16, 4.7),
         "flight_length_m": (1.133, 1.133), "particle_density_kg_m3": (1590, 1590),
         "particle_diameter_m": (6e-4, 9e-4)}
    g = plan.grid(q, d, d.study)
    assert plan.covers(g, q) == []
    assert g["floors"] == g["fallHeight"] and g["floors"][-1] <= 5
    assert g["spillRate"][0] < 4.9 and g["spillRate"][-1] > 29.4
    assert all(b / a <= 3.0 * 1.01 for a, b in zip(g["spillRate"], g["spillRate"][1:]))
    assert g["template"].endswith("windTunnel") and plan.runs(g) == 2 * len(g["spillRate"]) * len(g["floors"])
    assert plan.cpu_estimate_s(g, d.study) > 0
    q["spill_rate_kg_m_s"] = (4.9, 900.0)
    assert plan.covers(g, q) == ["spill_rate_kg_m_s"]
    text = plan.sweep_dict(g, d, d.study, str(tmp_path / "t.csv"))
    assert "boxWidth 5;" in text and "gasTemperature 80;" in text and "floors (" in text


def _queries(vmax, smax):
    return {"gas_velocity_m_s": (0.0 if vmax == 0 else 0.5 * vmax, vmax), "spill_rate_kg_m_s": (0.5 * smax, smax),
            "fall_height_m": (0.5, 4.0), "flight_length_m": (1.133, 1.133),
            "particle_density_kg_m3": (1590.0, 1590.0), "particle_diameter_m": (6e-4, 9e-4)}


def test_the_scene_is_no_more_than_the_drift_needs(tmp_path):
    d = Description(write(tmp_path, GOOD))
    # the windTunnel template releases through 0.05 m at 1 m/s: the edge (5.6e-4) at
    # S = 5.6e-4 x 1590 x 0.05 x 1 = 0.04452 kg/(m s)
    edge = 5.6e-4 * 1590 * 0.05 * 1.0
    assert plan.scene(_queries(0.0, 3.0), d)["scene"] == "none"
    lone = plan.scene(_queries(1.5, 0.99 * edge), d)
    assert lone["scene"] == "lone" and lone["route"] == "isolated" and "below a curtain's edge" in lone["why"]
    box = plan.scene(_queries(1.5, 1.01 * edge), d)
    assert box["scene"] == "box" and box["route"] == "table" and "windTunnel" in box["why"]
    # a NaN spill is not taken for a dilute one
    assert plan.scene(_queries(1.5, float("nan")), d)["scene"] == "box"


def test_the_segment_scene_plans_from_the_drum_models_angles(tmp_path):
    d = Description(write(tmp_path, GOOD + "study: {scene: drumSegment}\n"))
    assert d.study["iterations"] is None and d.study["stop"] == "statistical"
    assert ("study.stop", "statistical") in [(e, v) for e, v, _ in d.defaults]
    q = dict(_queries(1.0, 29.0), repose_angle_deg=(36.94, 58.94), release_angle_deg=(86.3, 211.9))
    assert plan.scene(q, d, "drumSegment")["route"] == "segment"
    # a dilute release needs lone particles whatever scene was asked for
    assert plan.scene(dict(q, spill_rate_kg_m_s=(0.001, 0.002)), d, "drumSegment")["scene"] == "lone"
    g = segment.grid(q, d.study)
    # whole degrees around the drum model's, at most 12 deg apart
    assert g["reposeAngle"] == [36.0, 47.5, 59.0] and segment.covers(g, q) == []
    assert g["gasVelocity"][0] < 1.0 < g["gasVelocity"][-1] and segment.runs(g) == 6
    assert segment.covers(g, dict(q, repose_angle_deg=(30.0, 50.0))) == ["repose_angle_deg"]
    with pytest.raises(InputError, match=r"dynamic angles of repose 15-50 deg lie outside"):
        segment.grid(dict(q, repose_angle_deg=(15.0, 50.0)), d.study)
    # one particle: the mass-weighted median class (60 % at 900 um)
    assert segment.particle(d) == (9e-4, 1590.0)
    text = segment.flight_dictionary(d, 0.5432109, 47.5)
    assert "bedDepth: 0.543211" in text and "nFlights: 28" in text and "radius: 2.5" in text
    assert "tipAngle: 117.0" in text and "dynamicAngleOfRepose: 47.5" in text
    sweep = segment.sweep_dict(g, d, d.study, "/f.yaml", str(tmp_path / "s.csv"), 80.0)
    for entry in ("scene drumSegment;", "stop statistical;", "diameter 0.0009;", "particleDensity 1590;",
                  "gasTemperature 80;", "reposeAngle (36 47.5 59);", "segmentLength 1.133;"):
        assert entry in sweep, entry
    assert "iterations" not in sweep
    assert segment.cpu_estimate_s(g, 26748, d.study) > 6 * segment.RUN_OVERHEAD_S
    names = [r[0] for r in routes.route_settings("/t.csv", 0.37, "segment")]
    assert names == ["segment", "sherritt", "isolated", "segmentLow", "segmentHigh"]
    assert routes.route_settings("/t.csv", 0.37, "segment")[0][2] == {"segmentTable": "/t.csv", "outside": "clamp"}


def test_the_union_of_queries_keeps_an_axis_only_one_has():
    a = {"x": (1.0, 2.0)}
    b = {"x": (0.5, 1.5), "repose_angle_deg": (36.0, 59.0)}
    assert plan.union(a, b) == {"x": (0.5, 2.0), "repose_angle_deg": (36.0, 59.0)}
