"""foamDictionary: values read so that OpenFOAM's warnings cannot become a value,
and a dictionary that is not text refused naming the line."""

import os
import subprocess
import sys

import pytest

from flightedDryer import foamDictionary  # noqa: E402

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", ".."))
MESH = os.path.join(ROOT, "etc", "templates", "curtain", "windTunnel", "system", "meshParameters")
WARNING = ("--> FOAM Warning : \n    From function Foam::fileName Foam::cwd_L()\n"
           "    in file POSIX.C at line 494\n    PWD is not the cwd() - reverting to physical description\n")


def test_warning_blocks_are_taken_out():
    assert foamDictionary.strip_warnings(WARNING + WARNING + "10.3\n") == "10.3\n"
    assert foamDictionary.strip_warnings("(1 2 3)\n") == "(1 2 3)\n"


def test_a_stale_pwd_cannot_become_a_value(tmp_path, monkeypatch):
    # the caller's PWD names another folder than its working one (a program started
    # with subprocess cwd=): OpenFOAM would print a warning on stdout before the value
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("PWD", "/")
    assert foamDictionary.value(MESH, "H") == "10.3"
    assert foamDictionary.scalar(MESH, "H") == 10.3


def test_curtain_case_check_under_a_stale_pwd():
    # the tool itself started by a program whose PWD is stale (no shell in between)
    r = subprocess.run([sys.executable, os.path.join(ROOT, "applications", "utilities", "curtainCase", "curtainCase"),
                        "-dir", "x", "-gasVelocity", "3", "-spillRate", "2", "-fallHeight", "4", "-flightLength", "1",
                        "-density", "1590", "-diameters", "850e-6", "-fractions", "1", "-check"],
                       cwd="/", env=dict(os.environ, PWD="/tmp"), capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "inputs checked: fall 4 m" in r.stdout


def test_not_text_is_refused_naming_the_line(tmp_path):
    p = tmp_path / "d"
    p.write_bytes(b"a 1;\nb \xff\xfe;\n")
    with pytest.raises(foamDictionary.FoamDictionaryError, match=r"line 2, byte 3 \(0xff\) is not UTF-8"):
        foamDictionary.keywords(str(p))
    p.write_bytes(b"a 1;\n\0\0\0")
    with pytest.raises(foamDictionary.FoamDictionaryError, match="line 2 holds a NUL byte"):
        foamDictionary.value(str(p), "a")


def test_missing_entries_and_non_numbers(tmp_path):
    p = tmp_path / "d"
    p.write_text("FoamFile { version 2.0; format ascii; class dictionary; object d; }\na 1;\nw word;\nn nan;\n")
    assert foamDictionary.value(str(p), "x", default="?") == "?"
    assert foamDictionary.has(str(p), "a") and not foamDictionary.has(str(p), "x")
    with pytest.raises(foamDictionary.FoamDictionaryError, match="entry 'x': missing or unreadable"):
        foamDictionary.value(str(p), "x")
    for entry in ("w", "n"):
        with pytest.raises(foamDictionary.FoamDictionaryError, match="is not a finite number"):
            foamDictionary.scalar(str(p), entry)
    foamDictionary.set_value(str(p), "a", "2")
    assert foamDictionary.scalar(str(p), "a") == 2
    assert foamDictionary.keywords(str(p)) == ["FoamFile", "a", "w", "n"]
