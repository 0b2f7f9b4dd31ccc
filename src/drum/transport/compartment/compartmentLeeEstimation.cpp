#include "drum/transport/compartment/compartmentLeeEstimation.hpp"

#include "drum/io/inputError.hpp"
#include "drum/rtd/rtdSimulation.hpp"

#include <algorithm>

namespace drum
{

StagnantExchange stagnantFrom
(
    const StagnantExchange& base,
    const std::vector<std::string>& names,
    const std::vector<double>& v
)
{
    StagnantExchange z = base;
    for (std::size_t k = 0; k < names.size(); ++k)
    {
        if (names[k] == "stagnantRatio") z.massRatio = v[k];
        else if (names[k] == "exchangeTime") z.exchangeTime = v[k];
    }
    return z;
}

const std::vector<LeeEstimationParameter>& leeEstimationParameters()
{
    static const std::vector<LeeEstimationParameter> list = {
        {"kilnTime", "kilnTime", 0.01, 1e30},               // t_kiln, s
        {"backFraction", "backFraction", 0.0, 1.0},         // C_B
        {"dragFactor", "forwardDragFactor", 0.0, 100.0},    // C_F^G (Eq 3.8)
        {"forwardShare", "forwardShare", 0.0, 1.0},         // s of leeParametersFrom
        {"designLoadMultiplier", "designLoadMultiplier", 0.05, 20.0},
        {"stagnantRatio", "stagnantRatio", 0.0, 10.0},      // M_s/M_p
        {"exchangeTime", "exchangeTime", 1.0, 1e6},         // s
    };
    return list;
}


const LeeEstimationParameter& leeEstimationParameter(const std::string& entry, const std::string& where,
                                                     const std::string& file)
{
    std::string allowed;
    for (const auto& p : leeEstimationParameters())
    {
        if (p.entry == entry || p.name == entry) return p;
        allowed += (allowed.empty() ? "" : ", ") + p.entry;
    }
    throw InputError(file, where, "unknown parameter '" + entry + "'; allowed: " + allowed);
}


double leeMaxForwardFraction0(const LeeDryer& dryer, const int n)
{
    double cf0 = 0;
    for (const LeeSliceData& s : leeSliceData(dryer, n, {1.0, 0.0, 1.0}))
    {
        cf0 = std::max(cf0, s.slice.forwardFraction);   // C_F^0 (C_F^G = 1)
    }
    return cf0;
}

LeeParameters leeParametersFrom
(
    const LeeDryer& dryer,
    const int n,
    const LeeParameters& base,
    const std::vector<std::string>& names,
    const std::vector<double>& v,
    LeeDryer* modified
)
{
    LeeParameters p = base;
    double share = -1;
    for (std::size_t k = 0; k < names.size(); ++k)
    {
        if (names[k] == "kilnTime") p.kilnTime = v[k];
        else if (names[k] == "backFraction") p.backFraction = v[k];
        else if (names[k] == "dragFactor") p.dragFactor = v[k];
        else if (names[k] == "forwardShare") share = v[k];
        else if (names[k] == "designLoadMultiplier" && modified) modified->designLoadMultiplier = v[k];
    }
    if (share >= 0)
    {
        // C_F^G = s (1 - C_B)/max_i C_F^0_i: C_F + C_B <= 1 in every slice
        // for 0 <= s <= 1, so the box bounds carry the constraint
        p.dragFactor = share*(1.0 - p.backFraction)/leeMaxForwardFraction0(dryer, n);
    }
    return p;
}

PredictionModel leeRtdModel
(
    const LeeDryer& dryer,
    const int n,
    const LeeParameters& base,
    const std::vector<std::string>& names,
    const double pulse,
    const std::vector<double>& times,
    const StagnantExchange& stagnant,
    const RtdObjective& objective
)
{
    for (const std::string& nm : names)
    {
        leeEstimationParameter(nm, "estimation parameter " + nm);
    }
    return [=](const std::vector<double>& v)
    {
        LeeDryer d = dryer;
        const LeeParameters p = leeParametersFrom(dryer, n, base, names, v, &d);
        const CompartmentNetwork net = leeNetwork(d, n, p);
        const TracerSystem sys = net.tracerSystem(net.steadyState(), stagnantFrom(stagnant, names, v));
        std::vector<double> E = exactRtdAt(sys, pulse, times);
        for (double& e : E) e *= 3600.0;    // 1/h, as Lee's D.O.Normalised
        return transformForObjective(E, objective);
    };
}

} // namespace drum
