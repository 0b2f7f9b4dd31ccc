// TwoPhaseModel, DRUM3: the axial solve (Sherritt 1991 §5.2, Eqs 134-139):
// the holdup profile from the discharge end with the bed slope of Eq 79
#include "drum/transport/twoPhase/twoPhaseModel.hpp"

#include "drum/io/inputError.hpp"
#include "drum/numerics/constants.hpp"
#include "drum/numerics/rungeKutta4.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace drum
{

bool TwoPhaseModel::solveDenseFlow(const TwoPhaseState& s, double feed, double& F2) const
{
    // Eq 55 for F2 at given F0: sum x_f/(A_i + F2) = 1/F0, decreasing in F2
    double amin = 1e300;
    double amax = -1e300;
    for (std::size_t i = 0; i < xf_.size(); ++i)
    {
        if (xf_[i] > 0)
        {
            amin = std::min(amin, s.airborneCapacity[i]);
            amax = std::max(amax, s.airborneCapacity[i]);
        }
    }
    auto f = [&](double x)
    {
        double sum = 0;
        for (std::size_t i = 0; i < xf_.size(); ++i)
        {
            if (xf_[i] > 0)
            {
                sum += xf_[i]/(s.airborneCapacity[i] + x);
            }
        }
        return sum - 1/feed;
    };
    double lo = std::max(feed - amax, -amin + 1e-12*std::max(1.0, std::abs(amin)));
    double hi = feed - amin;
    const double tol = 1e-10/feed;  // rounding of Eq 55 when all A_i are equal
    const double flo = f(lo);
    const double fhi = f(hi);
    if (!(flo >= -tol) || !(fhi <= tol))
    {
        return false;
    }
    if (hi - lo <= 1e-14*std::max(1.0, std::abs(hi)) || std::abs(fhi) <= tol)
    {
        F2 = hi;
        return true;
    }
    for (int it = 0; it < 200 && hi - lo > 1e-14*std::max(1.0, std::abs(hi)); ++it)
    {
        const double m = 0.5*(lo + hi);
        (f(m) > 0 ? lo : hi) = m;
    }
    F2 = 0.5*(lo + hi);
    return true;
}


TwoPhaseResult TwoPhaseModel::solveAxial(double feedRate, const AxialOptions& options) const
{
    if (!(feedRate > 0) || !std::isfinite(feedRate))
    {
        std::ostringstream os;
        os << "feed rate " << feedRate << " kg/s outside (0, inf)";
        throw InputError(case_.name, "feedRate", os.str());
    }
    if (case_.options.imposedDenseFlow)
    {
        // F2 fixed: Eq 55 fixes theta_i everywhere, the holdup is constant
        TwoPhaseResult r = solveConstantHoldup(feedRate).front();
        const TwoPhaseState s = atDischargeAngle(r.dischargeAngle);
        for (double z : {0.0, case_.drum.length})
        {
            r.profile.push_back(profilePoint(s, z));
        }
        return r;
    }
    const double theta0 = options.dischargeEndAngle.value_or(finalAngle_ - 2*deg);
    requireInRange(theta0, minDischargeAngle(), finalAngle_, "dischargeEndAngle [rad]", case_.name);

    const double n = case_.drum.speed;
    const double rhoB = case_.material.bulkDensity;
    const double phi = case_.material.repose;
    const double a = case_.drum.slope;
    const std::size_t nx = xf_.size();

    struct Eval
    {
        TwoPhaseState s;
        double gamma;
        double dHds;
        bool capped;
    };
    auto evaluate = [&](double H, double s)
    {
        Eval e;
        const double theta = thetaOfHoldup(H);
        e.s = TwoPhaseState();
        e.s.dischargeAngle = theta;
        bool over = false;
        e.s.interiorDischargeAngle = interiorAngle(theta, over);
        holdups(theta, e.s.interiorDischargeAngle, e.s);
        e.s.gasVelocity = gasVelocity(e.s.holdup);
        airborneCapacities(theta, e.s.interiorDischargeAngle, e.s.gasVelocity, e.s);
        denseTerms(theta, e.s.interiorDischargeAngle, e.s);
        double F2 = 0;
        if (!solveDenseFlow(e.s, feedRate, F2))
        {
            std::ostringstream os;
            os << "no dense-phase flow satisfies Eq 55 for feed " << feedRate
               << " kg/s at " << s << " m from the discharge (theta_i = " << theta/deg
               << " deg): some size class moves against the solids";
            throw InputError(case_.name, "feedRate", os.str());
        }
        e.s.feedRate = feedRate;
        e.s.denseFlow = F2;
        e.s.airborneFlow = feedRate - F2;
        e.s.holdupFractions.resize(nx);
        for (std::size_t i = 0; i < nx; ++i)
        {
            e.s.holdupFractions[i] = feedRate*xf_[i]/(e.s.airborneCapacity[i] + F2);  // Eq 53
        }
        // Eq 135 with N_ex,s in the denominator (code), gamma capped at phi
        const double c3 = std::pow(e.s.chord, 3);
        double gamma;
        if (c3*e.s.slopedSurfaces > 0)
        {
            gamma = (2/(pi*c3*e.s.slopedSurfaces)*(3*F2*std::sin(phi)/(n*rhoB) - a*e.s.dischargingCubes) - a)
                /std::cos(phi);
        }
        else
        {
            gamma = F2 > denseFlow(e.s, 0.0) ? phi : -phi;
        }
        e.gamma = std::clamp(gamma, -phi, phi);
        e.capped = !(std::abs(gamma) < phi);  // Eq 79 at |gamma| = phi cannot give F2
        e.dHds = e.gamma*e.s.chord*e.s.slopedSurfaces;  // Eq 134 (z from the discharge end)
        return e;
    };

    // state: H, int H, int H1, int F2, int H x_d,i
    const std::size_t ny = 4 + nx;
    auto rhs = [&](double s, const std::vector<double>& y, Eval* keep)
    {
        const Eval e = evaluate(y[0], s);
        std::vector<double> d(ny);
        d[0] = e.dHds;
        d[1] = e.s.holdup;
        d[2] = e.s.airborneHoldup;
        d[3] = e.s.denseFlow;
        for (std::size_t i = 0; i < nx; ++i)
        {
            d[4 + i] = e.s.holdup*e.s.holdupFractions[i];
        }
        if (keep)
        {
            *keep = e;
        }
        return d;
    };

    const double L = case_.drum.length;
    const int steps = case_.options.axialSteps;
    const double h = L/steps;
    std::vector<double> y(ny, 0.0);
    y[0] = holdupAt(theta0);
    TwoPhaseResult r;
    r.feedRate = feedRate;
    for (int k = 0; k < steps; ++k)
    {
        const double s = k*h;
        Eval e0;
        const auto k1 = rhs(s, y, &e0);
        r.profile.push_back(profilePoint(e0.s, s));
        r.profile.back().bedSlope = e0.gamma;
        r.profile.back().slopeCapped = e0.capped;
        if (e0.capped)
        {
            r.cappedLength += h;
        }
        rungeKutta4Step([&](double si, const std::vector<double>& yi) { return rhs(si, yi, nullptr); },
            s, h, k1, y);
    }
    Eval eL;
    rhs(L, y, &eL);
    r.profile.push_back(profilePoint(eL.s, L));
    r.profile.back().bedSlope = eL.gamma;
    r.profile.back().slopeCapped = eL.capped;
    if (eL.capped)
    {
        // Still at the cap at the feed end: even a bed sloped at phi does
        // not carry the dense flow Eq 55 needs there, and where the chord
        // l(theta_i) vanishes Eq 134 stops the holdup rising at all, so the
        // profile would end at the flights' capacity whatever the feed
        // (the Sheikh plateau). No steady state: refuse.
        const auto [maxFeed, maxAt] = largestCarriedFeed(drum1Grid());
        std::ostringstream os;
        os << "feed " << feedRate << " kg/s is beyond what the drum can carry: the bed slope is still held at"
           << " the cap phi = " << phi/deg << " deg at the feed end (Eqs 79, 135; capped over "
           << r.cappedLength << " of " << L << " m, feed-end theta_i " << eL.s.dischargeAngle/deg
           << " deg, chord " << eL.s.chord << " m). Without bed slope (DRUM1) the drum carries at most "
           << maxFeed << " kg/s (theta_i = " << maxAt/deg << " deg)";
        throw InputError(case_.name, "feedRate", os.str());
    }

    const double intH = y[1];
    r.holdupMass = rhoB*intH;
    r.airborneFraction = y[2]/intH;
    r.meanResidenceTime = rhoB*intH/feedRate;  // Eq 138 with Eq 137
    r.denseFlow = y[3]/L;
    r.airborneFlow = feedRate - r.denseFlow;
    for (std::size_t i = 0; i < nx; ++i)
    {
        r.holdupFractions.push_back(y[4 + i]/intH);
        r.sizeResidenceTimes.push_back(xf_[i] > 0 ? rhoB/(feedRate*xf_[i])*y[4 + i] : 0.0);  // Eq 139
    }
    r.dischargeAngle = eL.s.dischargeAngle;
    const double tf = r.dischargeAngle;
    r.regime = tf <= phi + 0.5*pi ? LoadingRegime::buried
        : std::abs(tf - pi) < 1e-9 ? LoadingRegime::design
        : tf < pi ? LoadingRegime::overloaded : LoadingRegime::underloaded;
    return r;
}

} // namespace drum
