// Sherritt's apparent in-sheet gas velocity V_c (1991 section 4.3.1, Eq 141):
// the gas velocity at which the lone-particle advance (Eq 17: Cd at the full
// slip, drag-free fall time, Eq 19) best fits a test's class advances in the
// least-squares sense, each class weighted by its feed mass fraction and the
// two smallest classes left out:
//     sum_i x_i (delta_i - delta_i(V_c))^2 = minimum                  (Eq 141)
// The tunnel's V_c (data/windtunnel_tests.csv, vc_m_s) is this fit to the
// measured class advances, in the air of his code (20 degC, 1 atm); applied
// to a model's class advances in that air it gives the model's V_c measured
// the same way, whatever air the model itself breathed.
#ifndef DRUM_WINDTUNNEL_APPARENTSHEETVELOCITY_HPP
#define DRUM_WINDTUNNEL_APPARENTSHEETVELOCITY_HPP

#include "particleDrag/gasProperties.hpp"
#include "scoring/windTunnelData.hpp"

#include <vector>

namespace drum
{

//- Where Eq 141 may put V_c, as multiples of V_g (the tunnel's V_c/V_g span
//  0.21-1.66; a fit on a bound is refused)
struct ApparentVcBounds
{
    double lowest = 1e-3;
    double highest = 4.0;
};

//- Eq 141 on the advances classAdvance[i] [m] of m.classes[i] in test t
//  (gas `air`, Sherritt's drag law). Throws InputError if the material has
//  fewer than three classes, an advance is not finite, or the best V_c lies
//  on a bound of `bounds`.
double apparentSheetVelocity
(
    const WindTunnelTest& t,
    const WindTunnelMaterial& m,
    const std::vector<double>& classAdvance,
    const particleDrag::Gas& air,
    const ApparentVcBounds& bounds = ApparentVcBounds()
);

} // namespace drum

#endif
