#include "drum/drift/driftModel.hpp"
#include "drum/drift/driftDictionary.hpp"
#include "drum/drift/driftTable.hpp"

#include "drum/io/inputError.hpp"
#include "particleDrag/loneParticleFall.hpp"
#include "particleDrag/sheetVelocity.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace drum
{

namespace
{
void check(const DriftQuery& q)
{
    requirePositive(q.particleDiameter, "drift query particle diameter");
    requirePositive(q.particleDensity, "drift query particle density");
    if (!(q.gasVelocity >= 0) || !std::isfinite(q.gasVelocity))
    {
        throw InputError("", "drift query gas velocity", "must be in [0, inf) m/s (+x is the gas direction)");
    }
    if (!(q.fallHeight >= 0) || !std::isfinite(q.fallHeight))
    {
        throw InputError("", "drift query fall height", "must be in [0, inf) m");
    }
}
} // namespace


IsolatedParticleDrift::IsolatedParticleDrift(particleDrag::Gas gas, particleDrag::DragLaw law)
:
    gas_(gas),
    law_(law)
{
    requirePositive(gas_.density, "gas density");
    requirePositive(gas_.viscosity, "gas viscosity");
}


double IsolatedParticleDrift::displacement(const DriftQuery& q) const
{
    check(q);
    const particleDrag::Particle p{q.particleDiameter, q.particleDensity};
    // Sherritt 1991 Eqs 13/16/17 with t = sqrt(2y/g) (Eq 19), V = V_g
    return particleDrag::loneParticleAdvance(law_, p, gas_, q.gasVelocity, q.fallHeight, q.incline);
}


double FullDragParticleDrift::displacement(const DriftQuery& q) const
{
    check(q);
    const particleDrag::Particle p{q.particleDiameter, q.particleDensity};
    particleDrag::FallIntegration o;
    o.constantK = false;      // Cd from the instantaneous slip
    o.verticalDrag = true;    // the fall slowed by drag (not Eq 19)
    return particleDrag::integrateFall(law_, p, gas_, q.gasVelocity, q.fallHeight, q.incline, o).advance;
}


double SherrittSheetDrift::displacement(const DriftQuery& q) const
{
    check(q);
    // Eq 142 (code exponents 0.763/0.857/0.437, capped at 1): V_c = C_V V_g
    const double cv = particleDrag::sherrittSheetVelocityRatio(q.fallHeight, q.spillRate, q.flightLength,
                                                               constants_);
    DriftQuery inSheet = q;
    inSheet.gasVelocity = cv*q.gasVelocity;
    return IsolatedParticleDrift::displacement(inSheet);
}


std::shared_ptr<const DriftModel> makeDriftModel
(
    const std::string& name,
    const particleDrag::Gas& gas,
    const particleDrag::DragLaw& law,
    const std::string& entry
)
{
    // Default table, policy and constants files (driftDictionary.hpp)
    DriftSettings settings;
    settings.model = name;
    return makeDriftModel(settings, gas, law, entry);
}


void DriftQueryRange::add(const DriftQuery& q)
{
    const std::array<double, 6> x{q.gasVelocity, q.spillRate, q.fallHeight, q.flightLength, q.particleDensity,
                                  q.particleDiameter};
    for (std::size_t a = 0; a < x.size(); ++a)
    {
        lo[a] = count ? std::min(lo[a], x[a]) : x[a];
        hi[a] = count ? std::max(hi[a], x[a]) : x[a];
    }
    ++count;
    if (std::isfinite(q.releaseAngleDeg) && std::isfinite(q.reposeAngleDeg))
    {
        const std::array<double, 2> y{q.releaseAngleDeg, q.reposeAngleDeg};
        for (std::size_t a = 0; a < y.size(); ++a)
        {
            angleLo[a] = angleCount ? std::min(angleLo[a], y[a]) : y[a];
            angleHi[a] = angleCount ? std::max(angleHi[a], y[a]) : y[a];
        }
        ++angleCount;
    }
}


double RecordingDrift::displacement(const DriftQuery& q) const
{
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        range_.add(q);
    }
    return inner_->displacement(q);
}


DriftQueryRange RecordingDrift::range() const
{
    const std::lock_guard<std::mutex> lock(mutex_);
    return range_;
}


std::string RecordingDrift::rangeCsv() const
{
    const DriftQueryRange r = range();
    std::ostringstream os;
    os << std::setprecision(10) << "axis,min,max,queries\n";
    for (int a = 0; a < 6; ++a)
    {
        os << driftAxisName(a) << ',' << r.lo[a] << ',' << r.hi[a] << ',' << r.count << '\n';
    }
    if (r.angleCount)
    {
        const char* names[2] = {"release_angle_deg", "repose_angle_deg"};
        for (int a = 0; a < 2; ++a)
        {
            os << names[a] << ',' << r.angleLo[a] << ',' << r.angleHi[a] << ',' << r.angleCount << '\n';
        }
    }
    return os.str();
}

} // namespace drum
