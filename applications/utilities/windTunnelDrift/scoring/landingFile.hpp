// The landing distribution curtainCase writes (curtainLanding.csv: per fall
// height and size class, the slot row with the release's mass centre, the
// bins along the flow with the fraction of the class's slot flux crossing
// that height in each and their mass centre, and the part lost by the
// outlet) read into the collection rule's classes (tunnelCollection.hpp).
// The one reader of that file in C++.
#ifndef DRUM_WINDTUNNEL_LANDINGFILE_HPP
#define DRUM_WINDTUNNEL_LANDINGFILE_HPP

#include "scoring/tunnelCollection.hpp"

#include <filesystem>
#include <map>
#include <vector>

namespace drum
{

//- Every fall height of the file (as printed) with its classes c0, c1, ...
//  in index order. InputError naming the file and the line for a malformed
//  row, and for a class index missing, or without a slot row or bins, at a
//  height.
std::map<double, std::vector<ClassLanding>> readLandingFile(const std::filesystem::path& file);

//- The classes at fall height y (matched to 1e-6 relative); InputError when
//  the file has no such height or not `classes` classes there
std::vector<ClassLanding> landingAt
(
    const std::map<double, std::vector<ClassLanding>>& landings,
    double fallHeight,
    std::size_t classes,
    const std::filesystem::path& file
);

} // namespace drum

#endif
