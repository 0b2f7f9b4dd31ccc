"""tests/benchmarks/curtainPeer/earlierSettings.bash, the one reader of the template's
earlier solver settings (the ladder's rungs, the warmStart benchmark's reference sweep):
groups in the file's order, an entry two groups set printed once with the first group's
(older) value, a malformed line refused with its number."""
import os
import shutil
import subprocess

from flightedDryer import PROJECT

HERE = os.path.join(PROJECT, "tests", "benchmarks", "curtainPeer")


def earlier_settings(folder, *groups):
    cmd = '. "%s/earlierSettings.bash" && earlier_settings "$@"' % folder
    return subprocess.run(["bash", "-c", cmd, "earlier_settings", *groups],
                          capture_output=True, text=True)


def edits(text):
    return [tuple(line.split("\t")) for line in text.splitlines()]


def copy(tmp_path, settings):
    shutil.copy(os.path.join(HERE, "earlierSettings.bash"), tmp_path)
    (tmp_path / "earlierSettings").write_text(settings)
    return str(tmp_path)


def test_an_entry_two_groups_set_takes_the_first_groups_value(tmp_path):
    folder = copy(tmp_path, "# comment\n\n"
                  "courant  system/fvSolution  PIMPLE/maxCo  2\n"
                  "cache    system/fvSolution  cache  {}\n"
                  "steps    system/fvSolution  PIMPLE/maxCo  5\n"
                  "steps    system/fvSolution  PIMPLE/startUp/maxCoHold  0\n")
    r = earlier_settings(folder)
    assert r.returncode == 0, r.stderr
    assert edits(r.stdout) == [("system/fvSolution", "PIMPLE/maxCo", "2"),
                               ("system/fvSolution", "cache", "{}"),
                               ("system/fvSolution", "PIMPLE/startUp/maxCoHold", "0")]
    # the groups named only, in the file's order whatever the order asked
    r = earlier_settings(folder, "steps", "cache")
    assert edits(r.stdout) == [("system/fvSolution", "cache", "{}"),
                               ("system/fvSolution", "PIMPLE/maxCo", "5"),
                               ("system/fvSolution", "PIMPLE/startUp/maxCoHold", "0")]
    assert earlier_settings(folder, "none").stdout == ""


def test_a_value_may_hold_spaces(tmp_path):
    folder = copy(tmp_path, "g  system/fvSolution  solvers/p/smoother  a b  c\n")
    assert edits(earlier_settings(folder).stdout) == [("system/fvSolution", "solvers/p/smoother", "a b c")]


def test_a_malformed_line_is_refused_with_its_number(tmp_path):
    folder = copy(tmp_path, "g  system/fvSolution  PIMPLE/maxCo  2\ng  system/fvSolution\n")
    r = earlier_settings(folder)
    assert r.returncode != 0
    assert "earlierSettings:2: expected GROUP FILE ENTRY VALUE" in r.stderr


def test_the_shipped_settings_start_the_ladder_at_maxCo_2():
    # the courant group's maxCo 2 (before the steps group's 5) is what every earlier
    # sweep ran with; each ladder group is in the file
    r = earlier_settings(HERE)
    assert r.returncode == 0, r.stderr
    got = {(f, e): v for f, e, v in edits(r.stdout)}
    assert got[("system/fvSolution", "PIMPLE/maxCo")] == "2"
    assert got[("system/fvSolution", "PIMPLE/startUp/iterations")] == "0"
    assert len(got) == len(edits(r.stdout))
    assert edits(earlier_settings(HERE, "steps").stdout)[0] == ("system/fvSolution", "PIMPLE/maxCo", "5")
