// TwoPhaseModel: construction (checks of the case), centrefill angles,
// fall heights and the interior discharge angle. The holdups and flows are in
// twoPhaseHoldup.cpp, DRUM1 in twoPhaseConstantHoldup.cpp, DRUM3 in twoPhaseAxial.cpp.
#include "drum/transport/twoPhase/twoPhaseModel.hpp"

#include "drum/io/inputError.hpp"
#include "drum/numerics/constants.hpp"
#include "particleDrag/gasProperties.hpp"
#include "particleDrag/loneParticleFall.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

namespace drum
{

// The largest feed DRUM1 carries over a set of states, and its theta_i
// (0, 0 when none carries solids towards the discharge)
std::pair<double, double> largestCarriedFeed(const std::vector<TwoPhaseState>& states)
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
    // the dictionary's entries and ranges (drumSolver checks them first; this guards library callers)
    if (!(d.slope >= 0 && d.slope <= 20*deg*(1 + 1e-12)))
    {
        std::ostringstream os;
        os << "value " << d.slope/deg << " outside the allowed range [0, 20]";
        throw InputError(file, "drum.slope_deg", os.str());
    }
    if (!(d.speed > 0 && d.speed <= 1.0))
    {
        std::ostringstream os;
        os << "value " << 60*d.speed << " outside the allowed range (0, 60]";
        throw InputError(file, "drum.speed_rpm", os.str());
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
        throw InputError(file, "material.fractions_pct", "need one mass fraction per sieve size in material.sizes_um, at least one class");
    }
    double total = 0;
    for (std::size_t i = 0; i < m.sieveSizes.size(); ++i)
    {
        requirePositive(m.sieveSizes[i], "material.sizes_um[" + std::to_string(i) + "]", file);
        requireInRange(m.massFractions[i], 0.0, 1e9, "material.fractions_pct[" + std::to_string(i) + "]", file);
        total += m.massFractions[i];
    }
    if (!(total > 0))
    {
        throw InputError(file, "material.fractions_pct", "mass fractions sum to zero");
    }
    for (std::size_t i = 0; i < m.sieveSizes.size(); ++i)
    {
        xf_.push_back(m.massFractions[i]/total);
        dp_.push_back(m.sieveSizes[i]*m.sphericity);  // code: D_p = sieve size x sphericity
    }
    const auto& gas = case_.gas;
    requireInRange(gas.massRate, 0.0, 1e4, "gas.massRate", file);
    requireInRange(gas.temperatureC, particleDrag::minTemperatureC, particleDrag::maxTemperatureC,
                   "gas.temperature_C", file);
    requireInRange(gas.pressureKPa, particleDrag::minPressureKPa, particleDrag::maxPressureKPa, "gas.pressure_kPa", file);
    const particleDrag::Gas air = particleDrag::Gas::air(gas.temperatureC, gas.pressureKPa);
    gasDensity_ = air.density;
    drift_ = case_.options.drift ? case_.options.drift : std::make_shared<SherrittSheetDrift>(air);
    const bool counter = gas.direction == GasFlow::countercurrent && gas.massRate > 0;
    toSolids_ = counter ? -1.0 : 1.0;
    alphaGas_ = counter ? -d.slope : d.slope;  // docs/errata.md S12: alpha < 0 counter-current
    if (!case_.options.closure)
    {
        throw InputError(file, "TwoPhaseOptions::closure", "no surface closure given (a library option, not a drumDict entry)");
    }
    requireInRange(case_.options.minDischargeAngle, 1*deg, 179*deg, "TwoPhaseOptions::minDischargeAngle (rad; a library option, not a drumDict entry)", file);
    requireInRange(case_.options.sweepStep, 0.01*deg, 10*deg, "TwoPhaseOptions::sweepStep (rad; a library option, not a drumDict entry)", file);
    if (case_.options.axialSteps < 10 || case_.options.axialSteps > 100000)
    {
        throw InputError(file, "model.axialSteps", "must be in [10, 100000]");
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

} // namespace drum
