// porousSheet: a reduced curtain model calibrated only against the CFD drift
// table (never against the wind-tunnel measurements).
//
// The curtain is a porous sheet of axial length L (the flight length) that
// the gas must cross along its length; the gas that does not push through
// escapes sideways. Its resistance against the gas' dynamic pressure is the
// curtain drag number
//     N = sigma K L / rho_g                                    [m]
//     sigma = S t_f / y = S sqrt(2/(g y))   mean solids mass per m^2 of sheet
//                                           (free fall, Sherritt Eq 19)
//     K = 3 Cd(Re at V_g) rho_g / (4 D_p rho_p)                (Sherritt Eq 14)
// i.e. the drag the sheet's solids would exert at full slip per unit sheet
// area, over rho_g V_g^2, times L. Like a screen with bypass (the gas speed
// through a screen of loss coefficient k is U/sqrt(1+k)), the in-curtain gas
// velocity is
//     V_c/V_g = (1 + a N)^-b
// with a [1/m] (an inverse effective sheet thickness: N a is the sheet's loss
// coefficient along L) and b fitted by least squares on ln(V_c/V_g) of the
// table (fitPorousSheet, library drumDriftFit; command windTunnelDrift -fit).
// The drift is then the shared core's lone-particle fall at V_c.
// Limits: dilute (S -> 0) V_c -> V_g, the isolated particle; dense (N >> 1/a)
// V_c/V_g ~ (aN)^-b -> 0, strong shielding.
// The shielding is a property of the whole curtain, so K is evaluated at the
// curtain's surface-mean (Sauter) diameter d32 = 1/sum(x_i/d_i) of its size
// distribution when one is given (curtainDiameter > 0), and at the query's
// class diameter otherwise; the drift of each class is its own lone-particle
// fall at the common V_c.
#ifndef DRUM_DRIFT_POROUSSHEETDRIFT_HPP
#define DRUM_DRIFT_POROUSSHEETDRIFT_HPP

#include "drum/drift/driftModel.hpp"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace drum
{

struct PorousSheetConstants
{
    double a = 0;   //!< 1/m
    double b = 0;   //!< -
    //- Provenance and fit statistics as read (key -> text)
    std::map<std::string, std::string> provenance;
};

//- Read the constants file (YAML: a_per_m, b, and provenance keys)
PorousSheetConstants readPorousSheetConstants(const std::filesystem::path& file);

//- Write it atomically (keys a_per_m, b, then provenance in order given)
void writePorousSheetConstants(const std::filesystem::path& file, const PorousSheetConstants& c);

//- Default place of the constants file in the project
std::filesystem::path defaultPorousSheetConstantsFile();

class PorousSheetDrift : public IsolatedParticleDrift
{
public:
    PorousSheetDrift(PorousSheetConstants c, particleDrag::Gas gas, particleDrag::DragLaw law = {},
                     double curtainDiameter = 0);

    //- Curtain drag number N [m] of the query
    double dragNumber(const DriftQuery& q) const;

    //- V_c/V_g = (1 + a N)^-b
    double velocityRatio(const DriftQuery& q) const;

    double displacement(const DriftQuery& q) const override;
    std::string name() const override { return "porousSheet"; }

    const PorousSheetConstants& constants() const { return c_; }

private:
    PorousSheetConstants c_;
    double curtainDiameter_;
};

//- Surface-mean diameter 1/sum(x_i/d_i) (fractions renormalised)
double sauterDiameter(const std::vector<double>& diameters, const std::vector<double>& fractions);

//- N of a query without constants (used by the fit)
double porousSheetDragNumber(const DriftQuery& q, const particleDrag::Gas& gas, const particleDrag::DragLaw& law);

} // namespace drum

#endif
