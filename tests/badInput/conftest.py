"""Counts the sweep's outcomes by kind (errors and unit-slip warnings apart)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))


def pytest_terminal_summary(terminalreporter):
    counts = {}
    for outcome in ("passed", "failed"):
        for rep in terminalreporter.stats.get(outcome, []):
            if rep.when != "call":
                continue
            kind = rep.nodeid.split("[", 1)[-1].split("-", 1)[0]
            tool = rep.nodeid.split("[", 1)[-1].split("-")[1]
            counts.setdefault((kind, tool), [0, 0])[outcome == "failed"] += 1
    terminalreporter.write_sep("-", "bad-input sweep by kind and tool (passed / failed)")
    for kind in ("error", "warning"):
        rows = {t: c for (k, t), c in counts.items() if k == kind}
        total = [sum(c[0] for c in rows.values()), sum(c[1] for c in rows.values())]
        terminalreporter.write_line("%-8s %4d / %d: %s" % (kind + "s", total[0], total[1], ", ".join(
            "%s %d/%d" % (t, c[0], c[1]) for t, c in sorted(rows.items()))))
