// TwoPhaseModel: holdups (airborne, discharging, non-discharging), gas
// velocity, airborne capacities, dense-phase terms and the feed balance at one
// discharge angle (Sherritt 1991 Ch. 3-4)
#include "drum/transport/twoPhase/twoPhaseModel.hpp"

#include "drum/io/inputError.hpp"
#include "drum/numerics/constants.hpp"
#include "particleDrag/loneParticleFall.hpp"
#include "drum/numerics/gaussLegendre.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace drum
{

namespace
{

// The holdup integrals: composite 4-point Gauss-Legendre, panels split at
// the given breakpoints and no wider than hmax
template<class F>
double integrate(const F& f, double a, double b, std::vector<double> breaks, double hmax = 0.5*deg)
{
    return compositeGaussLegendre<4>(f, a, b, std::move(breaks), PanelSplit{0, hmax});
}

std::vector<double> within(const std::vector<double>& v, double a, double b)
{
    std::vector<double> out;
    for (const double x : v)
    {
        if (x > a && x < b)
        {
            out.push_back(x);
        }
    }
    return out;
}

} // namespace


double TwoPhaseModel::airborneMass(double thetaI, double psiI) const
{
    const double n = case_.drum.speed;
    const double rhoB = case_.material.bulkDensity;
    const double phi = case_.material.repose;
    // buried flights shed nothing to the curtains (code fallrate/flowrates)
    const double lo = thetaI > 0.5*pi + phi ? thetaI : pi + 2*phi - thetaI;
    auto fex = [&](double t)
    {
        const double l = ex_.length(t);
        return l*l*particleDrag::fallTime(exteriorFallHeight(t));
    };
    const std::vector<double> brk{pi, g_.thetaA, g_.thetaB};
    double m = case_.exterior->count()*integrate(fex, lo, 2*pi, within(ex_.nodes(), lo, 2*pi), 1*deg);
    if (in_)
    {
        auto fin = [&](double p)
        {
            const double l = in_->length(p);
            return l*l*particleDrag::fallTime(interiorFallHeight(p));
        };
        m += case_.interior->count()*integrate(fin, psiI, pi, within(in_->nodes(), psiI, pi), 1*deg);
    }
    (void)brk;
    return 0.5*n*rhoB*m;  // Eq 91, kg per metre of drum
}


void TwoPhaseModel::holdups(double thetaI, double psiI, TwoPhaseState& s) const
{
    const int Nex = case_.exterior->count();
    const double E = 2*pi;
    const double thetaF = 2*pi - thetaI;           // Eq 71
    const double Din = case_.interior ? case_.interior->tipDiameter() : 0.0;
    const double Dex = case_.exterior->tipDiameter();
    const double ratioInEx = case_.interior ? double(case_.interior->count())/Nex : 0.0;
    const double thetaD = std::acos(Din/Dex*std::cos(psiI));  // Eq 70

    // Non-discharging exterior flight at theta (0 <= theta <= theta_i):
    // what has fallen into it from the exterior flights straight above
    // (Eqs 101, 102, 107, 108) and from the interior flights (103, 104).
    auto hnd = [&](double t)
    {
        const double top = std::min(t, thetaF);
        double recv = ex_.integralL2(E - std::min(top, g_.thetaC), E);
        if (top > g_.thetaE)
        {
            recv += ex_.integralL2(E - top, E - g_.thetaE);
        }
        if (in_ && t > g_.thetaC)
        {
            double psi = t >= g_.thetaE ? pi : std::acos(std::clamp(Dex*std::cos(t)/Din, -1.0, 1.0));  // Eq 105
            if (psi > psiI)
            {
                recv += ratioInEx*in_->integralL2(psiI, psi);
            }
        }
        return 0.5*recv;
    };
    double ndEx;
    if (!in_)
    {
        // Open drum (theta_c = theta_e = pi/2): the flight at theta holds
        // 1/2 (C(2 pi) - C(2 pi - min(theta, theta_f))), C = int l^2, so its
        // integral over [0, theta_i] is exact through int C (Eqs 101, 102)
        const double top = std::min(thetaI, thetaF);
        ndEx = 0.5*(thetaI*ex_.cumulativeL2(E) - ex_.integralOfCumulativeL2(E - top, E)
                    - std::max(0.0, thetaI - thetaF)*ex_.cumulativeL2(E - thetaF));
    }
    else
    {
        std::vector<double> brk{g_.thetaC, g_.thetaE, thetaD, thetaF};
        for (const double x : ex_.nodes())
        {
            brk.push_back(E - x);
        }
        ndEx = integrate(hnd, 0.0, thetaI, within(brk, 0.0, thetaI));
    }
    // Discharging exterior flights, int h (Eq 97) over theta_i..2 pi as
    // Eq 122, buried flights included: with theta_i below the flights'
    // pocket range l is the bed chord (tabulateSherrittFlight), and a buried
    // flight's h is the share of the bed its own surface sheds (the line
    // stops at the next flight), so flights + bed are counted once each
    const double disEx = 0.5*ex_.iteratedDischarge(thetaI, E);

    double ndIn = 0;
    double disIn = 0;
    if (in_)
    {
        const int Nin = case_.interior->count();
        const double ratioExIn = double(Nex)/Nin;
        const double lower = std::max(g_.thetaA, thetaI);
        const double total = lower < g_.thetaB ? ratioExIn*ex_.integralL2(lower, g_.thetaB) : 0.0;
        // receiving half pi..2pi (Eqs 109, 110, 114 with Eq 112)
        auto hrecv = [&](double psi)
        {
            const double th = pi + std::acos(std::clamp(Din*std::cos(psi - pi)/Dex, -1.0, 1.0));
            return th > lower ? 0.5*ratioExIn*ex_.integralL2(lower, std::min(th, g_.thetaB)) : 0.0;
        };
        ndIn = integrate(hrecv, pi, 2*pi, {}) + psiI*0.5*std::min(total, 2*in_->holdupVolume(0.0));  // Eqs 111/115
        disIn = 0.5*in_->iteratedDischarge(psiI, pi);  // Eq 98
        ndIn *= Nin/(2*pi);
        disIn *= Nin/(2*pi);
    }
    s.nonDischargingHoldup = Nex/(2*pi)*ndEx + ndIn;  // Eq 116/123, 126
    s.dischargingHoldup = Nex/(2*pi)*disEx + disIn;
    s.airborneHoldup = airborneMass(thetaI, psiI)/case_.material.bulkDensity;  // Eq 127
    // What the flights shed into the curtains: Eq 40/41 summed over the
    // discharging arcs, with the airborne limits of Eq 91 (buried flights
    // shed onto the covering surface, not into the curtains)
    const double phi = case_.material.repose;
    const double lo = thetaI > 0.5*pi + phi ? thetaI : pi + 2*phi - thetaI;
    double shed = Nex*ex_.integralL2(lo, 2*pi);
    if (in_)
    {
        shed += case_.interior->count()*in_->integralL2(psiI, pi);
    }
    s.circulation = 0.5*case_.drum.speed*case_.material.bulkDensity*shed;
    s.holdup = s.airborneHoldup + s.nonDischargingHoldup + s.dischargingHoldup;
}


double TwoPhaseModel::holdupAt(double thetaI) const
{
    bool over = false;
    const double psiI = interiorAngle(thetaI, over);
    TwoPhaseState s;
    holdups(thetaI, psiI, s);
    return s.holdup;
}


double TwoPhaseModel::gasVelocity(double holdup) const
{
    const auto& d = case_.drum;
    const double area = 0.25*pi*(d.shellDiameter*d.shellDiameter - d.centrefillDiameter*d.centrefillDiameter) - holdup;
    if (case_.gas.massRate == 0)
    {
        return 0.0;
    }
    if (!(area > 0))
    {
        return std::numeric_limits<double>::infinity();
    }
    return case_.gas.massRate/(gasDensity_*area);  // code annulusvel()
}


void TwoPhaseModel::airborneCapacities(double thetaI, double psiI, double Vg, TwoPhaseState& s) const
{
    const double n = case_.drum.speed;
    const double rhoB = case_.material.bulkDensity;
    const double phi = case_.material.repose;
    const double lo = thetaI > 0.5*pi + phi ? thetaI : pi + 2*phi - thetaI;
    s.airborneCapacity.assign(xf_.size(), 0.0);
    for (std::size_t i = 0; i < xf_.size(); ++i)
    {
        DriftQuery q;
        q.particleDiameter = dp_[i];
        q.particleDensity = case_.material.particleDensity;
        q.gasVelocity = Vg;
        q.incline = alphaGas_;
        q.flightLength = case_.exterior->axialLength();
        auto fex = [&](double t)
        {
            const double l = ex_.length(t);
            if (l <= 0)
            {
                return 0.0;
            }
            q.fallHeight = exteriorFallHeight(t);
            q.spillRate = pi*n*rhoB*l*l;  // Eq 40
            return l*l*drift_->displacement(q);
        };
        double I = case_.exterior->count()*integrate(fex, lo, 2*pi, within(ex_.nodes(), lo, 2*pi), 1*deg);  // Eq 48
        if (in_)
        {
            q.flightLength = case_.interior->axialLength();
            auto fin = [&](double p)
            {
                const double l = in_->length(p);
                if (l <= 0)
                {
                    return 0.0;
                }
                q.fallHeight = interiorFallHeight(p);
                q.spillRate = pi*n*rhoB*l*l;  // Eq 41
                return l*l*drift_->displacement(q);
            };
            I += case_.interior->count()*integrate(fin, psiI, pi, within(in_->nodes(), psiI, pi), 1*deg);  // Eq 50
        }
        s.airborneCapacity[i] = toSolids_*0.5*n*rhoB*I;  // Eq 51 without x_d,i
    }
}


void TwoPhaseModel::denseTerms(double thetaI, double psiI, TwoPhaseState& s) const
{
    const double phi = case_.material.repose;
    const int Nex = case_.exterior->count();
    SurfaceClosureInput in;
    in.dischargeAngle = thetaI;
    const double Din = case_.interior ? case_.interior->tipDiameter() : 0.0;
    in.thetaD = std::acos(Din/case_.exterior->tipDiameter()*std::cos(psiI));  // Eq 70
    in.thetaF = 2*pi - thetaI;  // Eq 71
    in.thetaA = g_.thetaA;
    in.thetaB = g_.thetaB;
    in.centrefill = case_.interior.has_value();
    in.exteriorCount = Nex;
    in.surfaceAtDischarge = ex_.length(thetaI);
    in.repose = phi;
    const SlopedSurfaces sl = case_.options.closure(in);
    s.slopedSurfaces = sl.count;
    s.chord = sl.chord;

    double Jex;
    if (thetaI <= phi + 0.5*pi)
    {
        // Eq 85: flights covered by the first discharging surface do not advance
        const double a = thetaI + 2*pi/Nex;
        const double b = 2*phi + pi - thetaI;
        Jex = a >= b ? ex_.integralL3(thetaI, 2*pi)
                     : ex_.integralL3(thetaI, a) + ex_.integralL3(b, 2*pi);
    }
    else
    {
        Jex = ex_.integralL3(thetaI, 2*pi);  // Eq 81
    }
    double cubes = Nex*Jex;
    if (in_)
    {
        cubes += case_.interior->count()*in_->integralL3(psiI, pi);  // Eq 82
    }
    s.dischargingCubes = cubes;
}


double TwoPhaseModel::denseFlow(const TwoPhaseState& s, double gamma) const
{
    if (case_.options.imposedDenseFlow)
    {
        return *case_.options.imposedDenseFlow;
    }
    const double n = case_.drum.speed;
    const double rhoB = case_.material.bulkDensity;
    const double phi = case_.material.repose;
    const double a = case_.drum.slope;  // solids frame, small-angle form
    const double c3 = s.chord*s.chord*s.chord;
    // Eq 79 (gamma = 0: Eq 86)
    return n*rhoB/(6*std::sin(phi))
        *(pi*s.slopedSurfaces*(a + gamma*std::cos(phi))*c3 + 2*a*s.dischargingCubes);
}


void TwoPhaseModel::solveFeed(TwoPhaseState& s) const
{
    const double F2 = denseFlow(s, 0.0);
    s.denseFlow = F2;
    double inv = 0;
    for (std::size_t i = 0; i < xf_.size(); ++i)
    {
        const double den = s.airborneCapacity[i] + F2;
        if (xf_[i] > 0 && !(den > 0))
        {
            std::ostringstream os;
            os << "size class " << i << " (" << case_.material.sieveSizes[i]*1e6
               << " um) would move against the solids flow: x_d < 0 (Sherritt 1991 §3.4)";
            s.valid = false;
            s.note = os.str();
            return;
        }
        inv += xf_[i]/den;  // Eq 55
    }
    s.feedRate = 1/inv;
    s.airborneFlow = s.feedRate - F2;  // Eq 34
    s.holdupFractions.resize(xf_.size());
    for (std::size_t i = 0; i < xf_.size(); ++i)
    {
        s.holdupFractions[i] = s.feedRate*xf_[i]/(s.airborneCapacity[i] + F2);  // Eq 53
    }
    s.valid = std::isfinite(s.feedRate) && s.feedRate > 0;
    if (!s.valid)
    {
        s.note = "no positive feed rate at this loading";
    }
}

} // namespace drum
