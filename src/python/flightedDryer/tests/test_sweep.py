"""sweep: the plan of a sweep (its runs, names, arguments, floors), its signature,
the resume decision (a run is finished only with these arguments and inputs),
and the Slurm job array written without a cluster."""

import json
import os

import pytest

from flightedDryer import PROJECT
from flightedDryer.errors import InputError
from flightedDryer.sweep import plan, slurm
from flightedDryer.sweep.dictionary import read_sweep

HEAD = "FoamFile { version 2.0; format ascii; class dictionary; object d; }\n"
GRID = ("grid { gasVelocity (1 3); spillRate (2); flightLength (1); particleDensity (1590);\n"
        "       fallHeight (1 2 4); diameter (3e-4 1e-3); }\nmassFractions (0.4 0.6);\n")


def sweep(tmp_path, extra=""):
    p = tmp_path / "sweepDict"
    p.write_text(HEAD + GRID + extra + "work \"%s\";\n" % (tmp_path / "work"))
    return read_sweep(str(p))


def test_the_plan_of_a_box_sweep(tmp_path):
    s = sweep(tmp_path, "floors (2 4);\n")
    cases = plan.cases_of(s)
    assert [c["name"] for c in cases] == ["V1_S2_L1_rho1590_H2", "V1_S2_L1_rho1590",
                                          "V3_S2_L1_rho1590_H2", "V3_S2_L1_rho1590"]
    low, high = cases[0], cases[1]
    assert low["serves"] == [1.0, 2.0] and high["serves"] == [4.0]
    assert low["args"][:6] == ["-gasVelocity", "1", "-spillRate", "2", "-fallHeight", "2"]
    assert "-heights" in high["args"] and high["args"][high["args"].index("-heights") + 1] == "1,2"
    assert high["args"][high["args"].index("-fractions") + 1] == "0.4,0.6"
    assert s["output"] == str(tmp_path / "driftTable.csv")


def test_the_signature_follows_the_arguments(tmp_path):
    a = plan.grid_key(plan.cases_of(sweep(tmp_path)))
    assert a == plan.grid_key(plan.cases_of(sweep(tmp_path)))        # same inputs, same bits
    assert a != plan.grid_key(plan.cases_of(sweep(tmp_path, "gasTemperature 80;\n")))
    assert a != plan.grid_key(plan.cases_of(sweep(tmp_path, "floors (2 4);\n")))


@pytest.mark.parametrize("extra,match", [
    ("drag Stokes;\n", r"entry 'drag' = 'Stokes' is not one of SchillerNaumann"),
    ("floors (3);\n", r"entry 'floors': 3 m is not a fall height of grid/fallHeight"),
    ("gasTemprature 80;\n", r"unknown entry 'gasTemprature' \(did you mean 'gasTemperature'\?\)"),
    ("bulkDensity 900;\n", r"entry 'bulkDensity' belongs to 'layerThickness packed'"),
    ("iterations 300;\nsteadyFrom 301;\n", r"entry 'steadyFrom' = '301' outside the allowed range \[0, 300\]"),
    ("steadyFrom 12.5;\n", r"entry 'steadyFrom' = '12.5' outside the allowed range \[0, 100000\] \(a whole number"),
])
def test_bad_sweeps_are_refused_naming_the_entry(tmp_path, extra, match):
    with pytest.raises(InputError, match=match):
        sweep(tmp_path, extra)


def test_steady_from_reaches_every_run_of_the_sweep(tmp_path):
    default = plan.cases_of(sweep(tmp_path))
    assert all("-steadyFrom" not in c["args"] for c in default)      # curtainCase's default
    given = plan.cases_of(sweep(tmp_path, "iterations 300;\nsteadyFrom 150;\n"))
    assert all(c["args"][c["args"].index("-steadyFrom") + 1] == "150" for c in given)
    assert plan.grid_key(default) != plan.grid_key(given)             # another sweep's runs


def finish(s, c, argv=None, inputs="sig"):
    d = plan.case_dir(s, c)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "curtainResult.csv"), "w") as f:
        f.write("class\n")
    with open(os.path.join(d, "curtainCase.args.json"), "w") as f:
        json.dump({"argv": argv if argv is not None else ["-dir", d] + c["args"], "inputs": inputs}, f)


def test_resume_takes_a_run_as_finished_only_with_these_inputs(tmp_path):
    s = sweep(tmp_path)
    c = plan.cases_of(s)[0]
    assert not plan.finished(s, c)                       # nothing there
    finish(s, c)
    assert plan.finished(s, c)
    finish(s, c, argv=["-dir", plan.case_dir(s, c)] + c["args"] + ["-np", "2"])
    assert plan.finished(s, c)                           # -np does not change the answer
    finish(s, c, argv=["-dir", plan.case_dir(s, c)] + c["args"][:-2])
    assert not plan.finished(s, c)                       # other arguments
    finish(s, c)
    c["inputs"] = "other"                                # curtainCase -check's signature differs
    assert not plan.finished(s, c)
    os.remove(os.path.join(plan.case_dir(s, c), "curtainCase.args.json"))
    assert not plan.finished(s, c)


