// Does a tracer run's time step resolve the distribution it samples?
//
// The network's exact moments (rtdMoments.hpp: k! c (-K)^{-(k+1)} b) are known
// before any step is taken, so a step that cannot resolve the RTD is refused
// before the run, and a run whose sampled moments part from the exact ones is
// refused after it, with the reason, rather than written as a result.
#ifndef DRUM_RTD_RTDRESOLUTION_HPP
#define DRUM_RTD_RTDRESOLUTION_HPP

#include "drum/rtd/rtdMoments.hpp"

#include <string>

namespace drum
{

//- Largest step accepted: this share of the exact standard deviation
constexpr double maxStepShareOfSd = 0.5;
//- Largest relative difference of the sampled mean from the exact one
constexpr double meanTolerance = 0.01;
//- Largest relative difference of the sampled SD from the exact one
constexpr double sdTolerance = 0.05;

//- The largest time step (s) that resolves a distribution of these exact moments
double largestResolvingStep(const RtdMoments& exact);

//- Throws InputError (file, "rtd.timeStep") when timeStep exceeds
//  largestResolvingStep(exact)
void requireResolvingStep(const RtdMoments& exact, double timeStep, const std::string& file);

//- Throws InputError (file, "rtd.timeStep") when the sampled mean or SD differs
//  from the exact one by more than meanTolerance / sdTolerance: the step is too
//  coarse for the integrator, or the recovery cuts off too much of the tail
void requireSampledMomentsMatch
(
    const RtdMoments& sampled,
    const RtdMoments& exact,
    double timeStep,
    double recovery,
    const std::string& file
);

} // namespace drum

#endif
