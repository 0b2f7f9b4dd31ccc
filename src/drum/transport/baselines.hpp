// Literature baselines for the mean residence time and RTD of flighted
// rotary drums (as reviewed in Sherritt 1991 §2.1, §2.5 and Lee 2008 Ch. 2).
// SI in and out unless stated; n is the drum speed in rev/s.
#ifndef DRUM_TRANSPORT_BASELINES_HPP
#define DRUM_TRANSPORT_BASELINES_HPP

namespace drum
{
namespace baselines
{

enum class GasFlow { coCurrent, counterCurrent };

//- Friedman & Marshall (1949), the form reproduced in Perry's handbook:
//  T[min] = 0.23 L/(S N^0.9 D) +- 0.6 B L G/F, B = 5 Dp^-0.5 (Dp in um,
//  L and D in ft, N in rpm, S slope in ft/ft, G and F gas and solids mass
//  fluxes in the same units); + countercurrent, - cocurrent. Sherritt 1991
//  Eq 3 and Lee 2008 Eqs 2.5-2.6 print converted variants whose constants
//  could not be checked against the originals; this is the original's structure.
//  Returns T in s.
double friedmanMarshall
(
    double length, double diameter, double slopeRad, double rpm,
    double gasMassFlux, double solidsMassFlux, double particleDiameter, GasFlow flow
);

//- Saeman & Mitchell (1954), Sherritt 1991 Eq 4:
//  T = L/(f(H) D n (tan(alpha) +- m V_g)); f(H) the cascade factor and m
//  the gas coefficient are fitted per drum (no universal values).
//  Sign: - for countercurrent (gas slows the solids). Returns s.
double saemanMitchell
(
    double length, double diameter, double n, double slopeRad,
    double cascadeFactor, double gasCoefficient, double gasVelocity, GasFlow flow
);

//- Matchett & Baker (1987) holdup, Lee 2008 Eq 2.10:
//  M_T = F L (2 n t_a + 1)/(2 n t_a (v_s + alpha D tan(theta)/(2 t_a)))
//  t_a fall time, v_s mean axial velocity of airborne solids, alpha the
//  dense-phase coefficient. Returns the mean residence time M_T/F in s.
double matchettBaker
(
    double length, double diameter, double n, double slopeRad,
    double fallTime, double airborneVelocity, double densePhaseCoefficient
);

//- Schofield & Glikin (1962), Lee 2008 Eq 2.9 / Sherritt 1991 Eqs 25-26:
//  residence time = L (cycle time)/(advance per cycle), advance in the fall
//  only: d = h sin(theta) +- K V^2 t_f^2/2 (+ cocurrent, - countercurrent),
//  t_f = sqrt(2h/g) (Sherritt Eq 19), cycle time = t_f + psi/(180 n) with
//  psi the mean discharge angle in degrees (Lee's printed form).
//  K = 3 C_D rho_g/(4 D_p rho_p) with Schiller-Naumann C_D (Lee Eq 2.13)
//  at the relative velocity V. Returns s; throws InputError when the
//  countercurrent drag stops the advance.
double schofieldGlikin
(
    double length, double slopeRad, double n, double fallHeight, double dischargeAngleDeg,
    double gasVelocity, GasFlow flow,
    double particleDiameter, double particleDensity, double gasDensity, double gasViscosity
);

//- Tanks in series, Lee 2008 Eq 2.11: E(t) = N^N/(Gamma(N) tau) x^{N-1} e^{-N x},
//  x = t/tau; mean tau, variance tau^2/N. N may be non-integer (>= 1).
double tanksInSeriesE(double t, double meanTime, double nTanks);

//- The N that matches a measured mean and SD: N = (mean/SD)^2
double tanksInSeriesN(double mean, double sd);

} // namespace baselines
} // namespace drum

#endif
