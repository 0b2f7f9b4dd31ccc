#!/usr/bin/python3
"""Iterations and wall time to a drift steady to a tolerance.

Reads a curtainDrift .dat (columns: Time drift_<c> captured_<c> ...
drift_bulk captured_bulk) and the solver log (lines "Time = t" followed by
"ExecutionTime = .. s  ClockTime = .. s"). The steady point is the first
written time after which every later drift stays within tol of the final
drift (a posteriori, the same rule for every solver and mesh).

    steadyDrift.py DRIFT_DAT LOG [--tol 0.01] [--column drift_bulk]

prints: final_time final_drift steady_time steady_steps steady_cpu_s
        steady_wall_s final_cpu_s final_wall_s tail_change (relative change
        of the drift over the last 10 % of writes). cpu: ExecutionTime of the
        (master) process; wall: ClockTime.
"""
import argparse
import re
import sys


def read_drift(path, column):
    header, rows = None, []
    with open(path) as f:
        for line in f:
            if line.startswith('#'):
                cols = line[1:].split()
                if cols and cols[0] == 'Time':
                    header = cols
                continue
            if line.strip():
                rows.append([float(v) for v in line.split()])
    if header is None or column not in header:
        sys.exit(f"{path}: no column '{column}' in the header {header}")
    j = header.index(column)
    return [(r[0], r[j]) for r in rows if len(r) > j]


def last_value(path, column):
    """Last written value of a column of a function object's .dat file."""
    rows = read_drift(path, column)
    if not rows:
        sys.exit(f"{path}: no data rows")
    return rows[-1][1]


def read_clock(path):
    """Map simulated time (or iteration) -> (cpu, wall) [s] at its end."""
    clock, t, steps = {}, None, 0
    time_re = re.compile(r'^Time = (\S+)')
    clock_re = re.compile(r'ExecutionTime = (\S+) s\s+ClockTime = (\S+)')
    with open(path) as f:
        for line in f:
            m = time_re.match(line)
            if m:
                t = float(m.group(1))
                steps += 1
                continue
            m = clock_re.search(line)
            if m and t is not None:
                clock[t] = (float(m.group(1)), float(m.group(2)), steps)
    if not clock:
        sys.exit(f"{path}: no 'Time =' / 'ClockTime =' lines")
    return clock


def wall_at(clock, t):
    times = sorted(clock)
    best = min(times, key=lambda s: abs(s - t))
    return clock[best]


def analyse(dat, log, tol=0.01, column='drift_bulk'):
    series = read_drift(dat, column)
    if len(series) < 3:
        sys.exit(f"{dat}: only {len(series)} rows; run longer")
    clock = read_clock(log)
    t_end, d_end = series[-1]
    steady = series[-1][0]
    for t, d in reversed(series):
        if abs(d - d_end) > tol*abs(d_end):
            break
        steady = t
    n_tail = max(2, len(series)//10)
    d_tail0 = series[-n_tail][1]
    tail = abs(d_end - d_tail0)/abs(d_end)
    cs, cf = wall_at(clock, steady), wall_at(clock, t_end)
    return dict(final_time=t_end, drift=d_end, steady_time=steady,
                steady_cpu=cs[0], steady_wall=cs[1], steady_steps=cs[2],
                final_cpu=cf[0], final_wall=cf[1], final_steps=cf[2],
                tail_change=tail)


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument('dat')
    p.add_argument('log')
    p.add_argument('--tol', type=float, default=0.01)
    p.add_argument('--column', default='drift_bulk')
    a = p.parse_args()
    r = analyse(a.dat, a.log, a.tol, a.column)
    print(' '.join(f"{r[k]:.6g}" for k in
                   ('final_time', 'drift', 'steady_time', 'steady_steps',
                    'steady_cpu', 'steady_wall', 'final_cpu', 'final_wall',
                    'tail_change')))


if __name__ == '__main__':
    main()
