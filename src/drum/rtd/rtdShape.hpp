// The shape of a residence-time distribution as a tracer test reads it: the
// quantiles t10, t50, t90 of the cumulative curve, the mean and SD of its body
// (the part before a cut time) and the share of the tracer after that cut (the
// tail). Each curve is normalised by its own area, so a model's RTD and a
// measured tracer curve of another total compare alike.
#ifndef DRUM_RTD_RTDSHAPE_HPP
#define DRUM_RTD_RTDSHAPE_HPP

#include <string>
#include <vector>

namespace drum
{

struct RtdShape
{
    double t10 = 0, t50 = 0, t90 = 0;   //!< s: times by which 10, 50, 90 % came out
    double bodyMean = 0, bodySd = 0;     //!< s: moments of the part before bodyEnd
    double tailShare = 0;                //!< share of the area after bodyEnd
    double bodyEnd = 0;                  //!< s
};

//- The time by which the share `q` of the curve's area came out (linear in the
//  cumulative trapezoids; times before 0 ignored)
double rtdQuantile(const std::vector<double>& t, const std::vector<double>& E, double q);

//- The shape of a sampled curve (times ascending) with its body cut at bodyEnd (s)
RtdShape rtdShape(const std::vector<double>& t, const std::vector<double>& E, double bodyEnd);

} // namespace drum

#endif
