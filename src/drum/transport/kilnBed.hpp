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
    //- gamma from the bed depths instead: (h_i - h_{i+1})/dz with the next slice's
    //  bed (none past the discharge end, which holds no dam); bedSlope is then unused
    bool slopeFromProfile = false;
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

//- Depth of a bed of fill angle beta at the drum's lowest line, D/2 (1 - cos(beta/2))
double bedDepth(double drumDiameter, double fillAngle);

//- With slopeFromProfile: the kiln mass of a slice of length dz carrying
//  `flow` when the next slice's bed is nextDepth deep (gamma = (h - h_next)/dz;
//  Eq 22 with that gamma is monotone in the fill); InputError when even a
//  half-full bed cannot carry it
double saemanKilnMass(const SaemanKiln& k, double sliceLength, double flow, double nextDepth);

//- With slopeFromProfile: Eq 22 for the slice's bed and the next slice's depth
//  (0 when the bed would run backwards)
double saemanKilnFlow(const SaemanKiln& k, double sliceLength, double kilnMass, double nextDepth);

} // namespace drum

#endif
