"""driftTablePlot: plotDriftTable's picture of a drift table: V_c/V_g and drift
across its grid, with Sherritt's Eq 142 beside the CFD (matplotlib, Debian's
python3-matplotlib). The axes and Eq 142's constants are the C++ side's."""

import csv
import math
import os
import sys

from .. import facts, files


def read(path):
    """(header dict, rows as dicts of floats) of a drift table CSV."""
    header = {}
    lines = open(path, encoding="utf-8").read().splitlines()
    data = [l for l in lines if not l.startswith("#")]
    for l in lines:
        if l.startswith("# ") and ":" in l:
            k, v = l[2:].split(":", 1)
            header[k.strip()] = v.strip()
    rows = []
    for r in csv.DictReader(data):
        rows.append({k: (float(v) if k != "case" else v) for k, v in r.items()})
    return header, rows


def mid(values):
    """The grid value at the middle (the lower of two middles)."""
    v = sorted(set(values))
    return v[(len(v) - 1) // 2]


def pick(rows, **fixed):
    out = rows
    for k, v in fixed.items():
        out = [r for r in out if abs(r[k] - v) <= 1e-9 * max(1, abs(v))]
    return out


def eq142(y, S, L):
    """Sherritt 1991 Eq 142 with the code's exponents, capped at 1 (docs/errata.md S9);
    its constants are the C++ side's (facts.eq142)."""
    c = facts.eq142()
    return min(1.0, c["k"] * y ** c["a"] / S ** c["b"] / L ** c["c"])


def plot(src, out):
    """The four panels of the drift table src, written to the PNG out."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    AX = facts.drift_table_axes()
    header, rows = read(src)
    vals = {a: sorted(set(r[a] for r in rows)) for a in AX}
    V0, S0, L0 = vals[AX[0]][0], mid(vals[AX[1]]), vals[AX[3]][0]
    rho0 = vals[AX[4]][-1]
    Ymax = vals[AX[2]][-1]
    d0 = mid(vals[AX[5]])
    fig, axs = plt.subplots(2, 2, figsize=(12, 9))
    styles = ["-", "--", ":", "-."]

    ax = axs[0][0]
    for j, rho in enumerate(vals[AX[4]]):
        for V in vals[AX[0]]:
            sel = sorted(pick(rows, gas_velocity_m_s=V, fall_height_m=Ymax, flight_length_m=L0,
                              particle_density_kg_m3=rho, particle_diameter_m=d0),
                         key=lambda r: r[AX[1]])
            ax.plot([r[AX[1]] for r in sel], [r["vc_over_vg"] for r in sel], styles[j % 4], marker="o",
                    label="V_g %g m/s, %g kg/m3" % (V, rho))
    ax.set_xscale("log")
    ax.set_xlabel("spill rate [kg/(m s)]")
    ax.set_ylabel("V_c/V_g")
    ax.set_title("(a) fall %g m, L %g m" % (Ymax, L0))
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)

    ax = axs[0][1]
    for i, S in enumerate(vals[AX[1]]):
        sel = sorted(pick(rows, gas_velocity_m_s=V0, spill_rate_kg_m_s=S, flight_length_m=L0,
                          particle_density_kg_m3=rho0, particle_diameter_m=d0), key=lambda r: r[AX[2]])
        ys = [r[AX[2]] for r in sel]
        if not ys:
            continue   # a missing grid point (failed case)
        line = ax.plot(ys, [r["vc_over_vg"] for r in sel], "-", marker="o", label="CFD, S %g" % S)
        yy = [ys[0] + (ys[-1] - ys[0]) * k / 50 for k in range(51)]
        ax.plot(yy, [eq142(y, S, L0) for y in yy], ":", color=line[0].get_color(),
                label="Eq 142, S %g" % S)
    ax.set_xlabel("fall height [m]")
    ax.set_ylabel("V_c/V_g (release to that height)")
    ax.set_title("(b) V_g %g m/s, L %g m, %g kg/m3" % (V0, L0, rho0))
    ax.legend(fontsize=7, ncol=2)
    ax.grid(alpha=0.3)

    ax = axs[1][0]
    for d in vals[AX[5]]:
        sel = sorted(pick(rows, gas_velocity_m_s=V0, spill_rate_kg_m_s=S0, flight_length_m=L0,
                          particle_density_kg_m3=rho0, particle_diameter_m=d), key=lambda r: r[AX[2]])
        ax.plot([r[AX[2]] for r in sel], [r["drift_m"] for r in sel], "-", marker="o",
                label="%g um" % (d * 1e6))
    ax.set_xlabel("fall height [m]")
    ax.set_ylabel("drift [m]")
    ax.set_title("(c) V_g %g m/s, S %g kg/(m s), L %g m, %g kg/m3" % (V0, S0, L0, rho0))
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)

    ax = axs[1][1]
    for d in vals[AX[5]]:
        sel = sorted(pick(rows, gas_velocity_m_s=V0, fall_height_m=Ymax, flight_length_m=L0,
                          particle_density_kg_m3=rho0, particle_diameter_m=d), key=lambda r: r[AX[1]])
        ok = [r for r in sel if math.isfinite(r["drift_m"])]
        ax.plot([r[AX[1]] for r in ok], [r["drift_m"] for r in ok], "-", marker="o",
                label="%g um" % (d * 1e6))
        for r in ok:
            if r["captured_fraction"] < 0.99:
                ax.annotate("%.2f" % r["captured_fraction"], (r[AX[1]], r["drift_m"]), fontsize=6)
    ax.set_xscale("log")
    ax.set_xlabel("spill rate [kg/(m s)]")
    ax.set_ylabel("drift [m] (numbers: captured fraction < 0.99)")
    ax.set_title("(d) fall %g m, V_g %g m/s, L %g m, %g kg/m3" % (Ymax, V0, L0, rho0))
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)

    fig.suptitle("%s: %s; mesh %s" % (os.path.basename(src), header.get("dictionary", ""),
                                      header.get("mesh", "")), fontsize=10)
    fig.tight_layout()
    try:
        files.save_figure(fig, out, 90)
    except files.WriteError as e:
        sys.exit("plotDriftTable: %s" % e)
    print("wrote", out)
