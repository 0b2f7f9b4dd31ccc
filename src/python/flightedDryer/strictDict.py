"""strictDict: an OpenFOAM-format dictionary read strictly, for the sweep
dictionaries: the project's own scan finds every keyword with its line and
refuses a keyword given twice (OpenFOAM keeps the last silently) and unbalanced
brackets; values are read with the packaged foamDictionary; every error names
the file, the line and the entry, with the allowed range."""

import difflib
import math
import os

from . import PROJECT, foamDictionary
from .errors import InputError


def scan_keys(path, text):
    """Keywords of an OpenFOAM dictionary with their line numbers, as
    {key: (line, {subkey: line})} for the top level and one level of
    sub-dictionaries. Refuses duplicated keywords (OpenFOAM keeps the last one
    silently) and unbalanced brackets, naming the file and the line."""
    tokens = []
    i, line, n = 0, 1, len(text)
    while i < n:
        c = text[i]
        if c == "\n":
            line += 1
            i += 1
        elif c.isspace():
            i += 1
        elif text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            if j < 0:
                raise InputError("%s:%d: comment '/*' is never closed" % (path, line))
            line += text.count("\n", i, j)
            i = j + 2
        elif c == '"':
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            if j >= n:
                raise InputError("%s:%d: string is never closed" % (path, line))
            tokens.append(("str", text[i:j + 1], line))
            line += text.count("\n", i, j)
            i = j + 1
        elif c in "{}();":
            tokens.append((c, c, line))
            i += 1
        else:
            j = i
            while j < n and not text[j].isspace() and text[j] not in "{}();\"":
                j += 1
            tokens.append(("word", text[i:j], line))
            i = j
    top = {}
    stack = []            # open brackets
    current = [top]       # dictionaries being filled (top, then a sub-dictionary)
    expect_key = True
    last_key = None
    for kind, val, ln in tokens:
        if kind in "({":
            if kind == "{" and stack == [] and last_key is not None and top.get(last_key, (0, None))[1] is not None:
                current.append(top[last_key][1])
            stack.append((kind, ln))
            expect_key = kind == "{"
            continue
        if kind in ")}":
            want = "(" if kind == ")" else "{"
            if not stack or stack[-1][0] != want:
                raise InputError("%s:%d: unbalanced '%s'" % (path, ln, kind))
            stack.pop()
            if kind == "}":
                if len(stack) == 0 and len(current) > 1:
                    current.pop()
                expect_key = not stack or stack[-1][0] == "{"
            else:
                expect_key = False   # a list value: the entry ends at its ';'
            continue
        if kind == ";":
            expect_key = not stack or stack[-1][0] == "{"
            continue
        if expect_key and (not stack or stack[-1][0] == "{"):
            expect_key = False
            if val.startswith("#"):
                raise InputError("%s:%d: directive %s is not supported in a sweep dictionary "
                                "(write the entries out)" % (path, ln, val))
            depth = len(stack)
            if depth == 0:
                if val in top:
                    raise InputError("%s:%d: entry '%s' given twice (first on line %d)"
                                    % (path, ln, val, top[val][0]))
                top[val] = (ln, {})
                last_key = val
            elif depth == 1 and len(current) > 1:
                sub = current[-1]
                if val in sub:
                    raise InputError("%s:%d: entry '%s/%s' given twice (first on line %d)"
                                    % (path, ln, last_key, val, sub[val]))
                sub[val] = ln
    if stack:
        raise InputError("%s:%d: '%s' is never closed" % (path, stack[-1][1], stack[-1][0]))
    return top


def check_allowed(path, top, allowed, sub_allowed, sub_name, note=lambda key: "", sub_note=""):
    """Unknown entries are refused with the nearest allowed name: `allowed` at the
    top level, `sub_allowed` in the sub-dictionary `sub_name`."""
    for key, (ln, sub) in top.items():
        if key not in allowed:
            near = difflib.get_close_matches(key, allowed, 1, 0.6)
            raise InputError("%s:%d: unknown entry '%s'%s%s; allowed entries: %s"
                             % (path, ln, key, " (did you mean '%s'?)" % near[0] if near else "",
                                note(key), " ".join(allowed[1:])))
        if key == sub_name:
            for g, gl in sub.items():
                if g not in sub_allowed:
                    near = difflib.get_close_matches(g, sub_allowed, 1, 0.6)
                    raise InputError("%s:%d: unknown entry '%s/%s'%s; allowed%s: %s"
                                     % (path, gl, sub_name, g, " (did you mean '%s/%s'?)" % (sub_name, near[0])
                                        if near else "", sub_note, " ".join(sub_allowed)))
    return top


