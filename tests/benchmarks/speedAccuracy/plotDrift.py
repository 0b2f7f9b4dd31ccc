#!/usr/bin/python3
"""Charts 1 and 3 of issue 7.

  plotDrift.py SCORES_DIR PEER_CSV MESH_CSV OUT_DIR

Chart 1 (driftSpeedAccuracy.png, driftSpeedAccuracy.csv):
  (a) every drift model against the shared wind-tunnel tests: RMS of
      ln(predicted/measured mean advance) against the CPU (wall) time per
      prediction, from validation/windTunnelDrift/results (scores.csv,
      timing.csv; the cfd rows are scored on the rows they ran, also shown
      like-for-like from scores_cfdRows.csv);
  (b) the CFD solvers on one wind-tunnel curtain (0.5 mm sand, 22 kg/(m s),
      4 m/s, 10.3 m): drift against the finest curtainFoam level / peer,
      against CPU time to a drift steady to 1 % - curtainFoam at its mesh
      levels (windTunnel meshStudy) and twoPhaseEulerFoam on the same meshes
      (tests/benchmarks/curtainPeer).
Chart 3 (meshCost.png): curtainFoam CPU time to a steady drift against the
number of cells.
Missing inputs are reported and their panel left out, never invented.
"""
import csv
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def rows(path):
    if not os.path.exists(path):
        print(f"plotDrift: {path} missing; its points are left out")
        return []
    with open(path) as f:
        return [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]


def save(fig, path):
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, path)
    print(f"plotDrift: wrote {path}")


scores_dir, peer_csv, mesh_csv, out = sys.argv[1:5]
os.makedirs(out, exist_ok=True)
scores = [r for r in rows(os.path.join(scores_dir, "scores.csv")) if r["fall_height_m"] == "all"]
timing = {r["model"]: r for r in rows(os.path.join(scores_dir, "timing.csv"))}
import glob
# like-for-like on the rows the shipped CFD setup answered (scores_cfd_<level>Rows.csv; the
# closure variants cfd_<level>_<name> are in the CSV of the scores, not in this chart):
# the fast references against the CFD
def shipped_cfd(model):
    """cfd_<level>: the shipped closure (variants are cfd_<level>_<name>)."""
    return model.startswith("cfd_") and model.count("_") == 1


cfd_files = sorted(f for f in glob.glob(os.path.join(scores_dir, "scores_cfd_*Rows.csv"))
                   if shipped_cfd(os.path.basename(f)[len("scores_"):-len("Rows.csv")]))
same_rows_models = {"isolated", "sherritt", "tableMaterial"}
cfd_rows = [r for f in cfd_files for r in rows(f) if r["fall_height_m"] == "all"
            and r["model"] in same_rows_models]
peer = rows(peer_csv)
mesh = rows(mesh_csv)

# every model that answered all rows, and the shipped CFD setup on its rows
len_all = max(int(r["count"]) for r in scores) if scores else 0
table = []
for r in scores:
    t = timing.get(r["model"])
    if t and (int(r["count"]) == len_all or shipped_cfd(r["model"])):
        table.append(dict(source="wind tunnel, the rows the model answered",
                          model=r["model"], rows=r["count"], rms_ln=float(r["rms_ln"]),
                          bias_ln=float(r["bias_ln"]), within25=float(r["within25"]),
                          cpu_s_per_prediction=float(t["wall_s_per_row"])))
for r in cfd_rows:
    t = timing.get(r["model"])
    if t:
        table.append(dict(source="wind tunnel, cfd rows only", model=r["model"] + " (same rows)",
                          rows=r["count"], rms_ln=float(r["rms_ln"]), bias_ln=float(r["bias_ln"]),
                          within25=float(r["within25"]), cpu_s_per_prediction=float(t["wall_s_per_row"])))

# CFD solvers on one curtain: reference = finest curtainFoam level
cfd = []
for r in mesh:
    cfd.append(dict(solver="curtainFoam", level=r["level"], cells=int(r["cells"]),
                    drift=float(r["drift_m"]), cpu=float(r["steady_cpu_s"])))
for r in peer:
    # curtainFoam from the mesh study where it ran; the peer file otherwise
    if r["solver"] == "curtainFoam" and mesh:
        continue
    if r["level"] in ("coarse", "medium", "fine") and r["np"] == "1":
        cfd.append(dict(solver=r["solver"], level=r["level"], cells=int(r["cells"]),
                        drift=float(r["drift_m"]), cpu=float(r["steady_cpu_s"])))
