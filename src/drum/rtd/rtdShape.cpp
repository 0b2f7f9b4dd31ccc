#include "drum/rtd/rtdShape.hpp"

#include "drum/io/inputError.hpp"
#include "drum/rtd/rtdMoments.hpp"

#include <cmath>

namespace drum
{

namespace
{

//- The curve from time 0 on (the part before the pulse start left out)
void fromZero(const std::vector<double>& t, const std::vector<double>& E,
              std::vector<double>& t0, std::vector<double>& E0)
{
    if (t.size() != E.size() || t.size() < 2)
    {
        throw InputError("", "RTD curve", "times and E(t) must have the same length >= 2");
    }
    for (std::size_t i = 0; i < t.size(); ++i)
    {
        if (t[i] >= 0)
        {
            t0.push_back(t[i]);
            E0.push_back(E[i]);
        }
    }
}

} // namespace


double rtdQuantile(const std::vector<double>& t, const std::vector<double>& E, const double q)
{
    std::vector<double> ts, Es;
    fromZero(t, E, ts, Es);
    std::vector<double> F(ts.size(), 0.0);
    for (std::size_t i = 1; i < ts.size(); ++i)
    {
        F[i] = F[i - 1] + 0.5*(ts[i] - ts[i - 1])*(Es[i] + Es[i - 1]);
    }
    const double target = q*F.back();
    if (!(F.back() > 0))
    {
        return std::nan("");
    }
    for (std::size_t i = 1; i < ts.size(); ++i)
    {
        if (F[i] >= target)
        {
            const double dF = F[i] - F[i - 1];
            return dF > 0 ? ts[i - 1] + (target - F[i - 1])/dF*(ts[i] - ts[i - 1]) : ts[i];
        }
    }
    return ts.back();
}


RtdShape rtdShape(const std::vector<double>& t, const std::vector<double>& E, const double bodyEnd)
{
    std::vector<double> ts, Es;
    fromZero(t, E, ts, Es);
    RtdShape s;
    s.bodyEnd = bodyEnd;
    s.t10 = rtdQuantile(ts, Es, 0.1);
    s.t50 = rtdQuantile(ts, Es, 0.5);
    s.t90 = rtdQuantile(ts, Es, 0.9);
    // the body: the samples up to bodyEnd (a tracer's own sampling points, as its
    // analyst would integrate them; no point is made up between two samples)
    std::vector<double> tb, Eb;
    for (std::size_t i = 0; i < ts.size() && ts[i] <= bodyEnd; ++i)
    {
        tb.push_back(ts[i]);
        Eb.push_back(Es[i]);
    }
    const RtdMoments whole = sampledMoments(ts, Es);
    if (tb.size() < 2 || !(whole.area > 0))
    {
        s.bodyMean = s.bodySd = s.tailShare = std::nan("");
        return s;
    }
    const RtdMoments body = sampledMoments(tb, Eb);
    s.bodyMean = body.mean;
    s.bodySd = body.sd();
    s.tailShare = 1 - body.area/whole.area;
    return s;
}

} // namespace drum
