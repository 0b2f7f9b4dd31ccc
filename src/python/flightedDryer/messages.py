"""messages: what the tools print, and how numbers are written in it.

Every line a tool prints for its user starts with the tool's name; numbers in
messages, case names and result files are written by the formatters here, so
the same value reads the same everywhere.
"""

import math


def sayer(tool):
    """A function printing 'tool: message' at once (flushed: logs and progress
    lines interleave in order with the children's output)."""
    def say(msg):
        print(tool + ": " + msg, flush=True)
    return say


def g6(v):
    """A grid value in a case name or a table: 6 significant digits."""
    return "%.6g" % v


def g8(v):
    """A result value: 8 significant digits, 'nan' for a value that is not finite."""
    return "nan" if not math.isfinite(v) else "%.8g" % v


def time_or_none(t):
    """A solver time for messages: 'none' when there is none."""
    return "none" if t is None else "%g" % t
