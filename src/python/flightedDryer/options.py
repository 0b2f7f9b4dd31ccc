"""options: a tool's command-line options, each given once and checked against
its allowed range; a bad one is an InputError naming the option and the range."""

import math
import sys

from .errors import InputError


def parse(argv, flags, valued, required, tool, usage):
    """{option: value or True} of argv. -help prints `usage` and exits; an
    unknown option, one given twice or one without its value is an InputError."""
    opts = {}
    i = 0
    while i < len(argv):
        a = argv[i]
        if a in ("-h", "-help", "--help"):
            print(usage)
            sys.exit(0)
        if a in opts:
            raise InputError("option %s given twice (%s and %s): give it once"
                             % (a, "set" if opts[a] is True else "'%s'" % opts[a],
                                "set" if a in flags else "'%s'" % (argv[i + 1] if i + 1 < len(argv) else "")))
        if a in flags:
            opts[a] = True
            i += 1
        elif a in valued:
            if i + 1 >= len(argv):
                raise InputError("option %s needs a value" % a)
            opts[a] = argv[i + 1]
            i += 2
        else:
            raise InputError("unknown option '%s' (see %s -help)" % (a, tool))
    for req in required:
        if req not in opts:
            raise InputError("missing option %s (see %s -help)" % (req, tool))
    return opts


def number(opts, key, lo, hi, units, lo_open=True, hi_open=False):
    """The option's value, a finite number in the range (lo, hi] (or as the flags say)."""
    text = opts[key]
    try:
        v = float(text)
    except ValueError:
        raise InputError("%s = '%s' is not a number" % (key, text))
    ok_lo = v > lo if lo_open else v >= lo
    ok_hi = v < hi if hi_open else v <= hi
    if not (math.isfinite(v) and ok_lo and ok_hi):
        raise InputError("%s = %s %s outside the allowed range %s%g, %g%s %s"
                         % (key, text, units, "(" if lo_open else "[", lo, hi,
                            ")" if hi_open else "]", units))
    return v


def whole(opts, key, lo, hi, units, lo_open=True, hi_open=False):
    """The option's value, a whole number in the range of number()."""
    v = number(opts, key, lo, hi, units, lo_open, hi_open)
    if v != int(v):
        raise InputError("%s = %s is not a whole number of %s" % (key, opts[key], units))
    return int(v)


def choice(opts, key, allowed, default=None):
    """A named option: one of `allowed` (default: its first)."""
    v = opts.get(key, default if default is not None else allowed[0])
    if v not in allowed:
        raise InputError("%s '%s' is not one of %s" % (key, v, " ".join(allowed)))
    return v


def number_list(opts, key, lo, hi, units):
    """A comma-separated list of finite numbers, each in (lo, hi]."""
    items = [t for t in opts[key].split(",")]
    out = []
    for t in items:
        try:
            v = float(t)
        except ValueError:
            raise InputError("%s: '%s' is not a number (comma-separated list expected)" % (key, t))
        if not (math.isfinite(v) and lo < v <= hi):
            raise InputError("%s: %s %s outside the allowed range (%g, %g] %s"
                             % (key, t, units, lo, hi, units))
        out.append(v)
    return out
