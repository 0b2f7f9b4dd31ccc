// windTunnelDrift -score: RMS ln(pred/measured), bias and share within +-25 %
// per model, per fall height and overall (drum::scorePredictions), as CSV
// and a predicted-against-measured PNG, of the mean advance or of the
// apparent in-sheet gas velocity.
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
    std::filesystem::path file;   //!< test,<quantity column>
};

//- What is scored: the mean advance (mean_advance_m) or Sherritt's apparent
//  in-sheet gas velocity (vc_m_s, Eq 141; tests without one are left out)
struct ScoredQuantity
{
    std::string column = "mean_advance_m";
    std::string label = "mean advance [m]";
    bool emptyIsUnmeasured = false;
};

//- The quantity a -quantity name means: advance or apparentVc; other
//  names are refused
ScoredQuantity scoredQuantity(const std::string& name);

//- Writes csv (model,fall_height_m,count,rms_ln,bias_ln,within25) with
//  fall_height_m "all" for the overall row, png if not empty (predicted
//  against measured of the models in `drawn`, every model if it is empty),
//  and byMaterial (model,material,count,rms_ln,bias_ln,within25) if not empty.
//  A prediction file that repeats a test, predicts a test the tests file does
//  not hold, or leaves out a measured test is refused naming the file, line and
//  test; allowMissing scores a model on the measured tests it predicts (its count
//  in the CSV) instead of refusing the ones it leaves out
void writeScores
(
    const std::filesystem::path& testsFile,
    const std::vector<NamedPredictions>& predictions,
    const std::filesystem::path& csv,
    const std::filesystem::path& png,
    const std::filesystem::path& byMaterial = {},
    const std::vector<std::string>& drawn = {},
    const ScoredQuantity& quantity = ScoredQuantity(),
    bool allowMissing = false
);

} // namespace windTunnelDrift

#endif