ref = None
cf = sorted((c for c in cfd if c["solver"] == "curtainFoam"), key=lambda c: c["cells"])
if cf:
    ref = cf[-1]
for c in cfd:
    table.append(dict(source="one curtain (0.5 mm sand, 22 kg/(m s), 4 m/s, 10.3 m)",
                      model=f"{c['solver']} {c['level']} ({c['cells']} cells)", rows=1,
                      rms_ln=abs(math.log(c["drift"]/ref["drift"])) if ref else float("nan"),
                      bias_ln=math.log(c["drift"]/ref["drift"]) if ref else float("nan"),
                      within25=float("nan"), cpu_s_per_prediction=c["cpu"]))

cols = ["source", "model", "rows", "rms_ln", "bias_ln", "within25", "cpu_s_per_prediction"]
text = "# regenerate: tests/benchmarks/speedAccuracy/run; one-curtain rows: |ln(drift/drift of the finest curtainFoam level)|\n"
text += ",".join(cols) + "\n" + "".join(",".join(str(r[c]) for c in cols) + "\n" for r in table)
tmp = os.path.join(out, "driftSpeedAccuracy.csv.tmp")
open(tmp, "w").write(text)
os.replace(tmp, os.path.join(out, "driftSpeedAccuracy.csv"))

fig, ax = plt.subplots(1, 2, figsize=(13, 5.5))
for r in table:
    # a table's crossed drift (_landed) is not what the tunnel weighed: in the CSV, not drawn
    if r["source"].startswith("wind tunnel") and not r["model"].endswith("_landed"):
        same = "same rows" in r["model"]
        ax[0].scatter(r["cpu_s_per_prediction"], r["rms_ln"], s=50,
                      marker="s" if r["model"].startswith("cfd") else "o",
                      facecolors="none" if same else None, edgecolors="k" if same else None)
        ax[0].annotate(f"{r['model']} (n={r['rows']})", (r["cpu_s_per_prediction"], r["rms_ln"]),
                       fontsize=8, xytext=(4, 3), textcoords="offset points")
ax[0].set_xscale("log")
ax[0].set_xlabel("wall time per prediction [s] (2 cores; CFD rows 2 at a time)")
ax[0].set_ylabel("RMS ln(predicted/measured advance)")
ax[0].set_title("(a) drift models on Sherritt's shared wind-tunnel tests", fontsize=10)
ax[0].grid(True, which="both", alpha=0.3)
for c in cfd:
    colour = "C0" if c["solver"] == "curtainFoam" else "C3"
    ax[1].scatter(c["cpu"], c["drift"], color=colour, s=50)
    ax[1].annotate(f"{c['level']} ({c['cells']})", (c["cpu"], c["drift"]), fontsize=8,
                   xytext=(4, 3), textcoords="offset points")
ax[1].scatter([], [], color="C0", label="curtainFoam (LTS)")
ax[1].scatter([], [], color="C3", label="twoPhaseEulerFoam (transient peer)")
ax[1].set_xscale("log")
ax[1].set_xlabel("CPU time to a drift steady to 1 % [s]")
ax[1].set_ylabel("drift at the floor [m]")
ax[1].set_title("(b) CFD on one wind-tunnel curtain, mesh levels", fontsize=10)
ax[1].legend(fontsize=8)
ax[1].grid(True, which="both", alpha=0.3)
fig.tight_layout()
save(fig, os.path.join(out, "driftSpeedAccuracy.png"))

if mesh:
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    m = sorted(mesh, key=lambda r: int(r["cells"]))
    ax.plot([int(r["cells"]) for r in m], [float(r["steady_cpu_s"]) for r in m], "o-", label="curtainFoam")
    for r in m:
        ax.annotate(r["level"], (int(r["cells"]), float(r["steady_cpu_s"])), fontsize=8,
                    xytext=(4, 3), textcoords="offset points")
    p = sorted((r for r in peer if r["solver"] == "twoPhaseEulerFoam" and r["np"] == "1"
                and r["level"] in ("coarse", "medium", "fine")), key=lambda r: int(r["cells"]))
    if p:
        ax.plot([int(r["cells"]) for r in p], [float(r["steady_cpu_s"]) for r in p], "s--",
                color="C3", label="twoPhaseEulerFoam")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("cells")
    ax.set_ylabel("CPU time to a drift steady to 1 % [s]")
    ax.set_title("Curtain CFD cost against mesh size (wind-tunnel curtain)", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    save(fig, os.path.join(out, "meshCost.png"))
