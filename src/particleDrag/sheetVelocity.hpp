// Sherritt 1991 Eq 142: the empirical gas velocity inside a falling curtain
#ifndef PARTICLEDRAG_SHEETVELOCITY_HPP
#define PARTICLEDRAG_SHEETVELOCITY_HPP

namespace particleDrag
{

//- The constants of Eq 142, C_V = k y^a (dm/dt)^-b L^-c: Sherritt's
//  regression with the code's exponents (sheetgasvel()) by default; other
//  values only to refit the correlation (out-of-sample scoring)
struct SheetVelocityConstants
{
    double k = 1.546;
    double a = 0.763;   //!< fall height exponent
    double b = 0.857;   //!< spill rate exponent
    double c = 0.437;   //!< flight length exponent
};

//- C_V = V_c/V_g = 1.546 y^0.763 (dm/dt)^-0.857 L^-0.437, capped at 1
//  (Eq 142 with the code's exponents, sheetgasvel()).
//  y: fall height [m], spill: spill rate [kg/(s m)], L: flight length [m].
//  Returns 1 when any input is <= 0, as the code does.
double sherrittSheetVelocityRatio
(
    double y,
    double spill,
    double L,
    const SheetVelocityConstants& constants = SheetVelocityConstants()
);

} // namespace particleDrag

#endif
