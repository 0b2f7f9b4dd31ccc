"""foamDictionary: the one way the project's Python tools read and edit OpenFOAM
dictionaries (through the packaged `foamDictionary` utility).

What OpenFOAM prints on stdout besides the value cannot become a value:

- the child's PWD is set to its real working folder, so OpenFOAM has no
  "PWD is not the cwd()" warning to print (a caller started with `cwd=` from
  a program whose PWD is stale gave one);
- any warning block OpenFOAM still prints (`--> FOAM Warning :` and its
  indented lines) is taken out of the output before it is read;
- the output is read as bytes and decoded without failing; a dictionary that is
  not text (a NUL byte, or bytes that are not UTF-8) is refused before it is
  read, naming the file and the line.

Every failure is a FoamDictionaryError naming the file and the entry.
"""

import os
import subprocess


class FoamDictionaryError(Exception):
    """A dictionary or an entry that cannot be read or set."""

    def __init__(self, path, entry, message):
        self.path, self.entry = path, entry
        where = path + (": entry '%s'" % entry if entry else "")
        super().__init__("%s: %s" % (where, message))


def check_text(path):
    """Refuse a file that is not UTF-8 text (FoamDictionaryError naming the line)."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise FoamDictionaryError(path, None, e.strerror or str(e))
    for n, line in enumerate(data.split(b"\n"), 1):
        if b"\0" in line:
            raise FoamDictionaryError(path, None, "line %d holds a NUL byte: not a text dictionary "
                                      "(binary content?)" % n)
        try:
            line.decode("utf-8")
        except UnicodeDecodeError as e:
            raise FoamDictionaryError(path, None, "line %d, byte %d (0x%02x) is not UTF-8 text"
                                      % (n, e.start + 1, line[e.start]))


def strip_warnings(text):
    """`text` without OpenFOAM's warning blocks (a '--> FOAM Warning' line and the
    indented lines after it)."""
    out, inside = [], False
    for line in text.splitlines(keepends=True):
        if line.startswith("--> FOAM Warning"):
            inside = True
            continue
        if inside and (line.startswith("    ") or not line.strip()):
            continue
        inside = False
        out.append(line)
    return "".join(out)


def _decode(data):
    return data.decode("utf-8", errors="replace")


def last_error(stderr, stdout=""):
    """The gist of a failed foamDictionary call: the lines after its FATAL line."""
    lines = [l.strip() for l in strip_warnings(stderr or stdout).splitlines() if l.strip()]
    for i, l in enumerate(lines):
        if "FOAM FATAL" in l:
            return " ".join(lines[i + 1:i + 3])
    return lines[-1] if lines else "no message"


def run(args, path, entry=None, cwd=None):
    """Run `foamDictionary ARGS PATH`; returns (returncode, stdout without warnings,
    stderr). The file is checked to be text first."""
    check_text(path)
    here = os.path.realpath(cwd or os.getcwd())
    env = dict(os.environ, PWD=here)
    try:
        r = subprocess.run(["foamDictionary"] + list(args) + [path], capture_output=True, cwd=here, env=env)
    except OSError as e:
        raise FoamDictionaryError(path, entry, "cannot run foamDictionary: %s (source etc/bashrc)"
                                  % (e.strerror or e))
    return r.returncode, strip_warnings(_decode(r.stdout)), _decode(r.stderr)


def has(path, entry):
    """Does the dictionary have the entry?"""
    return run(["-entry", entry, "-value"], path, entry)[0] == 0


def value(path, entry, default=None):
    """The entry's value as text (stripped); `default` if given and the entry is
    missing, else FoamDictionaryError."""
    rc, out, err = run(["-entry", entry, "-value"], path, entry)
    if rc != 0:
        if default is not None:
            return default
        raise FoamDictionaryError(path, entry, "missing or unreadable: %s" % last_error(err, out))
    text = out.strip()
    if not text:
        raise FoamDictionaryError(path, entry, "has no value")
    return text


def scalar(path, entry):
    """The entry's value as a finite number."""
    text = value(path, entry)
    try:
        v = float(text)
    except ValueError:
        v = float("nan")
    if v != v or v in (float("inf"), float("-inf")):
        raise FoamDictionaryError(path, entry, "'%s' is not a finite number" % text)
    return v


def keywords(path, entry=None):
    """The keywords of the dictionary (or of its sub-dictionary `entry`)."""
    args = (["-entry", entry] if entry else []) + ["-keywords"]
    rc, out, err = run(args, path, entry)
    if rc != 0:
        raise FoamDictionaryError(path, entry, "not a readable OpenFOAM dictionary: %s" % last_error(err, out))
    return out.split()


def set_value(path, entry, text):
    """Set (or add) the entry to `text`."""
    rc, out, err = run(["-entry", entry, "-set", text], path, entry)
    if rc != 0:
        raise FoamDictionaryError(path, entry, "could not be set to '%s': %s" % (text, last_error(err, out)))


def remove(path, entry):
    """Remove the entry."""
    rc, out, err = run(["-entry", entry, "-remove"], path, entry)
    if rc != 0:
        raise FoamDictionaryError(path, entry, "could not be removed: %s" % last_error(err, out))


def add(path, entry, text):
    """Add the entry with the value `text` (foamDictionary -add)."""
    rc, out, err = run(["-entry", entry, "-add", text], path, entry)
    if rc != 0:
        raise FoamDictionaryError(path, entry, "could not be added as '%s': %s" % (text, last_error(err, out)))
