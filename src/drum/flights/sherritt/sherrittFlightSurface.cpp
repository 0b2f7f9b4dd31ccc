#include "drum/flights/sherritt/sherrittFlightSurface.hpp"
#include "drum/numerics/constants.hpp"

#include "drum/io/inputError.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace drum
{

namespace
{

// int_0^w (l0 + (l - l0) u/w)^2 du for a linear l from l0 to l over width w
double segL2(double l0, double l, double w)
{
    return w*(l0*l0 + l0*l + l*l)/3.0;
}

double segL3(double l0, double l, double w)
{
    return w*(l0 + l)*(l0*l0 + l*l)/4.0;
}
} // namespace


SherrittFlightSurface::SherrittFlightSurface(const SherrittFlightProfile& profile, double repose)
:
    profile_(profile),
    repose_(repose)
{
    if (!(repose > 0.0 && repose < 0.5*pi))
    {
        std::ostringstream os;
        os << "kinetic angle of repose " << repose*180/pi
           << " deg outside the open range (0, 90) deg";
        throw InputError(profile.source(), "repose angle", os.str());
    }
    const double hi = profile.emptyAngle();
    const double lo = hi - 2*pi;

    // Raw (unclamped) l between lo and hi is linear between the shifted
    // table angles; add the zero crossings so the clamped l is linear too
    std::vector<double> x{lo, hi};
    for (const double a : profile.angles())
    {
        const double t = a + repose;
        if (t > lo && t < hi)
        {
            x.push_back(t);
        }
    }
    std::sort(x.begin(), x.end());
    auto raw = [&](double t) { return profile.horizontalLength(t - repose); };
    for (std::size_t k = 0; k + 1 < x.size(); ++k)
    {
        const double r0 = raw(x[k]);
        const double r1 = raw(x[k + 1]);
        nodes_.push_back(x[k]);
        if ((r0 < 0 && r1 > 0) || (r0 > 0 && r1 < 0))
        {
            nodes_.push_back(x[k] + (x[k + 1] - x[k])*r0/(r0 - r1));
        }
    }
    nodes_.push_back(x.back());
    nodes_.erase(std::unique(nodes_.begin(), nodes_.end()), nodes_.end());

    values_.resize(nodes_.size());
    for (std::size_t k = 0; k < nodes_.size(); ++k)
    {
        values_[k] = std::max(0.0, raw(nodes_[k]));
    }

    cumL2_.assign(nodes_.size(), 0.0);
    cumL3_.assign(nodes_.size(), 0.0);
    cumC_.assign(nodes_.size(), 0.0);
    for (std::size_t k = 0; k + 1 < nodes_.size(); ++k)
    {
        const double w = nodes_[k + 1] - nodes_[k];
        cumL2_[k + 1] = cumL2_[k] + segL2(values_[k], values_[k + 1], w);
        cumL3_[k + 1] = cumL3_[k] + segL3(values_[k], values_[k + 1], w);
        cumC_[k + 1] = cumC_[k] + partialIntC(k, nodes_[k + 1]);
    }
}


std::size_t SherrittFlightSurface::interval(double x) const
{
    if (x <= nodes_.front())
    {
        return 0;
    }
    if (x >= nodes_.back())
    {
        return nodes_.size() - 2;
    }
    return static_cast<std::size_t>
    (
        std::upper_bound(nodes_.begin(), nodes_.end(), x) - nodes_.begin()
    ) - 1;
}


double SherrittFlightSurface::length(double theta) const
{
    const double x = std::clamp(theta, nodes_.front(), nodes_.back());
    const std::size_t k = interval(x);
    const double w = nodes_[k + 1] - nodes_[k];
    return values_[k] + (values_[k + 1] - values_[k])*(x - nodes_[k])/w;
}


double SherrittFlightSurface::dischargeRate(double theta, double rps, double bulkDensity) const
{
    if (theta > emptyAngle() || theta < lowerAngle())
    {
        return 0.0;
    }
    const double l = length(theta);
    return pi*rps*bulkDensity*l*l;  // Sherritt 1991 Eq 40 (Eq 41 interior)
}


double SherrittFlightSurface::cumulativeL2(double theta) const
{
    const double x = std::clamp(theta, nodes_.front(), nodes_.back());
    const std::size_t k = interval(x);
    return cumL2_[k] + segL2(values_[k], length(x), x - nodes_[k]);
}


double SherrittFlightSurface::integralL2(double a, double b) const
{
    return cumulativeL2(b) - cumulativeL2(a);
}


double SherrittFlightSurface::integralL3(double a, double b) const
{
    auto cum = [&](double theta)
    {
        const double x = std::clamp(theta, nodes_.front(), nodes_.back());
        const std::size_t k = interval(x);
        return cumL3_[k] + segL3(values_[k], length(x), x - nodes_[k]);
    };
    return cum(b) - cum(a);
}


double SherrittFlightSurface::partialIntC(std::size_t k, double x) const
{
    // C is a cubic on the interval: 2-point Gauss-Legendre is exact
    const double x0 = nodes_[k];
    const double w = x - x0;
    if (w <= 0)
    {
        return 0.0;
    }
    const double g = 0.5/std::sqrt(3.0);
    double sum = 0;
    for (const double u : {0.5 - g, 0.5 + g})
    {
        const double t = x0 + u*w;
        const double l = values_[k] + (values_[k + 1] - values_[k])*(t - x0)/(nodes_[k + 1] - x0);
        sum += cumL2_[k] + segL2(values_[k], l, t - x0);
    }
    return 0.5*w*sum;
}


double SherrittFlightSurface::integralOfCumulativeL2(double a, double b) const
{
    auto cum = [&](double theta)
    {
        const double x = std::clamp(theta, nodes_.front(), nodes_.back());
        const std::size_t k = interval(x);
        // outside the domain C is constant: add its share
        const double outside =
            theta > nodes_.back() ? (theta - nodes_.back())*cumL2_.back() : 0.0;
        return cumC_[k] + partialIntC(k, x) + outside;
    };
    return cum(b) - cum(a);
}


double SherrittFlightSurface::iteratedDischarge(double a, double b) const
{
    // int_a^b (C(E) - C(theta)) dtheta
    return (b - a)*cumL2_.back() - integralOfCumulativeL2(a, b);
}


double SherrittFlightSurface::holdupVolume(double theta) const
{
    return 0.5*integralL2(theta, emptyAngle());  // Eq 97/98
}


double SherrittFlightSurface::holdupMass(double theta, double bulkDensity) const
{
    return bulkDensity*holdupVolume(theta);
}


double SherrittFlightSurface::initialDischargeAngle(double volume) const
{
    const double full = holdupVolume(lowerAngle());
    if (!(volume >= 0.0) || !(volume <= full*(1 + 1e-12)))
    {
        std::ostringstream os;
        os << "flight holdup " << volume << " m3/m outside [0, " << full
           << "] m3/m, the most this flight holds at phi = "
           << repose_*180/pi << " deg";
        throw InputError(profile_.source(), "flight holdup volume", os.str());
    }
    // h(theta) is non-increasing: search the node table, then solve the
    // cubic on the interval by bisection
    const double target = 2*volume;  // int_theta^E l^2
    const double total = cumL2_.back();
    // want C(theta) = total - target; pick the largest theta
    const double c = total - target;
    std::size_t k = nodes_.size() - 2;
    while (k > 0 && cumL2_[k] > c)
    {
        --k;
    }
    double lo = nodes_[k];
    double hi = nodes_[k + 1];
    if (cumL2_[k + 1] <= c)
    {
        return hi;
    }
    for (int it = 0; it < 200 && hi - lo > 1e-14; ++it)
    {
        const double mid = 0.5*(lo + hi);
        if (cumulativeL2(mid) > c)
        {
            hi = mid;
        }
        else
        {
            lo = mid;
        }
    }
    return 0.5*(lo + hi);
}

} // namespace drum
