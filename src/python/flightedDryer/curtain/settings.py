"""settings: the fixed choices of a curtainCase run (file names, tolerances,
ranges), named once for the modules of the curtain package."""

import os

from .. import PROJECT
from ..messages import sayer

say = sayer("curtainCase")

DEFAULT_TEMPLATE = os.path.join(PROJECT, "etc", "templates", "curtain", "windTunnel")
GAS_MODELS = ("kEpsilon", "realizableKE", "kOmegaSST")   # RAS models curtainFoam's gas has
PARTICLE_TURBULENCE = ("none", "Simonin", "SimoninCrowe")
TURBULENT_DISPERSION = ("none", "gradientDiffusion")
PARTICLE_PARTICLE_DRAG = ("none", "Syamlal")
LEVELS = ("coarse", "medium", "fine")
COLUMNS = ["class", "diameter_m", "mass_fraction", "fall_height_m", "drift_m",
           "captured_fraction", "vc_over_vg", "gas_velocity_m_s", "cells",
           "iterations", "converged"]
RESULT = "curtainResult.csv"
LANDING = "curtainLanding.csv"
ARGS = "curtainCase.args.json"
LOCK = ".curtainCase.lock"
INPUTS = ".curtainCase.inputs"      # in a case folder: the settings it was made for
MANIFEST = ".curtainCase.files"     # in a case folder: the files curtainCase wrote
STAGE = ".curtainCase.stage"        # in DIR/case.partial: first or gentle
LOCK_WAIT = 20                      # s to wait for another run of DIR to end
MIN_FALL_CELLS = 2                  # the fall height spans at least this many cells
MIN_SECTION_CELLS = 0.5             # planes at least half a cell apart
MIN_LAYER, MAX_LAYER = 0.002, 0.2   # m: release layer thickness (the mesh's cells across it follow)
PACKED_SLOT_FRACTION = 0.5          # -layerThickness packed: at most this solids fraction at the slot
LANDING_BIN = 0.25                  # m: bins of the landing distribution along the flow
CAPTURED_GATE = 0.05                # a class's drift is judged once this much lands
REL_TOL = 0.01        # "steady to 1 %"
DRIFT_ABS_TOL = 1e-3  # m
VC_ABS_TOL = 2e-3
VC_REL_TOL = 0.05     # V_c/V_g: a curtain at low gas velocity keeps a small unsteadiness
STEADY_FROM_WINDOWS = 1   # -steadyFrom default: the steady window may end from one window on
