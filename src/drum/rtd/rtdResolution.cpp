#include "drum/rtd/rtdResolution.hpp"

#include "drum/io/inputError.hpp"

#include <cmath>
#include <sstream>

namespace drum
{

namespace
{

std::string fixed(double v, int digits)
{
    std::ostringstream o;
    o.precision(digits);
    o << v;
    return o.str();
}

} // namespace


double largestResolvingStep(const RtdMoments& exact)
{
    return maxStepShareOfSd*exact.sd();
}


void requireResolvingStep(const RtdMoments& exact, const double timeStep, const std::string& file)
{
    const double hmax = largestResolvingStep(exact);
    if (!(std::isfinite(hmax) && hmax > 0))
    {
        throw InputError(file, "rtd.timeStep", "the network's exact RTD has no spread (SD "
            + fixed(exact.sd(), 6) + " s): no time step can sample it");
    }
    if (!(timeStep <= hmax))
    {
        throw InputError(file, "rtd.timeStep", fixed(timeStep, 6) + " s cannot resolve the residence time "
            "distribution: its exact mean is " + fixed(exact.mean, 6) + " s and SD " + fixed(exact.sd(), 6)
          + " s; allowed (0, " + fixed(hmax, 4) + "] s (at most " + fixed(maxStepShareOfSd, 3) + " SD)");
    }
}


void requireSampledMomentsMatch
(
    const RtdMoments& sampled,
    const RtdMoments& exact,
    const double timeStep,
    const double recovery,
    const std::string& file
)
{
    const double dMean = std::abs(sampled.mean/exact.mean - 1);
    const double dSd = std::abs(sampled.sd()/exact.sd() - 1);
    if (!(dMean <= meanTolerance && dSd <= sdTolerance))
    {
        throw InputError(file, "rtd.timeStep, rtd.recovery", "the tracer run with step " + fixed(timeStep, 6)
          + " s and recovery " + fixed(recovery, 6) + " gives mean " + fixed(sampled.mean, 6) + " s and SD "
          + fixed(sampled.sd(), 6) + " s against the exact " + fixed(exact.mean, 6) + " s and "
          + fixed(exact.sd(), 6) + " s (allowed: within " + fixed(100*meanTolerance, 3) + " % and "
          + fixed(100*sdTolerance, 3) + " %); use a smaller rtd.timeStep, the exact integrator, or a "
            "recovery closer to 1");
    }
}

} // namespace drum