def test_the_slurm_array_is_written_without_a_cluster(tmp_path):
    s = sweep(tmp_path)
    cases = plan.cases_of(s)
    sched = {"partition": "short", "account": None, "time": "00:30:00", "extra": ["--mem=2G"]}
    script, collect, lst = slurm.write_slurm(s, cases, [cases[0], cases[1]], 2, sched)
    text = open(script).read()
    assert "#SBATCH --array=0-1\n" in text and "#SBATCH --ntasks=2\n" in text
    assert "#SBATCH --partition=short\n#SBATCH --time=00:30:00\n#SBATCH --mem=2G\n" in text
    assert ". %s/etc/bashrc" % PROJECT in text
    lines = open(lst).read().splitlines()
    assert len(lines) == 2 and lines[0].startswith("curtainCase -dir ") and lines[0].endswith("-np 2")
    assert "buildDriftTable -dict %s -work %s -out %s -collect" % (s["dict"], s["work"], s["output"]) \
        in open(collect).read()
    assert os.access(script, os.X_OK) and os.access(collect, os.X_OK)


def test_array_ranges():
    assert slurm.array_spec([0, 1, 2, 3, 5, 7, 8]) == "0-3,5,7-8"
    assert slurm.array_spec([4]) == "4"


def test_warm_start_chains_are_the_plans(tmp_path):
    g = ("grid { gasVelocity (1 3); spillRate (2 5 9); flightLength (1); particleDensity (1590);\n"
         "       fallHeight (1 2); diameter (3e-4); }\nmassFractions (1);\nfloors (1 2);\n")
    p = tmp_path / "warmDict"
    p.write_text(HEAD + g + "warmStart yes;\nwork \"%s\";\n" % (tmp_path / "work"))
    s = read_sweep(str(p))
    cases = plan.cases_of(s)
    chains = plan.chains_of(s, cases)
    # one chain per floor (a mesh), the spill rates up, then down at the next gas velocity
    assert [[c["name"].split("_L")[0] for c in ch] for ch in chains] == \
        [["V1_S2", "V1_S5", "V1_S9", "V3_S9", "V3_S5", "V3_S2"]] * 2
    assert [c["floor"] for c in chains[0]] == [1.0] * 6
    by = {c["name"]: c for c in cases}
    first, second, last = chains[1][0], chains[1][1], chains[1][-1]
    assert "-startFrom" not in first["args"] and "-keep" in first["args"]
    assert second["args"][second["args"].index("-startFrom") + 1] == plan.case_dir(s, first)
    assert second["parent"] == first["name"] and "-keep" not in last["args"]
    assert by[last["name"]]["parent"] == chains[1][-2]["name"]
    # the Slurm array: a task per chain, its cases in order
    slurm.write_slurm(s, cases, cases, 1, {"extra": []})
    tasks = open(os.path.join(slurm.slurm_dir(s), "tasks.txt")).read().splitlines()
    index = {c["name"]: i + 1 for i, c in enumerate(cases)}
    assert tasks == [" ".join(str(index[c["name"]]) for c in ch) for ch in chains]
    assert slurm.unit_of(s, cases)[last["name"]] == 1
    # without warmStart: a task per case, no chain arguments
    cold = plan.cases_of(sweep(tmp_path))
    assert all("-startFrom" not in c["args"] and "-keep" not in c["args"] for c in cold)
    assert slurm.task_cases(sweep(tmp_path), cold) == [[i] for i in range(len(cold))]


def test_warm_start_with_a_packed_layer_chains_only_one_spill(tmp_path):
    g = ("grid { gasVelocity (1 3); spillRate (2 5); flightLength (1); particleDensity (1590);\n"
         "       fallHeight (1); diameter (3e-4); }\nmassFractions (1);\n")
    p = tmp_path / "warmDict"
    p.write_text(HEAD + g + "warmStart yes;\nlayerThickness packed;\nbulkDensity 900;\n"
                 "work \"%s\";\n" % (tmp_path / "work"))
    s = read_sweep(str(p))
    chains = plan.chains_of(s, plan.cases_of(s))
    # the packed layer's thickness follows the spill rate: another mesh per spill
    assert [[c["name"].split("_L")[0] for c in ch] for ch in chains] == [["V1_S2", "V3_S2"], ["V1_S5", "V3_S5"]]


def test_warm_segments_chain_by_repose_angle(tmp_path):
    p = tmp_path / "segDict"
    p.write_text(HEAD + 'scene drumSegment;\nflights "etc/defaults/driftTables/invictaSegment.yaml";\n'
                 "warmStart yes;\ngrid { reposeAngle (36 48); gasVelocity (0.75 1.25); }\n"
                 "work \"%s\";\n" % (tmp_path / "work"))
    s = read_sweep(str(p))
    cases = plan.cases_of(s)
    chains = plan.chains_of(s, cases)
    assert [[c["name"] for c in ch] for ch in chains] == [["phi36_Vg0.75", "phi36_Vg1.25"],
                                                          ["phi48_Vg0.75", "phi48_Vg1.25"]]
    second = chains[0][1]
    assert second["args"][second["args"].index("-startFrom") + 1] == plan.case_dir(s, chains[0][0])
    assert "-startFrom" not in chains[1][0]["args"] and "-keep" not in second["args"]
