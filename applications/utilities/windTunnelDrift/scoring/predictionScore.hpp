// How well a drift model predicts measured mean advances: RMS of
// ln(predicted/measured), its mean (bias), and the share within +-25%.
#ifndef DRUM_WINDTUNNEL_PREDICTIONSCORE_HPP
#define DRUM_WINDTUNNEL_PREDICTIONSCORE_HPP

#include <map>

namespace drum
{

struct PredictionScore
{
    int count = 0;
    double rmsLnError = 0;   //!< sqrt(mean(ln(pred/meas)^2))
    double bias = 0;         //!< mean(ln(pred/meas)); > 0 over-predicts
    double within25 = 0;     //!< share of |pred/meas - 1| <= 0.25
};

//- Score the tests present in both maps (keyed by test number). Pairs with
//  a non-positive value are refused (std::invalid_argument).
PredictionScore scorePredictions
(
    const std::map<int, double>& predicted,
    const std::map<int, double>& measured
);

} // namespace drum

#endif
