#!/usr/bin/python3
"""Post-process the curtainPeer benchmark (see ./curtainPeer).

    curtainPeerPlot.py RUN_ROOT RESULTS_DIR LEVEL NP

For curtainFoam (LTS: "time" = iteration) and twoPhaseEulerFoam (transient):
drift at the floor and V_c/V_g at the end, and the CPU / wall time until the
drift stays within 1 % of its final value (tutorials/curtain/windTunnel/
steadyDrift.py, the same rule for both). Writes curtainPeer.csv (one row per
solver, appended per level/np: rows of an earlier level stay; with repeated
curtainFoam runs, curtainFoam.2, ...: their median CPU and wall time) and
curtainPeer_<level>.png (drift history against CPU time).
"""
import csv
import os
import re
import statistics
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, '..', '..', '..', 'tutorials', 'curtain', 'windTunnel'))
import steadyDrift  # noqa: E402

SOLVERS = (('curtainFoam', 'curtainFoam'), ('peer', 'twoPhaseEulerFoam'))


def run_files(case, solver):
    """A run's drift history and solver log."""
    return (os.path.join(case, 'postProcessing/drift/0/curtainDrift.dat'),
            os.path.join(case, 'log.' + solver))


def repeat_cases(run_root, sub):
    """The folders of a solver's repeated runs (SUB.2, SUB.3, ...), in order."""
    found = []
    for name in os.listdir(run_root):
        m = re.fullmatch(re.escape(sub) + r'\.(\d+)', name)
        if m:
            found.append((int(m.group(1)), os.path.join(run_root, name)))
    return [path for _, path in sorted(found)]


def atomic_write(path, text):
    tmp = path + '.tmp'
    with open(tmp, 'w') as f:
        f.write(text)
    os.replace(tmp, path)


def main():
    run_root, out, level, np_ = sys.argv[1:5]
    rows, hist = [], {}
    for sub, solver in SOLVERS:
        case = os.path.join(run_root, sub)
        dat, log = run_files(case, solver)
        if not (os.path.exists(dat) and os.path.exists(log)):
            print(f"{solver}: no run in {case}; skipped")
            continue
        s = steadyDrift.analyse(dat, log, 0.01, 'drift_bulk')
        # repeats of the same run (curtainPeer REPEAT): the same iterations and
        # drifts, bit for bit; the CPU and wall times their median
        repeats = [s] + [steadyDrift.analyse(*run_files(r, solver), 0.01, 'drift_bulk')
                         for r in repeat_cases(run_root, sub)]
        for r in repeats[1:]:
            if (r['steady_steps'], r['drift'], r['final_time']) != (s['steady_steps'], s['drift'], s['final_time']):
                sys.exit(f"{solver}: a repeat of {case} gave another run (steady after {r['steady_steps']} "
                         f"against {s['steady_steps']} steps, drift {r['drift']!r} against {s['drift']!r})")
        for k in ('steady_cpu', 'steady_wall', 'final_cpu'):
            s[k] = statistics.median(r[k] for r in repeats)
        with open(os.path.join(case, 'log.blockMesh')) as f:
            cells = int(re.search(r'nCells:\s*(\d+)', f.read()).group(1))
        vc = steadyDrift.last_value(os.path.join(case, 'postProcessing/gasInCurtain/0/curtainGasVelocity.dat'),
                        'VcByVg')
        rows.append(dict(level=level, np=np_, solver=solver, cells=cells,
                         drift_m='%.4f' % s['drift'], VcByVg='%.4f' % vc,
                         end=s['final_time'], steady_at=s['steady_time'],
                         steady_steps=s['steady_steps'],
                         steady_cpu_s='%.1f' % s['steady_cpu'],
                         steady_wall_s='%.1f' % s['steady_wall'],
                         total_cpu_s='%.1f' % s['final_cpu'],
                         tail_change='%.2e' % s['tail_change'],
                         runs=len(repeats),
                         steady_cpu_runs_s=' '.join('%.2f' % r['steady_cpu'] for r in repeats)))
        clock = steadyDrift.read_clock(log)
        hist[solver] = [(steadyDrift.wall_at(clock, t)[0], d)
                        for t, d in steadyDrift.read_drift(dat, 'drift_bulk')]
    if not rows:
        sys.exit("no finished run")
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, 'curtainPeer.csv')
    old = []
    if os.path.exists(path):
        with open(path) as f:
            old = [r for r in csv.DictReader(f)
                   if not (r['level'] == level and r['np'] == np_)]
    cols = list(rows[0].keys())
    allrows = old + rows
    text = ','.join(cols) + '\n' + ''.join(
        ','.join(str(r.get(c, '')) for c in cols) + '\n' for r in allrows)
    atomic_write(path, text)
    print(text, end='')
    by = {r['solver']: r for r in rows}
    if len(by) == 2:
        cf, pe = by['curtainFoam'], by['twoPhaseEulerFoam']
        dd = float(cf['drift_m'])/float(pe['drift_m']) - 1
        sp = float(pe['steady_cpu_s'])/float(cf['steady_cpu_s'])
        spw = float(pe['steady_wall_s'])/float(cf['steady_wall_s'])
        print(f"drift curtainFoam/peer - 1 = {100*dd:+.1f} % (target within 3 %); "
              f"speed-up to a 1 % steady drift: CPU {sp:.1f}x, wall {spw:.1f}x (target >= 20x on the medium mesh)")

    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4))
    for solver, h in hist.items():
        ax.plot([c for c, _ in h], [d for _, d in h], label=solver)
        r = next(r for r in rows if r['solver'] == solver)
        ax.axvline(float(r['steady_cpu_s']), ls=':', color=ax.lines[-1].get_color())
    ax.set_xscale('log')
    ax.set_ylim(0, 4)
    ax.set_xlabel('CPU time [s] (master process)')
    ax.set_ylabel('drift at the floor [m]')
    ax.set_title(f'curtainFoam vs twoPhaseEulerFoam, {level} mesh, np {np_}\n'
                 'dotted: drift steady to 1 %', fontsize=9)
    ax.legend()
    fig.tight_layout()
    png = os.path.join(out, f'curtainPeer_{level}.png')
    fig.savefig(png + '.tmp.png', dpi=110)
    os.replace(png + '.tmp.png', png)


if __name__ == '__main__':
    main()
