#include "drum/transport/twoPhaseModel.hpp"
#include "drum/numerics/constants.hpp"

#include "drum/io/inputError.hpp"
#include "particleDrag/loneParticleFall.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <utility>

namespace drum
{

namespace
{

// Composite 4-point Gauss-Legendre over [a, b], panels split at the given
// breakpoints and no wider than hmax
template<class F>
double integrate(F f, double a, double b, std::vector<double> breaks, double hmax = 0.5*deg)
{
    if (!(b > a))
    {
        return 0.0;
    }
    static const double x[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
    static const double w[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
    breaks.push_back(a);
    breaks.push_back(b);
    std::sort(breaks.begin(), breaks.end());
    double sum = 0;
    double lo = a;
    for (const double bp : breaks)
    {
        const double hi = std::min(bp, b);
        if (hi <= lo)
        {
            continue;
        }
        const int n = std::max(1, static_cast<int>(std::ceil((hi - lo)/hmax)));
        const double h = (hi - lo)/n;
        for (int k = 0; k < n; ++k)
        {
            const double c = lo + (k + 0.5)*h;
            for (int j = 0; j < 4; ++j)
            {
                sum += 0.5*h*w[j]*f(c + 0.5*h*x[j]);
            }
        }
        lo = hi;
    }
    return sum;
}

// The largest feed DRUM1 carries over a set of states, and its theta_i
// (0, 0 when none carries solids towards the discharge)
std::pair<double, double> largestFeed(const std::vector<TwoPhaseState>& states)
{
    double maxFeed = 0;
    double maxAt = 0;
    for (const TwoPhaseState& st : states)
    {
        if (st.valid && st.feedRate > maxFeed)
        {
            maxFeed = st.feedRate;
            maxAt = st.dischargeAngle;
        }
    }
    return {maxFeed, maxAt};
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


std::string loadingRegimeName(LoadingRegime r)
{
    switch (r)
    {
        case LoadingRegime::underloaded: return "underloaded";
        case LoadingRegime::design: return "design";
        case LoadingRegime::overloaded: return "overloaded";
        case LoadingRegime::buried: return "buried";
    }
    return "?";
}


TwoPhaseModel::TwoPhaseModel(TwoPhaseCase c)
:
    case_(std::move(c)),
    ex_
    (
        [&]() -> const SherrittFlightProfile&
        {
            if (!case_.exterior)
            {
                throw InputError(case_.name, "flights.exterior", "missing: the model needs exterior flights");
            }
            return *case_.exterior;
        }(),
        case_.material.repose
    )
{
    const auto& d = case_.drum;
    const auto& m = case_.material;
    const std::string& file = case_.name;
    requirePositive(d.shellDiameter, "drum.diameter", file);
    requirePositive(d.length, "drum.length", file);
    requireInRange(d.slope, 0.0, 20*deg, "drum.slope [rad]", file);
    if (!(d.speed > 0 && d.speed <= 1.0))
    {
        std::ostringstream os;
        os << "speed " << d.speed << " rev/s outside (0, 1] rev/s";
        throw InputError(file, "drum.speed", os.str());
    }
    case_.exterior->checkTipsAgainst(d.shellDiameter, "flights.exterior.tipDiameter");
    if (d.centrefillDiameter != 0)
    {
        requireInRange(d.centrefillDiameter, 0.0, case_.exterior->tipDiameter(), "drum.centrefillDiameter", file);
        if (!case_.interior)
        {
            throw InputError(file, "flights.interior", "missing: a centrefill (drum.centrefillDiameter > 0) needs interior flights");
        }
    }
    if (case_.interior)
    {
        if (case_.interior->side() != FlightSide::interior)
        {
            throw InputError(file, "flights.interior", "the profile is not marked interior");
        }
        if (!(d.centrefillDiameter > 0))
        {
            throw InputError(file, "drum.centrefillDiameter", "interior flights need a centrefill diameter in (0, D_in)");
        }
        case_.interior->checkTipsAgainst(d.centrefillDiameter, "flights.interior.tipDiameter");
        if (!(case_.interior->tipDiameter() < case_.exterior->tipDiameter()))
        {
            std::ostringstream os;
            os << "interior tip diameter " << case_.interior->tipDiameter()
               << " m must be below the exterior tip diameter " << case_.exterior->tipDiameter() << " m";
            throw InputError(file, "flights.interior.tipDiameter", os.str());
        }
        in_.emplace(*case_.interior, m.repose);
    }
    requirePositive(m.particleDensity, "material.particleDensity", file);
    requireInRange(m.bulkDensity, 1e-9, m.particleDensity, "material.bulkDensity", file);
    requireInRange(m.sphericity, 1e-3, 1.0, "material.sphericity", file);
    if (m.sieveSizes.empty() || m.sieveSizes.size() != m.massFractions.size())
    {
        throw InputError(file, "material.sizes", "need one mass fraction per sieve size, at least one class");
    }
    double total = 0;
    for (std::size_t i = 0; i < m.sieveSizes.size(); ++i)
    {
        requirePositive(m.sieveSizes[i], "material.sizes[" + std::to_string(i) + "].diameter", file);
        requireInRange(m.massFractions[i], 0.0, 1e9, "material.sizes[" + std::to_string(i) + "].fraction", file);
        total += m.massFractions[i];
    }
    if (!(total > 0))
    {
        throw InputError(file, "material.sizes", "mass fractions sum to zero");
    }
    for (std::size_t i = 0; i < m.sieveSizes.size(); ++i)
    {
        xf_.push_back(m.massFractions[i]/total);
        dp_.push_back(m.sieveSizes[i]*m.sphericity);  // code: D_p = sieve size x sphericity
    }
    const auto& gas = case_.gas;
    requireInRange(gas.massRate, 0.0, 1e6, "gas.massRate [kg/s]", file);
    requireInRange(gas.temperatureC, -50.0, 1500.0, "gas.temperature [degC]", file);
    const particleDrag::Gas air = particleDrag::Gas::air(gas.temperatureC);
    gasDensity_ = air.density;
    drift_ = case_.options.drift ? case_.options.drift : std::make_shared<SherrittSheetDrift>(air);
    const bool counter = gas.direction == GasFlow::countercurrent && gas.massRate > 0;
    toSolids_ = counter ? -1.0 : 1.0;
    alphaGas_ = counter ? -d.slope : d.slope;  // docs/errata.md S12: alpha < 0 counter-current
    if (!case_.options.closure)
    {
        throw InputError(file, "model.closure", "no surface closure given");
    }
    requireInRange(case_.options.minDischargeAngle, 1*deg, 179*deg, "model.minDischargeAngle [rad]", file);
    requireInRange(case_.options.sweepStep, 0.01*deg, 10*deg, "model.sweepStep [rad]", file);
    if (case_.options.axialSteps < 4 || case_.options.axialSteps > 100000)
    {
        throw InputError(file, "model.axialSteps", "must be in [4, 100000]");
    }
    if (case_.options.imposedDenseFlow && !std::isfinite(*case_.options.imposedDenseFlow))
    {
        throw InputError(file, "model.imposedDenseFlow", "must be finite (kg/s)");
    }

    // Centrefill angles, Eqs 35, 36, 99, 100 (open drum: D_in = 0)
    const double r = case_.interior ? case_.interior->tipDiameter()/case_.exterior->tipDiameter() : 0.0;
    g_.thetaA = pi + std::acos(r);
    g_.thetaB = pi + std::acos(-r);
    g_.thetaC = std::acos(r);
    g_.thetaE = std::acos(-r);

    // Final discharge angle: where the exterior flight has shed everything
    finalAngle_ = 2*pi;
    const auto& nodes = ex_.nodes();
    for (std::size_t k = nodes.size(); k-- > 0;)
    {
        if (ex_.length(nodes[k]) > 0)
        {
            finalAngle_ = std::min(2*pi, nodes[std::min(k + 1, nodes.size() - 1)]);
            break;
        }
    }
    if (!(finalAngle_ > case_.options.minDischargeAngle + 2*deg))
    {
        throw InputError(file, "flights.exterior", "the flights hold nothing above the lowest discharge angle searched");
    }

    // Holdup table for inverting H(theta_i)
    const int n = static_cast<int>(std::ceil((finalAngle_ - minDischargeAngle())/deg));
    for (int k = 0; k <= n; ++k)
    {
        const double t = minDischargeAngle() + (finalAngle_ - minDischargeAngle())*k/n;
        Htheta_.push_back(t);
        Hvalue_.push_back(holdupAt(t));
    }
}


double TwoPhaseModel::exteriorFallHeight(double theta) const
{
    const double Do = case_.drum.shellDiameter;
    const double Dex = case_.exterior->tipDiameter();
    if (theta <= 0 || theta >= 2*pi)
    {
        return 0.0;
    }
    const double c = std::cos(theta);
    const double s = std::sin(theta);
    if (case_.interior && theta > pi)
    {
        const double Di = case_.drum.centrefillDiameter;
        const double Din = case_.interior->tipDiameter();
        const double x = std::abs(Dex*c);
        if (x < Di)
        {
            // over the centrefill wall: Eq 93 in the code's form (+ wall
            // height), or tip height minus wall-top height if asked
            const double wall = 0.5*Di*std::sin(std::acos(Dex*c/Di));
            const double tip = -0.5*Dex*s;
            return case_.options.geometricWallFall ? std::max(0.0, tip - wall) : tip + wall;
        }
        if (x < Din)
        {
            return -0.5*Dex*s;  // Eq 94: down to the centreline
        }
    }
    // Eq 92, applied by the code over the whole 0 < theta < 2 pi (docs/errata.md S5)
    return 0.5*Do*(std::sin(std::acos(Dex/Do*c)) - Dex/Do*s);
}


double TwoPhaseModel::interiorFallHeight(double psi) const
{
    const double Do = case_.drum.shellDiameter;
    const double Din = case_.interior ? case_.interior->tipDiameter() : 0.0;
    return 0.5*Do*(std::sin(std::acos(Din*std::cos(psi)/Do)) - Din/Do*std::sin(psi));  // Eq 96
}


double TwoPhaseModel::interiorAngle(double thetaI, bool& overfilled) const
{
    overfilled = false;
    if (!in_)
    {
        return pi;
    }
    const double lower = std::max(g_.thetaA, thetaI);  // code: theta_i > theta_a moves the limit
    if (lower >= g_.thetaB)
    {
        return pi;  // nothing reaches the centrefill flights
    }
    // Eq 44: int_psi_i^pi l_in^2 = N_ex/N_in int_lower^theta_b l_ex^2
    const double received = double(case_.exterior->count())/case_.interior->count()
        *ex_.integralL2(lower, g_.thetaB);
    const double volume = 0.5*received;
    if (volume > in_->holdupVolume(0.0))
    {
        overfilled = true;
        return 0.0;  // as the code: a full interior flight at psi = 0
    }
    return std::max(0.0, in_->initialDischargeAngle(volume));
}


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
    r.holdup_kg = s.holdup*rhoB*L;
    r.airborne_fraction = s.airborneHoldup/s.holdup;
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
        const auto [maxFeed, maxAt] = largestFeed(states);
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
        auto add = [&](const std::vector<double>& kk, double f)
        {
            std::vector<double> out(y);
            for (std::size_t j = 0; j < ny; ++j)
            {
                out[j] += f*kk[j];
            }
            return out;
        };
        const auto k2 = rhs(s + 0.5*h, add(k1, 0.5*h), nullptr);
        const auto k3 = rhs(s + 0.5*h, add(k2, 0.5*h), nullptr);
        const auto k4 = rhs(s + h, add(k3, h), nullptr);
        for (std::size_t j = 0; j < ny; ++j)
        {
            y[j] += h/6*(k1[j] + 2*k2[j] + 2*k3[j] + k4[j]);
        }
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
        const auto [maxFeed, maxAt] = largestFeed(drum1Grid());
        std::ostringstream os;
        os << "feed " << feedRate << " kg/s is beyond what the drum can carry: the bed slope is still held at"
           << " the cap phi = " << phi/deg << " deg at the feed end (Eqs 79, 135; capped over "
           << r.cappedLength << " of " << L << " m, feed-end theta_i " << eL.s.dischargeAngle/deg
           << " deg, chord " << eL.s.chord << " m). Without bed slope (DRUM1) the drum carries at most "
           << maxFeed << " kg/s (theta_i = " << maxAt/deg << " deg)";
        throw InputError(case_.name, "feedRate", os.str());
    }

    const double intH = y[1];
    r.holdup_kg = rhoB*intH;
    r.airborne_fraction = y[2]/intH;
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
