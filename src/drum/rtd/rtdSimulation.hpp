// Dynamic tracer simulation of a linear compartment network: the response
// E(t) to a rectangular feed pulse of unit total tracer.
//
// Integrators:
//   exact          exact step propagator exp(K h) (with the pulse input
//                  folded into an augmented matrix exponential, Eigen
//                  unsupported/Eigen/MatrixFunctions): no truncation error
//                  at the grid points, any step size.
//   trbdf2         TR-BDF2 (L-stable, 2nd order), sparse LU factored once.
//   backwardEuler  backward Euler (L-stable, 1st order).
//   forwardEuler   explicit Euler: stable only for h <= h_max, where
//                  h_max = min over eigenvalues of -2 Re(l)/|l|^2. The step
//                  is checked before the run; beyond h_max the run throws
//                  InputError or (policy fallback) switches to trbdf2 and
//                  says so. A run-time guard also stops any run whose
//                  tracer inventory grows or turns negative.
#ifndef DRUM_RTD_RTDSIMULATION_HPP
#define DRUM_RTD_RTDSIMULATION_HPP

#include "drum/rtd/tracerSystem.hpp"

#include <functional>
#include <string>
#include <vector>

namespace drum
{

enum class RtdIntegrator { exact, trbdf2, backwardEuler, forwardEuler };

//- Parse "exact" | "trbdf2" | "backwardEuler" | "forwardEuler"; entry and
//  file name the source in the InputError
RtdIntegrator parseRtdIntegrator
(
    const std::string& name,
    const std::string& entry = "integrator",
    const std::string& file = ""
);

std::string toString(RtdIntegrator integrator);

enum class UnstableStepPolicy
{
    error,      //!< throw InputError naming the step and its limit
    fallback,   //!< switch to trbdf2 and record a warning
    unchecked   //!< no check at all: ONLY to demonstrate the failure in tests
};

struct RtdOptions
{
    RtdIntegrator integrator = RtdIntegrator::exact;
    double timeStep = 5.0;          //!< s
    double pulseDuration = 0.0;     //!< s; 0 gives the impulse response
    double recovery = 0.999;        //!< stop once this fraction has left
    long maxSteps = 10000000;       //!< error if recovery is not reached
    UnstableStepPolicy onUnstable = UnstableStepPolicy::error;
    //- Called now and then with the recovered fraction (progress display)
    std::function<void(double)> progress;
};

struct RtdResult
{
    std::vector<double> time;       //!< s, from the pulse start
    std::vector<double> E;          //!< 1/s
    double recovered = 0;           //!< fraction of the tracer that left by the last time
    RtdIntegrator used = RtdIntegrator::exact;
    std::vector<std::string> warnings;
};

RtdResult simulateRtd(const TracerSystem& sys, const RtdOptions& options);

//- Forward-Euler stability limit from the eigenvalues of K, s
double forwardEulerStepLimit(const TracerSystem& sys);

//- Exact E at the given times (ascending, >= 0) after a pulse of the given
//  duration; propagators are cached per distinct interval
std::vector<double> exactRtdAt
(
    const TracerSystem& sys,
    double pulseDuration,
    const std::vector<double>& times
);

} // namespace drum

#endif
