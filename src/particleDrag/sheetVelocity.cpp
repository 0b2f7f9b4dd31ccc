#include "particleDrag/sheetVelocity.hpp"

#include <algorithm>
#include <cmath>

namespace particleDrag
{

double sherrittSheetVelocityRatio(double y, double spill, double L, const SheetVelocityConstants& e)
{
    // Sherritt 1991 Eq 142, code exponents and cap (sheetgasvel())
    if (y <= 0 || spill <= 0 || L <= 0)
    {
        return 1.0;
    }
    const double ratio =
        e.k*std::pow(y, e.a)/std::pow(spill, e.b)/std::pow(L, e.c);
    return std::min(1.0, ratio);
}

} // namespace particleDrag