class StrictDict:
    """A dictionary read entry by entry with the packaged foamDictionary, its
    keywords and their lines scanned first (scan_keys)."""

    def __init__(self, path):
        self.path = os.path.abspath(path)
        if not os.path.isfile(self.path):
            raise InputError("%s: no such file" % path)
        try:
            # text first, then the project's own scan (duplicates, brackets: OpenFOAM's
            # reader keeps a repeated entry's last value, and foamDictionary can crash on one)
            foamDictionary.check_text(self.path)
            with open(self.path, encoding="utf-8") as f:
                self.lines = scan_keys(self.path, f.read())
            self.keys = foamDictionary.keywords(self.path)
        except foamDictionary.FoamDictionaryError as e:
            raise InputError(str(e))

    def where(self, entry):
        """'file:line: entry' for messages."""
        head = entry.split("/")[0]
        ln = self.lines.get(head, (None, {}))[0]
        if "/" in entry and head in self.lines:
            ln = self.lines[head][1].get(entry.split("/", 1)[1], ln)
        return "%s:%s" % (self.path, ln) if ln else self.path

    def has(self, entry):
        return foamDictionary.has(self.path, entry)

    def value(self, entry, default=None):
        rc, out, err = foamDictionary.run(["-entry", entry, "-value"], self.path, entry)
        if rc != 0:
            if default is not None:
                return default
            raise InputError("%s: entry '%s' missing or unreadable: %s"
                            % (self.where(entry), entry, foamDictionary.last_error(err, out)))
        return out.strip()

    def string(self, entry, default=None):
        """A path or name: a quoted string or a single word."""
        v = self.value(entry, default)
        if len(v) >= 2 and v[0] == '"' and v[-1] == '"':
            return v[1:-1]
        if len(v.split()) != 1:
            raise InputError("%s: entry '%s' = '%s' is not a single word or a quoted string"
                            % (self.where(entry), entry, v))
        return v

    def word(self, entry, default=None, allowed=None):
        v = self.value(entry, default)
        if len(v.split()) != 1 or v.startswith("("):
            raise InputError("%s: entry '%s' = '%s' is not a single word" % (self.where(entry), entry, v))
        if allowed and v not in allowed:
            raise InputError("%s: entry '%s' = '%s' is not one of %s"
                            % (self.where(entry), entry, v, " ".join(allowed)))
        return v

    def whole(self, entry, lo, hi, multiple=1, why=""):
        """A whole number in [lo, hi] (and a multiple of `multiple`), or None if absent."""
        if not self.has(entry):
            return None
        text = self.value(entry)
        if not text.isdigit() or not lo <= int(text) <= hi or int(text) % multiple:
            raise InputError("%s: entry '%s' = '%s' outside the allowed range [%d, %d] (a whole number%s)"
                            % (self.where(entry), entry, text, lo, hi,
                               ", a multiple of %d%s" % (multiple, why) if multiple > 1 else ""))
        return int(text)

    def folder(self, entry, default):
        """A case folder, relative to the project."""
        path = os.path.join(PROJECT, self.string(entry, default))
        if not os.path.isdir(path):
            raise InputError("%s: entry '%s': no case folder %s" % (self.where(entry), entry, path))
        return path

    def scalar(self, entry, lo, hi, units=""):
        """A number in the closed range [lo, hi]."""
        text = self.value(entry)
        try:
            v = float(text)
        except ValueError:
            v = float("nan")
        if not lo <= v <= hi:
            raise InputError("%s: entry '%s' = '%s' outside the allowed range [%g, %g]%s"
                            % (self.where(entry), entry, text, lo, hi, " " + units if units else ""))
        return v

    def scalar_list(self, entry, lo, hi, units, increasing=True, lo_closed=False):
        text = self.value(entry)
        tokens = _list_tokens(text)
        if tokens is None or not tokens:
            raise InputError("%s: entry '%s' = '%s' is not a non-empty list (v1 v2 ...)"
                            % (self.where(entry), entry, text))
        out = []
        for t in tokens:
            try:
                v = float(t)
            except ValueError:
                raise InputError("%s: entry '%s': '%s' is not a number" % (self.where(entry), entry, t))
            if not (math.isfinite(v) and (lo <= v if lo_closed else lo < v) and v <= hi):
                raise InputError("%s: entry '%s': %s %s outside the allowed range %s%g, %g] %s"
                                % (self.where(entry), entry, t, units, "[" if lo_closed else "(", lo, hi, units))
            out.append(v)
        if increasing and any(b <= a for a, b in zip(out[:-1], out[1:])):
            raise InputError("%s: entry '%s' = %s must be strictly increasing"
                            % (self.where(entry), entry, text))
        return out


def _list_tokens(text):
    """Tokens of an OpenFOAM list value as printed by foamDictionary: '(a b c)' or
    'N(a b c)'."""
    t = text.strip()
    if "(" not in t or not t.endswith(")"):
        return None
    head, body = t.split("(", 1)
    if head.strip() and not head.strip().isdigit():
        return None
    tokens = body[:-1].split()
    if head.strip() and int(head) != len(tokens):
        return None
    return tokens
