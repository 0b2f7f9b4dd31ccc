// Lee's compartment dryer as an RTD estimation problem: his parameters
// from named values and the prediction model the least-squares fit of
// drum/rtd/rtdEstimation.hpp drives (what Lee 2008 section 5.2 / Ch. 7
// did in gPROMS), beside the model it belongs to.
#ifndef DRUM_TRANSPORT_COMPARTMENTLEEESTIMATION_HPP
#define DRUM_TRANSPORT_COMPARTMENTLEEESTIMATION_HPP

#include "drum/rtd/rtdEstimation.hpp"
#include "drum/transport/compartment/compartmentLeeDryer.hpp"

#include <string>
#include <vector>

namespace drum
{

//- One parameter Lee's model can be fitted in: its name in the fit (and in
//  estimation.csv), the drumDict entry a user lists in estimation.parameters,
//  and the box bounds of the fit
struct LeeEstimationParameter
{
    std::string name;       //!< kilnTime, backFraction, dragFactor, ...
    std::string entry;      //!< model entry it stands for (forwardShare: none, "forwardShare")
    double lower, upper;
};

//- Every fittable parameter, the one list the reader, the fit and the model use
const std::vector<LeeEstimationParameter>& leeEstimationParameters();

//- The parameter listed as `entry` in estimation.parameters (its drumDict
//  name, or its fit name); InputError naming `where` and the allowed names
const LeeEstimationParameter& leeEstimationParameter(const std::string& entry, const std::string& where,
                                                     const std::string& file = "");

//- Largest C_F^0 = maf_h sin(theta)/(L/N) over the slices (Eq 3.7)
double leeMaxForwardFraction0(const LeeDryer& dryer, int nSlices);

//- Lee parameters from named values. "forwardShare" s in [0, 1] stands for
//  C_F^G = s (1 - C_B)/max_i C_F^0_i, which keeps C_R = 1 - C_F - C_B >= 0
//  in every slice: Lee's fits end on that constraint (Lee 2008 Table 7.2), where
//  a box-bounded optimiser in (t_kiln, C_B, C_F^G) stalls.
//  "designLoadMultiplier" goes into *modified when given.
LeeParameters leeParametersFrom
(
    const LeeDryer& dryer,
    int nSlices,
    const LeeParameters& base,
    const std::vector<std::string>& names,
    const std::vector<double>& values,
    LeeDryer* modified = nullptr
);

//- Lee's dryer as a prediction model: E(t) in 1/h at `times` (s after the
//  pulse start) for a rectangular pulse, with the named free parameters
//  taken from the vector: "kilnTime", "backFraction", "dragFactor",
//  "forwardShare", "designLoadMultiplier", and for the stagnant-zone
//  extension "stagnantRatio", "exchangeTime". Others come from `base` and
//  `stagnant`. The output is transformed as the objective says.
PredictionModel leeRtdModel
(
    const LeeDryer& dryer,
    int nSlices,
    const LeeParameters& base,
    const std::vector<std::string>& freeParameters,
    double pulseDuration,
    const std::vector<double>& times,
    const StagnantExchange& stagnant = {},
    const RtdObjective& objective = {}
);

//- Stagnant-zone values from named values (defaults from `base`)
StagnantExchange stagnantFrom
(
    const StagnantExchange& base,
    const std::vector<std::string>& names,
    const std::vector<double>& values
);

} // namespace drum

#endif
