#!/usr/bin/python3
"""Post-process the windTunnel mesh study (see ./meshStudy).

    meshStudyPlot.py RUN_ROOT RESULTS_DIR level [level ...]

For each level: cells (log.blockMesh), cells across the half sheet
(system/meshLevels), final drift at the floor and V_c/V_g, iterations, CPU and
wall time until the drift stays within 1 % of its final value
(steadyDrift.py). Writes RESULTS_DIR/meshStudy.csv, meshStudy.png and
meshStudyGCI.txt: Richardson extrapolation and the grid convergence index
(Celik et al. 2008, J. Fluids Eng. 130 078001) from the three finest levels,
with the representative refinement ratio r = (N1/N2)^(1/3) and, since the
answer is controlled by the cross-sheet cell, also with r = dz2/dz1.
"""
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import steadyDrift  # noqa: E402


def atomic_write(path, text):
    tmp = path + '.tmp'
    with open(tmp, 'w') as f:
        f.write(text)
    os.replace(tmp, path)


def cells(case):
    with open(os.path.join(case, 'log.blockMesh')) as f:
        m = re.search(r'nCells:\s*(\d+)', f.read())
    if not m:
        sys.exit(f"{case}/log.blockMesh: no nCells")
    return int(m.group(1))


def foam_value(path, name):
    r = subprocess.run(['foamDictionary', '-entry', name, '-value', path],
                       capture_output=True, text=True)
    return r.stdout.strip() if r.returncode == 0 else None


def entry(case, name):
    """A mesh entry: explicit in meshParameters, else the level's."""
    mp = os.path.join(case, 'system', 'meshParameters')
    v = foam_value(mp, name)
    if v is None:
        level = foam_value(mp, 'level')
        v = foam_value(os.path.join(case, 'system', 'meshLevels'),
                       f'levels/{level}/{name}')
    if v is None:
        sys.exit(f"{mp}: no entry '{name}' (nor in the level's system/meshLevels)")
    return float(v)


def gci(f1, f2, f3, r21, r32):
    """Celik et al. 2008: apparent order p (fixed-point), extrapolated f,
    fine-grid GCI (safety factor 1.25). f1 finest."""
    e21, e32 = f2 - f1, f3 - f2
    if e21 == 0 or e32 == 0 or e32/e21 <= 0:
        return dict(p=float('nan'), fext=float('nan'), gci=float('nan'),
                    note='oscillatory or flat convergence: no Richardson estimate')
    s = math.copysign(1, e32/e21)
    p = 1.0
    for _ in range(200):
        q = math.log((r21**p - s)/(r32**p - s))
        p = abs(math.log(abs(e32/e21)) + q)/math.log(r21)
    fext = (r21**p*f1 - f2)/(r21**p - 1)
    ea = abs((f1 - f2)/f1)
    return dict(p=p, fext=fext, gci=1.25*ea/(r21**p - 1), note='monotone')


