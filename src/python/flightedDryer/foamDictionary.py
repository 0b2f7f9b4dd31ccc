"""foamDictionary: the one way the project's Python tools read and edit OpenFOAM
dictionaries, with the semantics of the packaged `foamDictionary` utility.

The requests go to one `foamDictionaryServer` per Python process (the project's
utility, started at the first request): it serves foamDictionary's -entry with
-value, -keywords, -set, -add and -remove, reading each file afresh and writing
a changed one as foamDictionary does, in one OpenFOAM process instead of one per
entry (a curtain case's set-up asks for about a hundred entries, each
foamDictionary start costing about 12 ms of CPU). The server ends when its
input closes: at this process's exit, or its death. With the environment
variable DRYER_FOAMDICTIONARY=packaged each request runs the packaged
foamDictionary instead (the benchmarks' reference cost).

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

import atexit
import os
import subprocess
import threading


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


class _Server:
    """The foamDictionaryServer co-process of this Python process (a child
    started after a fork gets a server of its own)."""

    command = ["foamDictionaryServer"]

    def __init__(self):
        self.proc, self.pid = None, None
        self.lock = threading.Lock()

    def _start(self):
        self.proc = subprocess.Popen(self.command, stdin=subprocess.PIPE,
                                     stdout=subprocess.PIPE, cwd="/", env=dict(os.environ, PWD="/"))
        self.pid = os.getpid()

    def stop(self):
        if self.proc is not None and self.pid == os.getpid():
            try:
                self.proc.stdin.close()
                self.proc.wait(timeout=10)
            except (OSError, subprocess.TimeoutExpired):
                self.proc.kill()
                self.proc.wait()
        self.proc = None

    def _read_block(self):
        n = int(self.proc.stdout.readline())
        data = self.proc.stdout.read(n)
        if len(data) != n:
            raise EOFError
        return data

    def call(self, words):
        """(returncode, stdout, stderr) of one request; OSError if the server
        cannot be started, RuntimeError if it dies answering (one found dead
        between requests is replaced)."""
        message = b"%d\n" % len(words) + b"".join(b"%d\n%s" % (len(w), w) for w in map(os.fsencode, words))
        with self.lock:
            if self.proc is None or self.pid != os.getpid() or self.proc.poll() is not None:
                self._start()
            try:
                self.proc.stdin.write(message)
                self.proc.stdin.flush()
                rc = int(self.proc.stdout.readline())
                return rc, self._read_block(), self._read_block()
            except (OSError, ValueError, EOFError):
                try:
                    code = self.proc.wait(timeout=5)
                except subprocess.TimeoutExpired:     # alive but not answering
                    self.proc.kill()
                    code = self.proc.wait()
                self.proc = None
                raise RuntimeError("foamDictionaryServer stopped (exit code %s)" % code)


_server = _Server()
atexit.register(_server.stop)


def _packaged(args, path, entry, here):
    """One request by the packaged foamDictionary, a process of its own (the
    way of DRYER_FOAMDICTIONARY=packaged: what a set-up cost before the server,
    for benchmarks and for comparing the two)."""
    try:
        r = subprocess.run(["foamDictionary"] + list(args) + [path], capture_output=True, cwd=here,
                           env=dict(os.environ, PWD=here))
    except OSError as e:
        raise FoamDictionaryError(path, entry, "cannot run foamDictionary: %s (source etc/bashrc)"
                                  % (e.strerror or e))
    return r.returncode, strip_warnings(_decode(r.stdout)), _decode(r.stderr)


def run(args, path, entry=None, cwd=None):
    """`foamDictionary ARGS PATH` (served by foamDictionaryServer); returns
    (returncode, stdout without warnings, stderr). The file is checked to be
    text first."""
    check_text(path)
    here = os.path.realpath(cwd or os.getcwd())
    if os.environ.get("DRYER_FOAMDICTIONARY") == "packaged":
        return _packaged(args, path, entry, here)
    try:
        rc, out, err = _server.call([here] + list(args) + [path])
    except OSError as e:
        raise FoamDictionaryError(path, entry, "cannot run foamDictionaryServer: %s (source etc/bashrc; "
                                  "./Allwmake builds it)" % (e.strerror or e))
    except RuntimeError as e:
        raise FoamDictionaryError(path, entry, str(e))
    return rc, strip_warnings(_decode(out)), _decode(err)


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
