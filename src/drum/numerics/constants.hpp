// Mathematical constants of the drum library, in one place.
#ifndef DRUM_NUMERICS_CONSTANTS_HPP
#define DRUM_NUMERICS_CONSTANTS_HPP

namespace drum
{

constexpr double pi = 3.14159265358979323846;
constexpr double deg = pi/180.0;    //!< one degree in radians

} // namespace drum

#endif
