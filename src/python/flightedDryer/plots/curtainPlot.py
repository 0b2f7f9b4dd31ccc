"""curtainPlot: plotCurtain's picture of a curtainFoam solution (the solids
fraction and the gas velocity on the sheet's midplane and on a horizontal plane,
sampled by OpenFOAM's postProcess -func surfaces) and its VTK for ParaView."""

import argparse
import glob
import os
import subprocess
import sys

from .. import files, foamDictionary, foamOutput

SURFACES = """FoamFile {{ version 2.0; format ascii; class dictionary; object plotCurtainDict; }}
functions
{{
    plotCurtainSurfaces
    {{
        type            surfaces;
        libs            (sampling);
        surfaceFormat   raw;
        interpolationScheme cell;
        fields          ({fields});
        surfaces
        {{
            vertical   {{ type cuttingPlane; planeType pointAndNormal;
                          pointAndNormalDict {{ point (0 0 {z0}); normal (0 0 1); }}
                          interpolate false; }}
            horizontal {{ type cuttingPlane; planeType pointAndNormal;
                          pointAndNormalDict {{ point (0 {yMid} 0); normal (0 1 0); }}
                          interpolate false; }}
        }}
    }}
}}
"""


def die(msg):
    print("plotCurtain: " + msg, file=sys.stderr)
    sys.exit(1)


def case_alpha_edge(case):
    """The curtain edge the case's curtainGasVelocity/curtainEdges used (their
    .dat headers: '# alphaEdge : value')."""
    for dat in sorted(glob.glob(os.path.join(case, "postProcessing", "*", "*", "*.dat"))):
        with open(dat, errors="replace") as f:
            for line in f:
                if not line.startswith("#"):
                    break
                k, _, v = line[1:].partition(":")
                if k.strip() == "alphaEdge":
                    try:
                        return float(v)
                    except ValueError:
                        die(f"{dat}: alphaEdge '{v.strip()}' is not a number")
    die(f"{case}: no curtain function object output with an alphaEdge header in postProcessing/; "
        "give -alphaEdge")


def latest_time(case):
    times = []
    for d in os.listdir(case):
        try:
            if d != "0" and os.path.isdir(os.path.join(case, d)):
                times.append((float(d), d))
        except ValueError:
            pass
    if not times:
        die(f"no solution time in {case} (run the solver first)")
    return max(times)[1]


def read_raw(path):
    """A raw surface sample (foamOutput.read_raw)"""
    try:
        return foamOutput.read_raw(path)
    except foamOutput.FoamOutputError as e:
        die(str(e))