def main():
    run_root, out = sys.argv[1], sys.argv[2]
    levels = sys.argv[3:]
    rows = []
    for lv in levels:
        case = os.path.join(run_root, lv)
        dat = os.path.join(case, 'postProcessing/drift/0/curtainDrift.dat')
        log = os.path.join(case, 'log.curtainFoam')
        if not (os.path.exists(dat) and os.path.exists(log)):
            print(f"{lv}: no run in {case}; skipped")
            continue
        s = steadyDrift.analyse(dat, log, 0.01, 'drift_bulk')
        vc = steadyDrift.last_value(os.path.join(case, 'postProcessing/gasInCurtain/0/curtainGasVelocity.dat'),
                      'VcByVg')
        nz = entry(case, 'nzSheet')
        rows.append(dict(level=lv, cells=cells(case), nzSheet=int(nz),
                         dzSheet_mm=1e3*0.025/nz, drift_m=s['drift'], VcByVg=vc,
                         iterations=int(s['final_time']),
                         steady_iterations=int(s['steady_time']),
                         steady_cpu_s=s['steady_cpu'], steady_wall_s=s['steady_wall'],
                         tail_change=s['tail_change']))
    if not rows:
        sys.exit("no finished level")
    rows.sort(key=lambda r: r['cells'])
    cols = list(rows[0].keys())
    fmt = {'drift_m': '%.4f', 'VcByVg': '%.4f', 'dzSheet_mm': '%.3f',
           'steady_cpu_s': '%.1f', 'steady_wall_s': '%.1f', 'tail_change': '%.2e'}
    text = ','.join(cols) + '\n' + ''.join(
        ','.join((fmt.get(c, '%s') % r[c]) for c in cols) + '\n' for r in rows)
    os.makedirs(out, exist_ok=True)
    atomic_write(os.path.join(out, 'meshStudy.csv'), text)
    print(text, end='')

    report = []
    if len(rows) >= 3:
        f3, f2, f1 = (r['drift_m'] for r in rows[-3:])
        n3, n2, n1 = (r['cells'] for r in rows[-3:])
        z3, z2, z1 = (r['dzSheet_mm'] for r in rows[-3:])
        for name, r21, r32 in (('r = (N1/N2)^(1/3)', (n1/n2)**(1/3), (n2/n3)**(1/3)),
                               ('r = dz2/dz1 (cross-sheet cell)', z2/z1, z3/z2)):
            g = gci(f1, f2, f3, r21, r32)
            report.append(f"{name}: r21 {r21:.3f}, r32 {r32:.3f}, apparent order "
                          f"{g['p']:.2f}, extrapolated drift {g['fext']:.3f} m, "
                          f"fine-level GCI {100*g['gci']:.1f} % ({g['note']})")
        report.insert(0, "Richardson / GCI (Celik et al. 2008) from levels "
                      + ', '.join(r['level'] for r in rows[-3:]) +
                      f": drift {f3:.3f}, {f2:.3f}, {f1:.3f} m")
    else:
        report.append("fewer than three levels: no Richardson estimate")
    atomic_write(os.path.join(out, 'meshStudyGCI.txt'), '\n'.join(report) + '\n')
    print('\n'.join(report))

    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    n = [r['cells'] for r in rows]
    ax[0].plot(n, [r['drift_m'] for r in rows], 'o-', label='curtainFoam (LTS)')
    for r in rows:
        ax[0].annotate(f"{r['level']} ({r['nzSheet']} across)", (r['cells'], r['drift_m']),
                       textcoords='offset points', xytext=(4, 4), fontsize=8)
    peer_csv = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..',
                            'tests', 'benchmarks', 'curtainPeer', 'results', 'curtainPeer.csv')
    if os.path.exists(peer_csv):   # the same meshes with twoPhaseEulerFoam, if measured
        import csv
        with open(peer_csv) as f:
            peer = sorted(((int(r['cells']), float(r['drift_m'])) for r in csv.DictReader(f)
                           if r['solver'] == 'twoPhaseEulerFoam' and r['level'] in levels),
                          key=lambda t: t[0])
        if peer:
            ax[0].plot([c for c, _ in peer], [d for _, d in peer], 's--',
                       label='twoPhaseEulerFoam (transient, curtainPeer)')
    ax[0].axhline(1.03, color='k', ls='--', lw=0.8, label='Sherritt test 22 (1.03 m)')
    ax[0].set_xscale('log')
    ax[0].set_xlabel('cells (half tunnel)')
    ax[0].set_ylabel('drift at the floor [m]')
    ax[0].legend(fontsize=8)
    ax[1].plot(n, [r['steady_cpu_s'] for r in rows], 'o-', label='CPU to 1 % steady')
    ax[1].plot(n, [r['steady_wall_s'] for r in rows], 's--', label='wall to 1 % steady')
    ax[1].set_xscale('log')
    ax[1].set_yscale('log')
    ax[1].set_xlabel('cells (half tunnel)')
    ax[1].set_ylabel('time [s], serial, shared machine')
    ax[1].legend(fontsize=8)
    fig.suptitle('windTunnel mesh study: 0.5 mm sand, 22 kg/(m s), 4 m/s, 10.3 m, L = 1 m')
    fig.tight_layout()
    tmp = os.path.join(out, 'meshStudy.tmp.png')
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, os.path.join(out, 'meshStudy.png'))


if __name__ == '__main__':
    main()
