#include "drum/flights/angleOfRepose.hpp"
#include "drum/numerics/constants.hpp"

#include "drum/io/csv.hpp"
#include "drum/io/inputError.hpp"

#include <cmath>

namespace drum
{

namespace
{
} // namespace


double drumFroudeNumber(double drumRadius, double speedRpm, double gravity)
{
    const double omega = speedRpm*2.0*pi/60.0;
    return drumRadius*omega*omega/gravity;                 // Sherritt 1991 Eq 7
}


double sherrittThetaDeg(double tipAngleFromBottomDeg)
{
    return std::fmod(std::fmod(tipAngleFromBottomDeg + 90.0, 360.0) + 360.0, 360.0);
}


double schofieldGlikinAngleDeg(double mu, double froude, double thetaDeg)
{
    requireInRange(mu, 0.0, 1e3, "mu");
    requireInRange(froude, 0.0, 1.0, "froude");
    const double th = thetaDeg*deg;
    // Sherritt 1991 Eq 6 (Schofield & Glikin 1962)
    const double num = mu - froude*(std::cos(th) - mu*std::sin(th));
    const double den = 1.0 + froude*(mu*std::cos(th) + std::sin(th));
    return std::atan2(num, den)/deg;
}


double brittonMoistureAngleDeg(double w, const std::string& entry)
{
    const double wMax = (90.0 - 34.5)/1222.2;
    if (!(w >= 0.0 && w < wMax))
    {
        throw InputError("", entry, "moisture " + std::to_string(w)
            + " kg/kg outside the allowed range [0, " + std::to_string(wMax)
            + ") of Lee 2008 Eq 7.2 (phi below 90 deg)");
    }
    return 1222.2*w + 34.5;                                // Lee 2008 Eq 7.2
}


double moistureProfile(int i, int n, double wInlet, double wOutlet)
{
    requirePositive(wInlet, "wInlet");
    requirePositive(wOutlet, "wOutlet");
    if (n < 2 || i < 1 || i > n)
    {
        throw InputError("", "i", "slice index must be in [1, N] with N >= 2");
    }
    // Lee 2008 Eq 7.3
    return wInlet*std::exp(std::log(wOutlet/wInlet)*double(i - 1)/double(n - 1));
}


std::vector<LeeRigExperiment> readLeeRigExperiments(const std::filesystem::path& path)
{
    std::vector<LeeRigExperiment> out;
    requireReadableFile(path.string());
    try
    {
        io::CSVReader<12, io::trim_chars<' '>, io::double_quote_escape<',', '"'>> in(path.string());
        in.read_header(io::ignore_extra_column,
            "experiment", "repeat", "flight", "abrasive_tip_surface", "material",
            "speed_rpm_table5_4", "speed_rpm_table5_5", "dynamic_angle_mean_deg",
            "dynamic_angle_sd_deg", "particle_velocity_mean_m_s",
            "particle_velocity_sd_m_s", "note");
        LeeRigExperiment e;
        std::string abrasive, speed55, vMean, vSd, note;
        while (in.read_row(e.experiment, e.repeat, e.flight, abrasive, e.material,
                           e.speedRpm, speed55, e.phiMeanDeg, e.phiSdDeg, vMean, vSd, note))
        {
            e.abrasiveTip = abrasive == "yes";
            e.layerVelocityMean = vMean.empty() ? 0.0 : std::stod(vMean);
            e.layerVelocitySd = vSd.empty() ? 0.0 : std::stod(vSd);
            out.push_back(e);
        }
    }
    catch (const io::error::base& err)
    {
        throw InputError(path.string(), "", err.what());
    }
    return out;
}

} // namespace drum