def main(argv, usage):
    ap = argparse.ArgumentParser(prog="plotCurtain", description=usage, add_help=False,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("-help", "-h", "--help", action="help", help="show this help and exit")
    ap.add_argument("-case", required=True)
    ap.add_argument("-out", default=None)
    ap.add_argument("-alphaEdge", type=float, default=None)
    ap.add_argument("-noVTK", action="store_true")
    a = ap.parse_args(argv)

    import numpy as np
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import LogNorm

    if not os.environ.get("WM_PROJECT_DIR"):
        die("the OpenFOAM environment is not set: source etc/bashrc of the project first")
    case = os.path.abspath(a.case)
    if not os.path.isdir(os.path.join(case, "system")):
        die(f"{case} is not an OpenFOAM case (no system/)")
    if a.alphaEdge is None:
        a.alphaEdge = case_alpha_edge(case)
    t = latest_time(case)
    alphas = sorted(os.path.basename(p) for p in glob.glob(os.path.join(case, t, "alpha.*"))
                    if not p.endswith(".air") and not p.endswith(".orig"))
    if not alphas:
        die(f"no alpha.<class> fields in {case}/{t}")
    gasU = "U.air"
    if not os.path.exists(os.path.join(case, t, gasU)):
        die(f"no gas velocity {gasU} in {case}/{t}")

    # Geometry: the slot patch gives the sheet midplane and the height
    try:
        H = float(foamDictionary.value(os.path.join(case, "system", "meshParameters"), "H", default="5"))
    except (ValueError, foamDictionary.FoamDictionaryError):
        H = 5.0
    dictPath = os.path.join(case, "system", "plotCurtainDict")
    with open(dictPath, "w") as f:
        f.write(SURFACES.format(fields=" ".join(alphas + [gasU]), z0=1e-6, yMid=0.5*H))
    log = os.path.join(case, "log.plotCurtain")
    with open(log, "w") as lf:
        r = subprocess.run(["postProcess", "-case", case, "-latestTime", "-dict",
                            "system/plotCurtainDict",
                            "-fields", "(" + " ".join(alphas + [gasU]) + ")"], stdout=lf, stderr=subprocess.STDOUT)
    if r.returncode != 0:
        die(f"postProcess failed, see {log}")
    sdir = os.path.join(case, "postProcessing", "plotCurtainSurfaces", t)
    if not os.path.isdir(sdir):
        die(f"no samples in {sdir}, see {log}")

    def plane(name):
        total = None
        xyz = None
        for al in alphas:
            d = read_raw(os.path.join(sdir, f"{al}_{name}.raw"))
            xyz = d[:, :3]
            total = d[:, 3] if total is None else total + d[:, 3]
        u = read_raw(os.path.join(sdir, f"{gasU}_{name}.raw"))
        return xyz, total, u[:, 3]

    out = a.out or os.path.join(case, "curtain.png")
    fig, ax = plt.subplots(2, 2, figsize=(13, 9),
                           gridspec_kw={"height_ratios": [3, 1]})
    for col, (name, i, j, xl, yl) in enumerate(
            [("vertical", 0, 1, "x along the gas [m]", "height y [m]"),
             ("horizontal", 0, 2, "x along the gas [m]", "z across the sheet [m]")]):
        xyz, al, ux = plane(name)
        x, y = xyz[:, i], xyz[:, j]
        alc = np.clip(al, 1e-7, None)
        lo = max(1e-6, alc.min())
        hi = max(alc.max(), 10*lo)
        c0 = ax[col][0].tricontourf(x, y, alc, levels=np.logspace(np.log10(lo), np.log10(hi), 25),
                                    norm=LogNorm(lo, hi), cmap="viridis")
        cb = fig.colorbar(c0, ax=ax[col][0], label="solids fraction (all classes)")
        decades = range(int(np.floor(np.log10(lo))), int(np.ceil(np.log10(hi))) + 1)
        cb.set_ticks([10.0**k for k in decades if lo <= 10.0**k <= hi])
        cb.set_ticklabels([f"1e{k}" for k in decades if lo <= 10.0**k <= hi])
        c1 = ax[col][1].tricontourf(x, y, ux, levels=25, cmap="coolwarm")
        fig.colorbar(c1, ax=ax[col][1], label="gas velocity along x [m/s]")
        if al.max() > a.alphaEdge:
            for k in (0, 1):
                ax[col][k].tricontour(x, y, al, levels=[a.alphaEdge], colors="k", linewidths=0.8)
        for k in (0, 1):
            ax[col][k].set_xlabel(xl)
            ax[col][k].set_ylabel(yl)
            ax[col][k].set_aspect("equal" if name == "vertical" else "auto")
        ax[col][0].set_title(f"{name} plane: solids fraction (edge alpha = {a.alphaEdge:g})")
        ax[col][1].set_title(f"{name} plane: gas velocity along the flow")
    name = os.path.basename(case)
    if name == "case":
        name = os.path.basename(os.path.dirname(case))
    fig.suptitle(f"{name}: curtainFoam at iteration/time {t}")
    fig.tight_layout()
    try:
        files.save_figure(fig, out, 110)
    except files.WriteError as e:
        die(str(e))
    print(f"plotCurtain: wrote {out}")

    if not a.noVTK:
        with open(os.path.join(case, "log.foamToVTK"), "w") as lf:
            r = subprocess.run(["foamToVTK", "-case", case, "-latestTime"],
                               stdout=lf, stderr=subprocess.STDOUT)
        if r.returncode != 0:
            die(f"foamToVTK failed, see {case}/log.foamToVTK")
        print(f"plotCurtain: VTK for ParaView in {os.path.join(case, 'VTK')}")
