"""docFigures: the figures the README and docs/ quote, written from the results
files that hold them, never typed.

Two kinds of marker, both HTML comments, so a rendered page shows the values
only:

- a figure:  <!--fig FILE ROW COLUMN FORMAT-->0.37<!--/fig-->
  FILE: a CSV of results, relative to the checkout ('#' lines are comments);
  ROW: the row, as column=value pairs joined by '&' (exactly one row must
  match; a value is URL-quoted, '%20' for a space), or '-' for a file of
  one row;
  COLUMN: the column quoted, optionally scaled: 'rms_ln', 'mean_s/60'
  (divided) or 'within25*100' (multiplied);
  FORMAT: a printf number format, '%.2f', '%.0f', '%+.2f'. A negative value
  is written with a true minus sign (U+2212).
- a tested bound:  <!--in FILE NEEDLE-->within 2 %<!--/in-->
  the text states a bound or value that a test or a results file asserts:
  NEEDLE (URL-quoted, '%20' for a space) must occur in FILE (the test or
  the results file);
- a table:   <!--table SCRIPT:FUNCTION-->  ...lines...  <!--/table-->
  (each marker on a line of its own): the lines between are FUNCTION(root)
  of the Python file SCRIPT (relative to the checkout), a generator that
  reads results files and returns Markdown.

update() rewrites every value and table from its files; check() lists what
differs. A marker whose file, row or column is missing, or whose value is not
a finite number, is an error naming the document and its line.

unmarked() lists the numbers of a document that look like a measured figure
(a decimal number or a percentage) but stand outside every marker, so a test
can require that a document states none by hand.
"""

import csv
import importlib.util
import math
import os
import re
import urllib.parse

from . import files

MARKER = re.compile(r"<!--fig (\S+) (\S+) (\S+) (\S+?)-->(.*?)<!--/fig-->")
IN_MARKER = re.compile(r"<!--in (\S+) (\S+?)-->(.*?)<!--/in-->")
TABLE_OPEN = re.compile(r"^<!--table (\S+):(\w+)-->$")
TABLE_CLOSE = "<!--/table-->"
MINUS = "\u2212"


class FigureError(Exception):
    """A marker that cannot be filled from its results file."""


def read_rows(path):
    """The rows of a results CSV as dicts ('#' lines skipped)."""
    with open(path, newline="", encoding="utf-8") as f:
        lines = [line for line in f if not line.startswith("#")]
    return list(csv.DictReader(lines))


def finite(text, where):
    """text as a finite float, or a FigureError naming where."""
    try:
        v = float(text)
    except (TypeError, ValueError):
        raise FigureError("%s: '%s' is not a number" % (where, text))
    if not math.isfinite(v):
        raise FigureError("%s: the value %s is not finite" % (where, text))
    return v


def fmt(value, form="%.3f"):
    """value in the printf format form, a negative with a true minus sign."""
    try:
        text = form % value
    except (TypeError, ValueError):
        raise FigureError("format '%s' is not a printf number format" % form)
    if text.startswith("-"):
        # a value that rounds to zero is written without a sign
        return text[1:] if float(text) == 0 else MINUS + text[1:]
    return text


def _scaled(text, column, where):
    m = re.fullmatch(r"([^*/]+)(?:([*/])([0-9.eE+-]+))?", column)
    if not m:
        raise FigureError("%s: column '%s' is not NAME, NAME/N or NAME*N" % (where, column))
    v = finite(text, where)
    if m.group(2) == "/":
        v /= float(m.group(3))
    elif m.group(2) == "*":
        v *= float(m.group(3))
    return v


