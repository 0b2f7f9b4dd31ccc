// Moments of a residence-time distribution.
//
// Definitions used throughout (state them when comparing with the theses):
//   area      m0 = int E dt
//   mean      mu = int t E dt / m0
//   variance  s2 = int (t - mu)^2 E dt / m0,   SD = sqrt(s2)
//   skewness  g1 = int (t - mu)^3 E dt / (m0 SD^3)   (standardised, dimensionless)
// Lee's Table 7.3 prints a "skewness (min)" of unstated definition; it is
// not this one (docs/errata.md L18).
#ifndef DRUM_RTD_RTDMOMENTS_HPP
#define DRUM_RTD_RTDMOMENTS_HPP

#include "drum/rtd/tracerSystem.hpp"

#include <vector>

namespace drum
{

struct RtdMoments
{
    double area = 0;        //!< int E dt (recovered fraction for a unit pulse)
    double mean = 0;        //!< s
    double variance = 0;    //!< s^2
    double skewness = 0;    //!< standardised, dimensionless

    double sd() const;
};

//- Trapezoidal moments of a sampled curve (times ascending); times before
//  zero are ignored. Throws InputError on mismatched or unsorted input.
RtdMoments sampledMoments(const std::vector<double>& t, const std::vector<double>& E);

//- Exact moments of the network's response to a rectangular pulse of the
//  given duration (0: impulse): int t^k c e^{Kt} b dt = k! c (-K)^{-(k+1)} b,
//  convolved with the uniform pulse shape (mean + T/2, variance + T^2/12,
//  third central moment unchanged). Sparse LU solves only.
RtdMoments exactMoments(const TracerSystem& sys, double pulseDuration);

} // namespace drum

#endif
