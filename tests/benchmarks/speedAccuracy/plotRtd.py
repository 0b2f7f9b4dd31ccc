#!/usr/bin/python3
"""Chart 2 of issue 7: drum-model RTD moment error against CPU time.

Usage: plotRtd.py rtd.csv out.png
"""
import csv
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["status"] == "ok"]
if not rows:
    sys.exit(f"plotRtd: no successful runs in {sys.argv[1]}")
marker = {"exact": "o", "trbdf2": "s", "backwardEuler": "^", "forwardEuler": "x"}
slices = sorted({int(r["slices"]) for r in rows})
cmap = plt.get_cmap("viridis")
colour = {n: cmap(i/max(1, len(slices) - 1)) for i, n in enumerate(slices)}

fig, ax = plt.subplots(1, 2, figsize=(13, 5.5))
for r in rows:
    n, integ = int(r["slices"]), r["integrator"]
    cpu = float(r["cpu_s"])
    for k, (col, lab) in enumerate([("mean_err_vs_model", "integration error of the mean"),
                                   ("sd_err_vs_measured", "SD error against the measured tracer")]):
        v = max(float(r[col]), 1e-7)
        ax[k].scatter(cpu, v, marker=marker[integ], color=colour[n], s=40)
for k, title in enumerate(["sampling + integration error: |mean/exact mean - 1|, same network",
                           "model + integrator: |SD/measured SD - 1| (Invicta, 6.73 min)"]):
    ax[k].set_xscale("log")
    ax[k].set_yscale("log")
    ax[k].set_xlabel("CPU time per RTD [s]")
    ax[k].set_title(title, fontsize=10)
    ax[k].grid(True, which="both", alpha=0.3)
for integ, m in marker.items():
    ax[0].scatter([], [], marker=m, color="k", label=integ)
for n in slices:
    ax[0].scatter([], [], marker="o", color=colour[n], label=f"N = {n} slices")
ax[0].legend(fontsize=8, ncol=2)
refused = sum(1 for r in csv.DictReader(open(sys.argv[1])) if r["status"] == "refused")
fig.suptitle("Drum model (Lee network, Invicta): RTD accuracy against CPU time; time steps 1-60 s;"
             f" {refused} runs refused (forward Euler beyond its stable step, C_F > 1)", fontsize=10)
fig.tight_layout()
tmp = sys.argv[2] + ".tmp.png"
fig.savefig(tmp, dpi=110)
import os
os.replace(tmp, sys.argv[2])
print(f"plotRtd: wrote {sys.argv[2]}")