class Results:
    """Cached reads of results CSVs below a checkout, by path relative to it."""

    def __init__(self, root):
        self.root = root
        self._rows = {}

    def rows(self, file, where=""):
        if file not in self._rows:
            try:
                self._rows[file] = read_rows(os.path.join(self.root, file))
            except OSError as e:
                raise FigureError("%scannot read %s: %s"
                                  % (where + ": " if where else "", file, e.strerror or e))
        return self._rows[file]

    def row(self, file, row, where=""):
        """The one row of file matching row ('a=1&b=x', a dict, or '-')."""
        rows = self.rows(file, where)
        if isinstance(row, dict):
            wanted = [(k, str(v)) for k, v in row.items()]
        elif row == "-":
            wanted = []
        else:
            wanted = []
            for pair in row.split("&"):
                if "=" not in pair:
                    raise FigureError("%s: row '%s' is not column=value pairs joined by &"
                                      % (where, row))
                k, v = pair.split("=", 1)
                wanted.append((k, urllib.parse.unquote(v)))
        found = [r for r in rows if all(r.get(k) == v for k, v in wanted)]
        if len(found) != 1 or (not wanted and len(rows) != 1):
            raise FigureError("%s: %d rows of %s match '%s' (one must)"
                              % (where, len(found), file, row))
        return found[0]

    def value(self, file, row, column, where=""):
        """The finite value of column (optionally scaled) in the row of file."""
        r = self.row(file, row, where)
        name = re.split(r"[*/]", column)[0]
        if name not in r:
            raise FigureError("%s: %s has no column '%s'" % (where, file, name))
        return _scaled(r[name], column, "%s: %s %s %s" % (where, file, row, column))


def value(root, file, row, column, form, where, cache=None):
    """The figure's text: FORMAT of COLUMN in the ROW of FILE."""
    results = cache if isinstance(cache, Results) else Results(root)
    v = results.value(file, row, column, where)
    try:
        return fmt(v, form)
    except FigureError as e:
        raise FigureError("%s: %s" % (where, e))


