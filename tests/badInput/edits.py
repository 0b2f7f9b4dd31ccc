"""Line edits that turn a good input file into a bad one, for the bad-input sweep.

YAML files (drumDict, flight dictionaries): an entry is addressed as
"section.key" (or "key" at the top); OpenFOAM dictionaries (sweep dictionaries)
as "key" or "sub/key". Each edit returns the new text, or raises LookupError
when the entry is not in the file (a case that no longer applies fails loudly).
"""

import re


def _yaml_line(lines, entry):
    """Index of the line holding YAML entry section.key (two-space nesting)."""
    lo, hi, found = 0, len(lines), None
    for d, key in enumerate(entry.split(".")):
        ind = "  " * d
        pat = re.compile(r"^%s%s:(\s|$)" % (ind, re.escape(key)))
        for i in range(lo, hi):
            if pat.match(lines[i]):
                break
        else:
            raise LookupError(entry)
        j = i + 1   # the key's block: the lines indented deeper
        while j < hi and (not lines[j].strip() or lines[j].lstrip().startswith("#")
                          or lines[j].startswith(ind + "  ")):
            j += 1
        lo, hi, found = i + 1, j, i
    return found


def _edit(text, find, entry, change):
    """`change(lines, i, key)` applied at the line `find(lines, entry)` locates."""
    lines = text.split("\n")
    i = find(lines, entry)
    change(lines, i, re.split(r"[./]", entry)[-1])
    return "\n".join(lines)


def _indent(line):
    return line[:len(line) - len(line.lstrip())]


def yaml_set(text, entry, value):
    """Entry's value replaced (its comment left out)."""
    def change(lines, i, key):
        lines[i] = "%s%s: %s" % (_indent(lines[i]), key, value)
    return _edit(text, _yaml_line, entry, change)


def yaml_rename(text, entry, new_key):
    def change(lines, i, key):
        lines[i] = lines[i].replace(key + ":", new_key + ":", 1)
    return _edit(text, _yaml_line, entry, change)


def yaml_duplicate(text, entry):
    return _edit(text, _yaml_line, entry, lambda lines, i, key: lines.insert(i + 1, lines[i]))


def yaml_remove(text, entry):
    return _edit(text, _yaml_line, entry, lambda lines, i, key: lines.pop(i))


def _foam_line(lines, entry):
    """Index of the line holding OpenFOAM entry key or sub/key."""
    parts = entry.split("/")
    start = 0
    for d, key in enumerate(parts):
        pat = re.compile(r"^\s*%s(\s|$|;)" % re.escape(key))
        for i in range(start, len(lines)):
            if pat.match(lines[i]):
                start = i + (1 if d < len(parts) - 1 else 0)
                break
        else:
            raise LookupError(entry)
    return start


def foam_set(text, entry, value):
    def change(lines, i, key):
        lines[i] = "%s%s %s;" % (_indent(lines[i]), key, value)
    return _edit(text, _foam_line, entry, change)


def foam_rename(text, entry, new_key):
    def change(lines, i, key):
        lines[i] = lines[i].replace(key, new_key, 1)
    return _edit(text, _foam_line, entry, change)


def foam_duplicate(text, entry):
    return _edit(text, _foam_line, entry, lambda lines, i, key: lines.insert(i + 1, lines[i]))


def foam_remove(text, entry):
    return _edit(text, _foam_line, entry, lambda lines, i, key: lines.pop(i))


def csv_set(text, row, column, value):
    """Cell (row counted from 1 after the header) of a CSV replaced."""
    lines = text.split("\n")
    header = lines[0].split(",")
    j = header.index(column)
    cells = lines[row].split(",")
    cells[j] = value
    lines[row] = ",".join(cells)
    return "\n".join(lines)


def csv_rename_column(text, column, new):
    lines = text.split("\n")
    header = lines[0].split(",")
    header[header.index(column)] = new
    lines[0] = ",".join(header)
    return "\n".join(lines)
