// Sherritt 1991 Eq 142: the empirical gas velocity inside a falling curtain
#ifndef PARTICLEDRAG_SHEETVELOCITY_HPP
#define PARTICLEDRAG_SHEETVELOCITY_HPP

namespace particleDrag
{

//- C_V = V_c/V_g = 1.546 y^0.763 (dm/dt)^-0.857 L^-0.437, capped at 1
//  (Eq 142 with the code's exponents, sheetgasvel()).
//  y: fall height [m], spill: spill rate [kg/(s m)], L: flight length [m].
//  Returns 1 when any input is <= 0, as the code does.
double sherrittSheetVelocityRatio(double y, double spill, double L);

} // namespace particleDrag

#endif
