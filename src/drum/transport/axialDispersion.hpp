// Axial dispersion of a rolling/kilning bed: Sherritt (2001) design
// correlation D_z = k (n/n_c)^a (2R)^b d_p^c X^d (Eq 51, Table 3-3; the
// rolling/cascading set is Eq 84), with the bed regime from the relative
// speed n/n_c (Sherritt 2001 Eq 1) and the fitted range flagged.
// SI units: D_z m2/s, 2R and d_p in m, X volume fraction, n/n_c fraction.
#ifndef DRUM_TRANSPORT_AXIALDISPERSION_HPP
#define DRUM_TRANSPORT_AXIALDISPERSION_HPP

#include <string>
#include <vector>

namespace drum
{

enum class BedRegime
{
    slumping,          //!< n/n_c < 0.03
    rollingCascading,  //!< 0.03 <= n/n_c < 0.3
    cataracting,       //!< 0.3 <= n/n_c < 1
    centrifuging       //!< n >= n_c: no correlation
};

std::string bedRegimeName(BedRegime r);

//- Constants of Eq 51 (Table 3-3)
struct DispersionConstants
{
    double k, a, b, c, d;
};

//- Table 3-3 set of a regime (slumping, rolling/cascading, cataracting);
//  allModes: the "all modes, n/n_c < 1" set
DispersionConstants sherritt2001Constants(BedRegime regime);
DispersionConstants sherritt2001AllModes();

//- Critical (centrifuging) speed n_c = sqrt(g/R)/(2 pi) [rev/s], Eq 1
double criticalSpeed(double drumDiameter);

//- Regime from n/n_c with the thesis' bounds
BedRegime bedRegime(double speedRatio);

//- Fill fraction of a bed segment of central angle beta: (beta - sin beta)/(2 pi)
//  (Eq 16 with its missing 1/pi, docs/errata.md D1)
double segmentFillFraction(double beta);

struct AxialDispersionInput
{
    double drumDiameter = 0;     //!< 2R, m
    double speed = 0;            //!< n, rev/s
    double particleDiameter = 0; //!< d_p, m
    double fill = 0;             //!< X, volume fraction of the bed
    bool allModes = false;       //!< use the all-modes set instead of the regime's
};

struct AxialDispersionResult
{
    double Dz = 0;                 //!< m2/s
    double speedRatio = 0;         //!< n/n_c
    double fillUsed = 0;           //!< X after clamping to [0.03, ...)
    BedRegime regime = BedRegime::rollingCascading;
    std::vector<std::string> warnings;  //!< outside the fitted range (scatter x2 inside it)
};

//- D_z from Eq 51. Throws InputError for non-positive inputs or n >= n_c.
//  X below 0.03 is clamped to 0.03 (D_z ~ X^-0.55 diverges) and
//  every departure from the fitted range (n/n_c 0.03-0.3 for the rolling set,
//  X < 0.5, 2R 0.05-0.6 m, d_p 0.125-13 mm) is listed in warnings.
AxialDispersionResult sherritt2001AxialDispersion(const AxialDispersionInput& in, const std::string& file = "");

//- d_p for Eq 51 from a size distribution: the Sauter mean of the sieve
//  sizes times the sphericity (the drag diameters), m
double dispersionParticleDiameter
(
    const std::vector<double>& sieveSizes,
    const std::vector<double>& fractions,
    double sphericity
);

//- Fill fraction X of a bed of volume per drum length V' (m3/m): V'/(pi D^2/4)
double bedFillFraction(double bedVolumePerLength, double drumDiameter);

//- One-line description of an evaluation, "Sherritt 2001 Eq 51
//  (rolling/cascading, n/n_c 0.159, X 0.045, d_p 850 um): D_z ... m2/s"
std::string describeAxialDispersion(const AxialDispersionResult& r, const AxialDispersionInput& in);

} // namespace drum

#endif
