// windTunnelDrift -score: RMS ln(pred/measured), bias and share within +-25 %
// per model, per fall height and overall (drum::scorePredictions), as CSV
// and a predicted-against-measured PNG.
#ifndef WINDTUNNELDRIFT_DRIFTSCORES_HPP
#define WINDTUNNELDRIFT_DRIFTSCORES_HPP

#include <filesystem>
#include <string>
#include <vector>

namespace windTunnelDrift
{

struct NamedPredictions
{
    std::string model;
    std::filesystem::path file;   //!< test,mean_advance_m
};

//- Writes csv (model,fall_height_m,count,rms_ln,bias_ln,within25) with
//  fall_height_m "all" for the overall row, png if not empty (predicted
//  against measured of the models in `drawn`, every model if it is empty),
//  and byMaterial (model,material,count,rms_ln,bias_ln,within25) if not empty
void writeScores
(
    const std::filesystem::path& testsFile,
    const std::vector<NamedPredictions>& predictions,
    const std::filesystem::path& csv,
    const std::filesystem::path& png,
    const std::filesystem::path& byMaterial = {},
    const std::vector<std::string>& drawn = {}
);

} // namespace windTunnelDrift

#endif
