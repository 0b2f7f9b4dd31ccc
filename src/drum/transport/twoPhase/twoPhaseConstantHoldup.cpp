// TwoPhaseModel, DRUM1: constant holdup along the drum (Sherritt 1991 §5.1):
// the state at a discharge angle, the theta_i sweep and every root of F0 = feed
#include "drum/transport/twoPhase/twoPhaseModel.hpp"

#include "drum/io/inputError.hpp"
#include "drum/numerics/constants.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace drum
{

TwoPhaseState TwoPhaseModel::atDischargeAngle(double thetaI) const
{
    if (!(thetaI > 0 && thetaI <= 2*pi))
    {
        std::ostringstream os;
        os << "initial discharge angle " << thetaI/deg << " deg outside (0, 360] deg";
        throw InputError(case_.name, "dischargeAngle", os.str());
    }
    TwoPhaseState s;
    s.dischargeAngle = thetaI;
    const double phi = case_.material.repose;
    s.regime = thetaI <= phi + 0.5*pi ? LoadingRegime::buried
        : std::abs(thetaI - pi) < 1e-9 ? LoadingRegime::design
        : thetaI < pi ? LoadingRegime::overloaded : LoadingRegime::underloaded;
    s.interiorDischargeAngle = interiorAngle(thetaI, s.interiorOverfilled);
    holdups(thetaI, s.interiorDischargeAngle, s);
    s.gasVelocity = gasVelocity(s.holdup);
    if (!std::isfinite(s.gasVelocity))
    {
        s.valid = false;
        s.note = "holdup fills the gas flow area";
        return s;
    }
    airborneCapacities(thetaI, s.interiorDischargeAngle, s.gasVelocity, s);
    denseTerms(thetaI, s.interiorDischargeAngle, s);
    solveFeed(s);
    return s;
}


std::vector<TwoPhaseState> TwoPhaseModel::sweep(double from, double to, int points) const
{
    if (points < 2)
    {
        throw InputError(case_.name, "sweep points", "need at least 2");
    }
    std::vector<TwoPhaseState> out;
    for (int k = 0; k < points; ++k)
    {
        out.push_back(atDischargeAngle(from + (to - from)*k/(points - 1)));
    }
    return out;
}


TwoPhaseProfilePoint TwoPhaseModel::profilePoint(const TwoPhaseState& s, double distanceFromDischarge) const
{
    TwoPhaseProfilePoint p;
    p.distanceFromDischarge = distanceFromDischarge;
    p.dischargeAngle = s.dischargeAngle;
    p.holdup = s.holdup;
    p.airborneHoldup = s.airborneHoldup;
    p.airborneFlow = s.airborneFlow;
    p.denseFlow = s.denseFlow;
    p.circulation = s.circulation;
    p.airborneCapacity = s.airborneCapacity;
    p.holdupFractions = s.holdupFractions;
    return p;
}


TwoPhaseResult TwoPhaseModel::constantResult(const TwoPhaseState& s) const
{
    const double L = case_.drum.length;
    const double rhoB = case_.material.bulkDensity;
    TwoPhaseResult r;
    r.feedRate = s.feedRate;
    r.holdupMass = s.holdup*rhoB*L;
    r.airborneFraction = s.airborneHoldup/s.holdup;
    r.meanResidenceTime = s.holdup*L*rhoB/s.feedRate;  // Eq 138
    for (std::size_t i = 0; i < xf_.size(); ++i)
    {
        r.sizeResidenceTimes.push_back(xf_[i] > 0 ? r.meanResidenceTime*s.holdupFractions[i]/xf_[i] : 0.0);  // Eq 140
    }
    r.holdupFractions = s.holdupFractions;
    r.airborneFlow = s.airborneFlow;
    r.denseFlow = s.denseFlow;
    r.dischargeAngle = s.dischargeAngle;
    r.regime = s.regime;
    return r;
}


std::vector<TwoPhaseState> TwoPhaseModel::drum1Grid() const
{
    const double lo = minDischargeAngle();
    const double hi = finalAngle_;
    const int n = std::max(8, static_cast<int>(std::ceil((hi - lo)/case_.options.sweepStep)));
    std::vector<TwoPhaseState> states;
    for (int k = 0; k <= n; ++k)
    {
        states.push_back(atDischargeAngle(lo + (hi - lo)*k/n));
    }
    return states;
}


std::vector<TwoPhaseResult> TwoPhaseModel::solveConstantHoldup(double feedRate) const
{
    if (!(feedRate > 0) || !std::isfinite(feedRate))
    {
        std::ostringstream os;
        os << "feed rate " << feedRate << " kg/s outside (0, inf)";
        throw InputError(case_.name, "feedRate", os.str());
    }
    const double lo = minDischargeAngle();
    const double hi = finalAngle_;
    const std::vector<TwoPhaseState> states = drum1Grid();
    const int n = static_cast<int>(states.size()) - 1;
    std::vector<TwoPhaseResult> roots;
    for (int k = n; k >= 1; --k)  // from the lightest loading down
    {
        const auto& a = states[k];
        const auto& b = states[k - 1];
        if (!a.valid || !b.valid)
        {
            continue;
        }
        const double fa = a.feedRate - feedRate;
        const double fb = b.feedRate - feedRate;
        if (fa == 0)
        {
            roots.push_back(constantResult(a));
            continue;
        }
        if ((fa < 0) != (fb < 0))
        {
            double tA = a.dischargeAngle;
            double tB = b.dischargeAngle;
            double fA = fa;
            TwoPhaseState mid = a;
            for (int it = 0; it < 50 && std::abs(tA - tB) > 1e-9; ++it)
            {
                const double t = 0.5*(tA + tB);
                mid = atDischargeAngle(t);
                const double fm = mid.valid ? mid.feedRate - feedRate : fA;
                if ((fm < 0) == (fA < 0))
                {
                    tA = t;
                    fA = fm;
                }
                else
                {
                    tB = t;
                }
            }
            roots.push_back(constantResult(atDischargeAngle(0.5*(tA + tB))));
        }
    }
    if (roots.empty())
    {
        const auto [maxFeed, maxAt] = largestCarriedFeed(states);
        std::ostringstream os;
        if (maxFeed == 0)
        {
            os << "no loading in [" << lo/deg << ", " << hi/deg
               << "] deg carries solids towards the discharge: " << states[n/2].note;
        }
        else if (feedRate > maxFeed)
        {
            os << "feed " << feedRate << " kg/s is beyond what the drum can carry: at most "
               << maxFeed << " kg/s (theta_i = " << maxAt/deg << " deg) over theta_i in ["
               << lo/deg << ", " << hi/deg << "] deg";
        }
        else
        {
            os << "feed " << feedRate << " kg/s is below the smallest flow resolved ("
               << "lightest loading theta_i = " << hi/deg << " deg)";
        }
        throw InputError(case_.name, "feedRate", os.str());
    }
    return roots;
}


double TwoPhaseModel::thetaOfHoldup(double H) const
{
    // H(theta_i) falls as theta_i rises; search from the light end
    const std::size_t n = Htheta_.size();
    if (H <= Hvalue_.back())
    {
        return Htheta_.back();
    }
    for (std::size_t k = n - 1; k-- > 0;)
    {
        if (Hvalue_[k] >= H)
        {
            // Illinois regula falsi in the 1-degree bracket of the table:
            // a handful of holdup evaluations instead of ~40 bisections
            double a = Htheta_[k];       // H(a) >= H
            double b = Htheta_[k + 1];   // H(b) < H
            double fa = Hvalue_[k] - H;
            double fb = Hvalue_[k + 1] - H;
            int side = 0;
            const double tolH = 1e-12*std::max(H, 1e-300);
            for (int it = 0; it < 100 && b - a > 1e-12; ++it)
            {
                const double t = fa - fb > 0 ? std::clamp(b - fb*(b - a)/(fb - fa), a, b) : 0.5*(a + b);
                const double ft = holdupAt(t) - H;
                if (std::abs(ft) <= tolH)
                {
                    return t;
                }
                if (ft > 0)
                {
                    a = t;
                    fa = ft;
                    if (side == 1) fb *= 0.5;
                    side = 1;
                }
                else
                {
                    b = t;
                    fb = ft;
                    if (side == -1) fa *= 0.5;
                    side = -1;
                }
            }
            return 0.5*(a + b);
        }
    }
    std::ostringstream os;
    os << "holdup " << H << " m3/m exceeds the most the flights carry in the searched range ("
       << Hvalue_.front() << " m3/m at theta_i = " << Htheta_.front()/deg
       << " deg): the drum cannot carry this feed";
    throw InputError(case_.name, "feedRate", os.str());
}

} // namespace drum
