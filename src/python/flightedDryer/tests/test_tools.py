"""The project's Python tools run on the interpreter the package is tested with
(Debian's /usr/bin/python3, which has the project's Debian packages), whatever
python3 comes first on PATH (a version manager's shim adds a few tenths of a
second of CPU to every run of a sweep and may lack those packages)."""

import os

from flightedDryer import PROJECT

INTERPRETER = "#!/usr/bin/python3"


def python_scripts():
    """Every file of the checkout's tools, tests, tutorials and validation whose
    first line names a Python interpreter."""
    found = []
    for top in ("applications", "docs", "tests", "tutorials", "validation"):
        for root, dirs, files in os.walk(os.path.join(PROJECT, top)):
            dirs[:] = [d for d in dirs if d not in ("results", "__pycache__")]
            for name in files:
                path = os.path.join(root, name)
                try:
                    with open(path, "rb") as f:
                        first = f.readline(200)
                except OSError:
                    continue
                if first.startswith(b"#!") and b"python" in first:
                    found.append((os.path.relpath(path, PROJECT), first.decode().strip()))
    return found


def test_every_python_tool_names_debians_interpreter():
    scripts = python_scripts()
    # the four command-line tools of a sweep and a study are among them
    names = {os.path.basename(p) for p, _ in scripts}
    assert {"curtainCase", "buildDriftTable", "drumSegmentCase", "dryerStudy"} <= names, names
    wrong = [(p, line) for p, line in scripts if line != INTERPRETER]
    assert wrong == [], wrong
