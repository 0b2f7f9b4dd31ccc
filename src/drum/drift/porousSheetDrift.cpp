#include "drum/drift/porousSheetDrift.hpp"

#include "drum/io/atomicFile.hpp"
#include "drum/io/inputError.hpp"
#include "drum/io/yamlInput.hpp"
#include "drum/io/projectPaths.hpp"
#include "particleDrag/loneParticleFall.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <limits>
#include <sstream>


namespace drum
{

std::filesystem::path defaultPorousSheetConstantsFile()
{
    return defaultsDir()/"driftModels"/"porousSheet.yaml";
}


PorousSheetConstants readPorousSheetConstants(const std::filesystem::path& file)
{
    const std::string f = file.string();
    if (!std::filesystem::exists(file))
    {
        throw InputError(f, "", "porousSheet constants not found: fit them to a drift table with "
            "'windTunnelDrift -fit porousSheet -table TABLE.csv -out " + f + "'");
    }
    const YAML::Node n = loadYamlFile(f);
    if (!n.IsMap() || !n["model"] || n["model"].as<std::string>() != "porousSheet")
    {
        throw InputError(f, "model", "not a porousSheet constants file (needs 'model: porousSheet')");
    }
    PorousSheetConstants c;
    for (const char* key : {"a_per_m", "b"})
    {
        if (!n[key]) throw InputError(f, key, "missing");
        double v;
        try { v = n[key].as<double>(); }
        catch (const YAML::Exception&) { throw InputError(f, key, "not a number"); }
        if (!(v > 0) || !std::isfinite(v)) throw InputError(f, key, "must be in (0, inf)");
        (std::string(key) == "b" ? c.b : c.a) = v;
    }
    for (const auto& kv : n)
    {
        const std::string k = kv.first.as<std::string>();
        if (k != "a_per_m" && k != "b" && kv.second.IsScalar()) c.provenance[k] = kv.second.as<std::string>();
    }
    return c;
}


void writePorousSheetConstants(const std::filesystem::path& file, const PorousSheetConstants& c)
{
    std::ostringstream os;
    os << "# porousSheet reduced curtain model: V_c/V_g = (1 + a N)^-b,\n"
       << "# N = sigma K L / rho_g (src/drum/drift/porousSheetDrift.hpp). Fitted to the CFD\n"
       << "# drift table only, never to the wind-tunnel measurements. Regenerate with the\n"
       << "# command under 'command'.\n";
    YAML::Emitter e;
    e << YAML::BeginMap;
    e << YAML::Key << "model" << YAML::Value << "porousSheet";
    e << YAML::Key << "a_per_m" << YAML::Value << YAML::Precision(10) << c.a;
    e << YAML::Key << "b" << YAML::Value << YAML::Precision(10) << c.b;
    for (const auto& kv : c.provenance)
    {
        if (kv.first == "model") continue;
        e << YAML::Key << kv.first << YAML::Value << kv.second;
    }
    e << YAML::EndMap;
    os << e.c_str() << "\n";
    if (!file.parent_path().empty()) std::filesystem::create_directories(file.parent_path());
    writeFileAtomically(file, os.str());
}


double porousSheetDragNumber(const DriftQuery& q, const particleDrag::Gas& gas, const particleDrag::DragLaw& law)
{
    if (!(q.spillRate > 0) || !(q.gasVelocity > 0) || !(q.flightLength > 0))
    {
        return 0;   // no curtain, no gas or no length: nothing shields
    }
    if (!(q.fallHeight > 0))
    {
        return std::numeric_limits<double>::infinity();
    }
    const double sigma = q.spillRate*std::sqrt(2/(particleDrag::gravity*q.fallHeight));  // S t_f / y, Eq 19
    const double K = particleDrag::dragParameter(law, {q.particleDiameter, q.particleDensity}, gas, q.gasVelocity);  // Eq 14
    return sigma*K*q.flightLength/gas.density;
}


PorousSheetDrift::PorousSheetDrift(PorousSheetConstants c, particleDrag::Gas gas, particleDrag::DragLaw law,
                                   double curtainDiameter)
:
    IsolatedParticleDrift(gas, law),
    c_(std::move(c)),
    curtainDiameter_(curtainDiameter)
{
    if (!(curtainDiameter_ >= 0)) throw InputError("", "porousSheet curtain diameter", "must be >= 0 m");
    requirePositive(c_.a, "porousSheet a_per_m");
    requirePositive(c_.b, "porousSheet b");
}


double PorousSheetDrift::dragNumber(const DriftQuery& q) const
{
    DriftQuery curtain = q;
    if (curtainDiameter_ > 0) curtain.particleDiameter = curtainDiameter_;
    return porousSheetDragNumber(curtain, gas_, law_);
}


double sauterDiameter(const std::vector<double>& d, const std::vector<double>& x)
{
    if (d.size() != x.size() || d.empty()) throw InputError("", "size classes", "need one fraction per diameter");
    double sx = 0, s = 0;
    for (std::size_t i = 0; i < d.size(); ++i)
    {
        requirePositive(d[i], "size class diameter");
        if (!(x[i] >= 0)) throw InputError("", "size class fraction", "must be >= 0");
        sx += x[i];
        s += x[i]/d[i];
    }
    if (!(sx > 0)) throw InputError("", "size class fraction", "must not all be zero");
    return sx/s;
}


double PorousSheetDrift::velocityRatio(const DriftQuery& q) const
{
    return std::pow(1 + c_.a*dragNumber(q), -c_.b);
}


double PorousSheetDrift::displacement(const DriftQuery& q) const
{
    if (q.gasVelocity == 0 || q.fallHeight == 0)
    {
        return IsolatedParticleDrift::displacement(q);
    }
    DriftQuery inCurtain = q;
    inCurtain.gasVelocity = velocityRatio(q)*q.gasVelocity;
    return IsolatedParticleDrift::displacement(inCurtain);
}

} // namespace drum
