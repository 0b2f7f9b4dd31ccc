"""foamDictionary: values read so that OpenFOAM's warnings cannot become a value,
and a dictionary that is not text refused naming the line."""

import os
import signal
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


DICT = ("FoamFile { version 2.0; format ascii; class dictionary; object d; }\n"
        "#include \"inc\"\nlevel coarse;\nx $a;\nlevels { coarse { n 4; g 0.5; } fine { n 8; } }\n"
        "functions { f1 { type a; } f2 { type b; } }\n\"alpha.*\" { tol 1e-10; }\n")
EDITS = [["-entry", "levels/coarse/n", "-set", "5"], ["-entry", "functions/f1", "-remove"],
         ["-entry", "functions/f3", "-set", "{ type c; libs (x y); w 0.5; }"],
         ["-entry", "b", "-add", "( 1 2.5e-7 3 )"], ["-entry", "level", "-set", "fine"],
         ["-entry", "x", "-set", "\"quoted\""]]
READS = [["-entry", "levels/coarse/g", "-value"], ["-entry", "levels", "-keywords"], ["-keywords"],
         ["-entry", "levels/fine", "-value"], ["-entry", "alpha.air", "-value"], ["-entry", "x", "-value"],
         ["-entry", "nope", "-value"], ["-entry", "functions/f3"]]


def _folder(tmp_path, name):
    d = tmp_path / name
    d.mkdir()
    (d / "inc").write_text("a 3;\n")
    (d / "d").write_text(DICT)
    return d


def test_the_server_answers_and_writes_as_foamDictionary_does(tmp_path, monkeypatch):
    # the same requests through the server and one packaged foamDictionary process
    # each (DRYER_FOAMDICTIONARY=packaged): the same exit codes, values and files
    ours, theirs = _folder(tmp_path, "ours"), _folder(tmp_path, "theirs")
    answers = {}
    for way, folder in (("server", ours), ("packaged", theirs)):
        if way == "packaged":
            monkeypatch.setenv("DRYER_FOAMDICTIONARY", "packaged")
        answers[way] = [foamDictionary.run(args, str(folder / "d"))[:2] for args in EDITS + READS]
    # 'alpha.air' is scoped as alpha/air (not the "alpha.*" key) and 'nope' missing, in both
    assert [rc != 0 for rc, _ in answers["server"]] == [False] * 10 + [True, False, True, False]
    assert answers["server"] == answers["packaged"]
    assert answers["server"][6][1] == "0.5\n" and "libs" in answers["server"][13][1]
    assert (ours / "d").read_bytes() == (theirs / "d").read_bytes()
    assert sorted(os.listdir(ours)) == ["d", "inc"]          # no temporary file left beside it


def test_server_errors_name_the_file_and_entry(tmp_path):
    p = tmp_path / "d"
    p.write_text("a 1;\nb { c 2;\n")
    with pytest.raises(foamDictionary.FoamDictionaryError, match=r"d: entry 'a': missing or unreadable: "
                       r"Unexpected EOF while reading dictionary entry file: .*d at line 3"):
        foamDictionary.value(str(p), "a")
    p.write_text("a 1;\n")
    with pytest.raises(foamDictionary.FoamDictionaryError, match=r"entry 'x/c': could not be set.*'x' not found"):
        foamDictionary.set_value(str(p), "x/c", "2")
    with pytest.raises(foamDictionary.FoamDictionaryError, match="missing: No such file"):
        foamDictionary.keywords(str(tmp_path / "missing"))
    assert foamDictionary.scalar(str(p), "a") == 1          # the server still answers


def test_a_killed_server_is_replaced_and_a_fork_gets_its_own(tmp_path):
    p = tmp_path / "d"
    p.write_text("a 1;\n")
    assert foamDictionary.scalar(str(p), "a") == 1
    first = foamDictionary._server.proc
    for sig in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP):    # meant for its client: ignored
        first.send_signal(sig)
    assert foamDictionary.scalar(str(p), "a") == 1 and foamDictionary._server.proc is first
    first.kill()
    first.wait()
    assert foamDictionary.scalar(str(p), "a") == 1          # the next request starts a new one
    assert foamDictionary._server.proc is not first
    server = foamDictionary._Server()                      # one dying while it answers
    server.command = ["sh", "-c", "read n; exit 3"]
    with pytest.raises(RuntimeError, match=r"foamDictionaryServer stopped \(exit code 3\)"):
        server.call(["/", "-keywords", str(p)])
    r, w = os.pipe()
    pid = os.fork()
    if pid == 0:                                           # the child asks through a server of its own
        ok = foamDictionary.scalar(str(p), "a") == 1 and foamDictionary._server.pid == os.getpid()
        os.write(w, b"1" if ok else b"0")
        os._exit(0)
    os.waitpid(pid, 0)
    assert os.read(r, 1) == b"1"
    assert foamDictionary.scalar(str(p), "a") == 1          # the parent's server is untouched
