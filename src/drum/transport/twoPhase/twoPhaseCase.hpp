// Input of Sherritt's (1991) two-phase (airborne/dense) drum model: drum,
// flights, material with its size distribution, gas, and model choices.
//
// Frame: everything here is given in the SOLIDS frame: the slope is positive
// when the drum falls towards the solids discharge, flows are positive
// towards the discharge. The gas flows with (cocurrent) or against
// (countercurrent) the solids; internally the model maps this onto
// Sherritt's gas-direction frame (docs/errata.md S12).
#ifndef DRUM_TRANSPORT_TWOPHASECASE_HPP
#define DRUM_TRANSPORT_TWOPHASECASE_HPP

#include "drum/drift/driftModel.hpp"
#include "drum/numerics/constants.hpp"
#include "drum/flights/sherritt/sherrittFlightProfile.hpp"
#include "drum/transport/twoPhase/twoPhaseSurfaceClosure.hpp"
#include "particleDrag/gasProperties.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace drum
{

struct TwoPhaseDrum
{
    double shellDiameter = 0;      //!< D_o, m
    double length = 0;             //!< flighted length L, m
    double slope = 0;              //!< rad, down towards the solids discharge, [0, 20 deg]
    double speed = 0;              //!< rev/s, (0, 1]
    double centrefillDiameter = 0; //!< D_i, m (0: open drum)
};

struct TwoPhaseMaterial
{
    double particleDensity = 0;  //!< rho_p, kg/m3
    double bulkDensity = 0;      //!< rho_b, kg/m3
    double repose = 0;           //!< kinetic angle of repose phi, rad
    double sphericity = 1;       //!< D_p = sieve size x sphericity (code)
    std::vector<double> sieveSizes;     //!< m, one per size class
    std::vector<double> massFractions;  //!< x_f,i (renormalised to 1)
};

enum class GasFlow
{
    cocurrent,
    countercurrent
};

struct TwoPhaseGas
{
    double massRate = 0;        //!< kg/s (0: no gas)
    double temperatureC = 20;   //!< for Sherritt's air rho(T), mu(T)
    GasFlow direction = GasFlow::cocurrent;
    double pressureKPa = particleDrag::standardPressureKPa;   //!< rho in proportion (ideal gas)
};

struct TwoPhaseOptions
{
    //- Drift per fall; null: SherrittSheetDrift (Eq 142) in air at the
    //  gas temperature
    std::shared_ptr<const DriftModel> drift;

    //- Sloped-surface closure of the dense phase (Eqs 76-78, 80, 83, 84)
    SurfaceClosure closure = sherrittSurfaceClosure;

    //- Impose the dense-phase flow F_2 [kg/s] instead of Eq 79 (Kamke's
    //  wood chips, Fig 5.30)
    std::optional<double> imposedDenseFlow;

    //- Eq 93 as geometry says (tip height minus wall-top height) instead of
    //  the printed/coded plus sign (docs/errata.md S5)
    bool geometricWallFall = false;

    //- Lowest discharge angle searched (the code's DRUM1 sweep starts at 40 deg)
    double minDischargeAngle = 40*pi/180;

    //- Sweep step for root bracketing [rad]
    double sweepStep = pi/360;

    //- RK4 steps along the drum (axial solve)
    int axialSteps = 200;
};

struct TwoPhaseCase
{
    std::string name;
    TwoPhaseDrum drum;
    std::optional<SherrittFlightProfile> exterior;  //!< required
    std::optional<SherrittFlightProfile> interior;  //!< centrefill flights
    TwoPhaseMaterial material;
    TwoPhaseGas gas;
    TwoPhaseOptions options;
};

} // namespace drum

#endif
