"""flightedDryer: the Python side of the flighted-dryer toolkit.

The command-line tools (curtainCase, buildDriftTable, the plot tools) are thin
front ends over this package; the physics lives on the C++ side, which the
package asks (airProperties, windTunnelDrift, dryerFacts) rather than repeats.

Modules:
  messages       the tools' messages and number formatting
  errors         the error kinds every tool maps to its exit status
  files          atomic, checked writes (a file is whole or absent)
  foamDictionary strict reading and editing of OpenFOAM dictionaries
  strictDict     a sweep-style dictionary: unknown or repeated entries refused
  foamOutput     what OpenFOAM's function objects write
  foamTimes      time folders: which is a whole restart point
  processes      solvers in their own process groups, locks, signals
  options        command-line options checked against their ranges
  gas            the curtain's air, from the C++ air model
  facts          the facts the C++ side owns (drag laws, Eq 142, table axes)
  densityRule    a particle density from the bulk density where the printed one is impossible
  curtain        one curtain case: inputs, set-up, the run, its results, folders
  sweep          a drift-table sweep: dictionary, plan, local pool, Slurm, table
  docFigures     the figures of the README and docs/, written from results
"""

import os

#: the checkout this package belongs to (DRYER_PROJECT, else two folders up)
PROJECT = os.environ.get("DRYER_PROJECT") or os.path.normpath(
    os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
