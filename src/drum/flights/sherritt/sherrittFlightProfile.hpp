// Sherritt 1991's flight description (§3.2, code `facelength`): a
// flight is a table of (rotation angle theta of the tip, length of the
// HORIZONTAL line from the tip back to the wall or to the flight itself).
//
// Angle convention (Sherritt 1991 nomenclature): theta is measured in the direction of
// rotation from the horizontal centreline; theta = 0 where the tip crosses
// the centreline moving down, so (0, pi) is the lower half and (pi, 2 pi) the
// upper half. An exterior flight discharges over theta_i <= theta <= 2 pi; an
// interior (centrefill) flight over psi_i <= psi <= pi (its "empty angle").
//
// The discharging surface lies at the kinetic angle of repose phi, so the
// surface length at rotation theta is the tabulated horizontal length at
// theta - phi (§3.2). Everything that depends on phi lives in
// SherrittFlightSurface (sherrittFlightSurface.hpp).
#ifndef DRUM_FLIGHTS_SHERRITTFLIGHTPROFILE_HPP
#define DRUM_FLIGHTS_SHERRITTFLIGHTPROFILE_HPP

#include <string>
#include <vector>

namespace drum
{

//- Where the flight sits: on the shell (exterior) or on the centrefill
enum class FlightSide
{
    exterior, //!< discharges theta_i..2 pi, tips on a locus of diameter D_ex
    interior  //!< centrefill flight: discharges psi_i..pi, tips on D_in
};

class SherrittFlightProfile
{
public:
    //- angles [rad]: strictly ascending, finite; lengths [m]: >= 0.
    //  tipDiameter: locus diameter of the tips (D_ex or D_in) [m] > 0;
    //  count: number of such flights round the drum (N_ex, N_in) >= 1;
    //  axialLength: axial length of one flight [m] > 0 (L of Eq 142);
    //  source: file (or other origin) named in error messages.
    //  Throws drum::InputError naming the offending entry.
    SherrittFlightProfile
    (
        std::vector<double> angles,
        std::vector<double> lengths,
        FlightSide side,
        double tipDiameter,
        int count,
        double axialLength,
        std::string source = ""
    );

    FlightSide side() const { return side_; }
    double tipDiameter() const { return tipDiameter_; }
    int count() const { return count_; }
    double axialLength() const { return axialLength_; }
    const std::vector<double>& angles() const { return angles_; }
    const std::vector<double>& lengths() const { return lengths_; }
    const std::string& source() const { return source_; }

    //- Angle by which the flight must be empty: 2 pi (exterior), pi (interior)
    double emptyAngle() const;

    //- Tabulated horizontal length at a rotation angle: piecewise-linear
    //  interpolation, linear extrapolation past the ends (as `interp()` in
    //  Sherritt's code, App. B). Not clamped: may be negative outside.
    double horizontalLength(double angle) const;

    //- Throw drum::InputError unless the tips lie strictly inside a wall of
    //  the given diameter (exterior flights: the shell; interior flights must
    //  lie outside the centrefill wall: tipDiameter > wallDiameter)
    void checkTipsAgainst(double wallDiameter, const std::string& entry) const;

private:
    std::vector<double> angles_;
    std::vector<double> lengths_;
    FlightSide side_;
    double tipDiameter_;
    int count_;
    double axialLength_;
    std::string source_;
};

} // namespace drum

#endif
