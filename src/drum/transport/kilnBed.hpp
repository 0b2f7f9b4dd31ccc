// The rolling bed of a drum's kilning (dense) phase as Saeman (1951) and
// Sherritt (1991 §2.4.3, Eqs 21-23) give it: a bed filling the drum section
// to the fill angle beta rolls at the kinetic angle of repose phi, and every
// pass across its surface chord advances a particle by the drum slope alpha
// and the bed's own axial slope gamma. Its flow
//   F_2 = pi n D^3 rho_b/6 [(alpha + gamma cos phi)/sin phi] sin^3(beta/2)   (Eq 22)
// with the chord D sin(beta/2) (Eq 23), the cube of which Eq 64 generalises
// to the beds inside flights. The sliding time is neglected (Sherritt: small
// at dryer Froude numbers). Bed area A = D^2/8 (beta - sin beta) (a circular
// segment); the flow is largest at half fill (beta = pi).
#ifndef DRUM_TRANSPORT_KILNBED_HPP
#define DRUM_TRANSPORT_KILNBED_HPP

namespace drum
{

struct SaemanKiln
{
    double drumDiameter = 0;    //!< D, m
    double speed = 0;           //!< n, rev/s
    double bulkDensity = 0;     //!< rho_b, kg/m3
    double drumSlope = 0;       //!< alpha, rad (towards the discharge)
    double bedSlope = 0;        //!< gamma, rad: the bed surface's own axial fall (0: level bed)
    double repose = 0;          //!< phi, rad (kinetic angle of repose)
};

//- The factor pi n D^3 rho_b/6 (alpha + gamma cos phi)/sin phi of Eq 22: the
//  flow at half fill, kg/s. InputError for a bed that does not advance.
double saemanFlowScale(const SaemanKiln& k);

//- Eq 22 at fill angle beta in [0, pi], kg/s
double saemanBedFlow(const SaemanKiln& k, double fillAngle);

//- Circular-segment area D^2/8 (beta - sin beta), m2, and its inverse
double bedArea(double drumDiameter, double fillAngle);
double fillAngle(double drumDiameter, double area);

//- Kiln mass of a slice of length dz that carries `flow` (Eq 22 inverted);
//  InputError when the flow exceeds the half-full bed's
double saemanKilnMass(const SaemanKiln& k, double sliceLength, double flow);

//- Kilning flow of a slice of length dz holding kilnMass in its bed (Eq 22);
//  beyond half fill the half-full bed's flow
double saemanKilnFlow(const SaemanKiln& k, double sliceLength, double kilnMass);

} // namespace drum

#endif
