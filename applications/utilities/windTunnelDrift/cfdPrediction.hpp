// The `cfd` model of windTunnelDrift: one curtainCase run (H6b's curtainFoam
// driver) per test row with the row's conditions and the material's size
// classes, in a work folder; reads DIR/curtainResult.csv back.
#ifndef WINDTUNNELDRIFT_CFDPREDICTION_HPP
#define WINDTUNNELDRIFT_CFDPREDICTION_HPP

#include "scoring/windTunnelData.hpp"

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace windTunnelDrift
{

struct CfdOptions
{
    std::string level = "coarse";   //!< curtainCase -level
    int np = 1;                     //!< curtainCase -np
    int jobs = 1;                   //!< rows run at once (each a curtainCase process)
    std::string drag;               //!< curtainCase -drag (empty: its default)
    std::filesystem::path work;     //!< one sub-folder per test
    bool keep = false;              //!< keep the case folders
    bool skipFailed = false;        //!< a failed row is reported and left out (never written as a number)
    std::string command = "curtainCase";
    std::string particleTurbulence;  //!< curtainCase -particleTurbulence (empty: its default)
    std::string turbulentDispersion; //!< curtainCase -turbulentDispersion (empty: its default)
    std::string particleParticleDrag; //!< curtainCase -particleParticleDrag (empty: its default)
    std::string turbulence;          //!< curtainCase -turbulence (empty: the template's gas model)
    std::string wakeShare;           //!< curtainCase -wakeShare (empty: its default; checked there)
    std::string releaseVelocity;     //!< curtainCase -releaseVelocity (empty: the template's)
    //! curtainCase -sphericity, with -drag HaiderLevenspiel only (empty: spheres); the
    //! classes keep the materials file's diameters
    std::string sphericity;
    //! curtainCase -layerThickness: empty (the template's 0.05 m), a value in m, or "packed":
    //! per row the layer that carries the spill at the bulk density and the release velocity,
    //! b = S/(rho_b v), thickened where that would exceed a solids fraction of 0.5 at the slot
    //! (the pressureless solids cannot be released near packing)
    std::string layerThickness;
    std::optional<double> gasPressure;  //!< curtainCase -gasPressure, kPa (none: 1 atm, the template's air)
    //! how a row's advance is measured: "sherritt" (the tunnel's collection rule on the
    //! landing distribution, scoring/tunnelCollection.hpp) or "landed" (the mean
    //! drift of what crossed the floor plane; a class that never lands fails the row)
    std::string collection = "sherritt";
};

//- One row's answer: the bulk mean advance and each size class's advance
//  (in the order of the material's classes), measured as CfdOptions::collection says
struct CfdRow
{
    double advance = 0;
    std::vector<double> classAdvance;
};

//- Per test: the bulk mean advance, sum_i x_i a_i at the row's fall height,
//  and the classes' a_i. Progress goes to std::cout. A failed row throws,
//  or with skipFailed is left out of the map (its log and case folder are
//  kept under work).
std::map<int, CfdRow> cfdPredictions
(
    const std::vector<drum::WindTunnelTest>& tests,
    const std::map<std::string, drum::WindTunnelMaterial>& materials,
    const CfdOptions& options
);

//- Read one curtainLanding.csv: what the wind tunnel would have recorded at
//  fall height y (its collection rule), for the bulk and for each class c0,
//  c1, ... in the order of `fractions`
CfdRow readLandingAdvance
(
    const std::filesystem::path& file,
    double fallHeight,
    const std::vector<double>& fractions
);

//- Read one curtainResult.csv: the drift at fall height y of the classes
//  with the given diameters (matched by diameter) and their mass-weighted mean
CfdRow readCurtainResult
(
    const std::filesystem::path& file,
    double fallHeight,
    const std::vector<double>& diameters,
    const std::vector<double>& fractions
);

} // namespace windTunnelDrift

#endif