def _generator(root, script, function, where):
    path = os.path.join(root, script)
    if not os.path.isfile(path):
        raise FigureError("%s: no table script %s" % (where, script))
    spec = importlib.util.spec_from_file_location("docTables_" + re.sub(r"\W", "_", script), path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    fn = getattr(mod, function, None)
    if not callable(fn):
        raise FigureError("%s: %s has no table function '%s'" % (where, script, function))
    return fn


def render(root, doc, text):
    """(new text, [(line, what, stated, generated)]) for text of doc: every
    figure and table filled from its results file."""
    results = Results(root)
    lines = text.split("\n")
    out, diffs, i = [], [], 0
    while i < len(lines):
        line, n = lines[i], i + 1
        where = "%s:%d" % (doc, n)
        t = TABLE_OPEN.match(line.strip())
        if t:
            end = next((j for j in range(i + 1, len(lines)) if lines[j].strip() == TABLE_CLOSE), None)
            if end is None:
                raise FigureError("%s: table marker without %s" % (where, TABLE_CLOSE))
            try:
                body = _generator(root, t.group(1), t.group(2), where)(results).rstrip("\n")
            except FigureError as e:
                raise FigureError("%s: table %s:%s: %s" % (where, t.group(1), t.group(2), e))
            stated = "\n".join(lines[i + 1:end])
            if stated != body:
                diffs.append((n, "table %s:%s" % t.groups(), stated, body))
            out += [line] + body.split("\n") + [lines[end]]
            i = end + 1
            continue

        def fill(m):
            v = value(root, *m.groups()[:4], where, results)
            if v != m.group(5):
                diffs.append((n, "%s %s %s" % m.groups()[:3], m.group(5), v))
            return "<!--fig %s %s %s %s-->%s<!--/fig-->" % (m.groups()[:4] + (v,))
        # a marker inside a code span is an example of the syntax, not a figure
        parts = re.split(r"(`[^`]*`)", line)
        for k in range(0, len(parts), 2):
            for m in IN_MARKER.finditer(parts[k]):
                _tested(results.root, m.group(1), urllib.parse.unquote(m.group(2)), where)
            parts[k] = MARKER.sub(fill, parts[k])
        out.append("".join(parts))
        i += 1
    return "\n".join(out), diffs


def _tested(root, file, needle, where):
    """A FigureError unless needle occurs in file (a test or a results file)."""
    try:
        with open(os.path.join(root, file), encoding="utf-8", errors="replace") as f:
            text = f.read()
    except OSError as e:
        raise FigureError("%s: cannot read %s: %s" % (where, file, e.strerror or e))
    if needle not in text:
        raise FigureError("%s: %s does not hold '%s'" % (where, file, needle))


def _read(root, doc):
    with open(os.path.join(root, doc), encoding="utf-8") as f:
        return f.read()


def update(root, doc):
    """Rewrite doc's figures and tables from their files (atomically);
    returns how many changed."""
    text = _read(root, doc)
    new, diffs = render(root, doc, text)
    if new != text:
        files.atomic_write(os.path.join(root, doc), new.encode("utf-8"))
    return len(diffs)


def check(root, doc):
    """The figures and tables of doc that differ from their files, as messages."""
    _, diffs = render(root, doc, _read(root, doc))
    msgs = []
    for n, what, stated, actual in diffs:
        if what.startswith("table"):
            msgs.append("%s:%d: %s differs from what its results give (run docs/figures -update)"
                        % (doc, n, what))
        else:
            msgs.append("%s:%d: states %s, %s gives %s" % (doc, n, stated, what, actual))
    return msgs


# A figure by hand: a decimal number, a number before a percent sign, or a
# whole number of seconds, minutes or a speed-up (22 s, 10 min, 7x).
FIGURE = re.compile(r"(?<![\w.\-/])([+" + MINUS + r"-]?\d+\.\d+|\d+(?=\s?(%|s\b|min\b|ms\b|ns\b|µs\b|x\b)))"
                    r"(?![\w.]*\d)")
# What a number may stand for without a marker: an input in one of these
# units (a range 'a–b unit' too).
INPUT_AFTER = re.compile(r"^([–-]\d+(\.\d+)?)?\s?(m/s|kg/\(m\s?s\)|kg/m3|kg/m³|kPa|mm|µm|um|°C?|K\b|Pa\b|rpm|"
                         r"m\b|cm\b|1/m|m\))")
REFERENCE_BEFORE = re.compile(r"(Eqs?\.?|Equations?|Tables?|sections?|Figs?\.?|Figures?|§|Ch\.|"
                              r"Chapter|v|version|pp?\.)\s?([\d.,–-]|\s|and\b|to\b)*$")
# A threshold (a goal or an allowed range), not a result: ±x, ≤ x, ≥ x.
THRESHOLD_BEFORE = re.compile(r"[±≤≥<>]\s?$")


def _strip_marked(line):
    line = MARKER.sub(lambda m: " " * len(m.group(0)), line)
    line = IN_MARKER.sub(lambda m: " " * len(m.group(0)), line)
    return re.sub(r"`[^`]*`", lambda m: " " * len(m.group(0)), line)


def unmarked(root, doc):
    """(line, number, context) of every figure-like number of doc outside the
    markers, code spans and code blocks (inputs in a unit and references to
    the theses' equations and tables are not figures)."""
    found, in_code, in_table = [], False, False
    for n, raw in enumerate(_read(root, doc).split("\n"), 1):
        s = raw.strip()
        if s.startswith("```"):
            in_code = not in_code
            continue
        if TABLE_OPEN.match(s):
            in_table = True
            continue
        if s == TABLE_CLOSE:
            in_table = False
            continue
        if in_code or in_table:
            continue
        line = _strip_marked(raw)
        line = re.sub(r"<!--.*?-->|\]\([^)]*\)", lambda m: " " * len(m.group(0)), line)
        for m in FIGURE.finditer(line):
            after, before = line[m.end():], line[:m.start()]
            if not after.lstrip().startswith("%") and INPUT_AFTER.match(after):
                continue
            if REFERENCE_BEFORE.search(before) or THRESHOLD_BEFORE.search(before):
                continue
            found.append((n, m.group(1), raw[max(0, m.start() - 30):m.end() + 20].strip()))
    return found
