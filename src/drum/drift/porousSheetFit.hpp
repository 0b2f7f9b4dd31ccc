// Least-squares calibration of the porousSheet reduced model on a CFD drift
// table (Ceres; library drumDriftFit so that drum does not link Ceres).
// Residuals ln(vc_over_vg_table) - ln((1 + a N)^-b) over every table row with
// V_g > 0, y > 0, S > 0 and V_c/V_g > 0; parameters ln a and ln b (both
// positive). Only the CFD enters: the wind-tunnel measurements never do.
#ifndef DRUM_DRIFT_POROUSSHEETFIT_HPP
#define DRUM_DRIFT_POROUSSHEETFIT_HPP

#include "drum/drift/driftTable.hpp"
#include "drum/drift/porousSheetDrift.hpp"

namespace drum
{

struct PorousSheetFit
{
    PorousSheetConstants constants;  //!< a, b and provenance (table, rows, rms)
    int rows = 0;                    //!< residuals used
    double rmsLn = 0;                //!< RMS of the ln residuals at the optimum
    bool converged = false;
};

PorousSheetFit fitPorousSheet
(
    const DriftTable& table,
    const particleDrag::Gas& gas,
    const particleDrag::DragLaw& law = {}
);

//- One fit over the rows of several tables (e.g. one per material: each
//  table's curtain is its own Sauter diameter); provenance lists them all
PorousSheetFit fitPorousSheet
(
    const std::vector<const DriftTable*>& tables,
    const particleDrag::Gas& gas,
    const particleDrag::DragLaw& law = {}
);

} // namespace drum

#endif
