// Air properties as coded by Sherritt 1991 (ROUTINES.C, App. B) at 1 atm; an
// ideal gas at other pressures (density in proportion, viscosity unchanged)
#ifndef PARTICLEDRAG_GASPROPERTIES_HPP
#define PARTICLEDRAG_GASPROPERTIES_HPP

namespace particleDrag
{

//- Standard gravity used throughout (Sherritt's code: GRAVITY = 9.81)
constexpr double gravity = 9.81;

//- Standard atmosphere [kPa]: the pressure of Sherritt's air
constexpr double standardPressureKPa = 101.325;

//- The pressures [kPa] the tools accept for a gas (airProperties, windTunnelDrift,
//  the drum model, the curtain tools through dryerFacts)
constexpr double minPressureKPa = 10;
constexpr double maxPressureKPa = 1000;

//- The temperatures [degC] the tools accept for a gas (the same tools)
constexpr double minTemperatureC = -50;
constexpr double maxTemperatureC = 1500;

//- Air density [kg/m3]: rho = 354.3/(T_C + 273.15) at 1 atm, T_C in degC,
//  in proportion to the pressure p [kPa] (ideal gas)
double airDensity(double temperatureC, double pressureKPa = standardPressureKPa);

//- Air viscosity [Pa s], Sutherland form of airvisc():
//  mu = 2.4e-5 ((423.15 + 120)/(T_K + 120)) (T_K/423.15)^1.5
double airViscosity(double temperatureC);

//- A gas: density and dynamic viscosity
struct Gas
{
    double density = 1.2086;      //!< kg/m3 (air at 20 degC)
    double viscosity = 1.8194e-5; //!< Pa s  (air at 20 degC)

    //- Dry air at T degC and p kPa (p > 0)
    static Gas air(double temperatureC, double pressureKPa = standardPressureKPa);
};

} // namespace particleDrag

#endif
