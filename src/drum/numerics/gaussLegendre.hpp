// Composite Gauss-Legendre quadrature, the one both the flight unloading
// (10 points) and the two-phase holdup integrals (4 points) use. The
// integration range is cut at given break points (kinks of the integrand)
// and each piece split into panels, either a fixed number per piece or
// none wider than a maximum width.
#ifndef DRUM_NUMERICS_GAUSSLEGENDRE_HPP
#define DRUM_NUMERICS_GAUSSLEGENDRE_HPP

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace drum
{

//- Positive nodes and their weights of the N-point rule on [-1, 1]
template<int N> struct GaussLegendreRule;

template<> struct GaussLegendreRule<4>
{
    static constexpr std::array<double, 2> x{0.3399810435848563, 0.8611363115940526};
    static constexpr std::array<double, 2> w{0.6521451548625461, 0.3478548451374538};
};

template<> struct GaussLegendreRule<10>
{
    static constexpr std::array<double, 5> x{0.1488743389816312, 0.4333953941292472,
        0.6794095682990244, 0.8650633666889845, 0.9739065285171717};
    static constexpr std::array<double, 5> w{0.2955242247147529, 0.2692667193099963,
        0.2190863625159820, 0.1494513491505806, 0.0666713443086881};
};

//- How each piece between break points is split into panels
struct PanelSplit
{
    int pieces = 0;         //!< > 0: this many equal panels per piece
    double maxWidth = 0;    //!< else: the fewest equal panels no wider than this
};

//- scale * integral of f over [a, b]: the N-point rule on every panel of
//  every piece between a, the break points inside (a, b), and b. Each
//  node pair adds w (f(m - h x/2) + f(m + h x/2)) h/2 scale.
template<int N, class F>
double compositeGaussLegendre
(
    const F& f,
    double a,
    double b,
    std::vector<double> breaks,
    PanelSplit split,
    double scale = 1.0
)
{
    using Rule = GaussLegendreRule<N>;
    if (!(b > a))
    {
        return 0.0;
    }
    std::vector<double> cuts{a};
    std::sort(breaks.begin(), breaks.end());
    for (const double p : breaks)
    {
        if (p > cuts.back() && p < b) cuts.push_back(p);
    }
    cuts.push_back(b);
    double sum = 0.0;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
    {
        const double lo = cuts[k];
        const double width = cuts[k + 1] - lo;
        const int n = split.pieces > 0 ? split.pieces
            : std::max(1, static_cast<int>(std::ceil(width/split.maxWidth)));
        const double h = width/n;
        for (int i = 0; i < n; ++i)
        {
            const double mid = lo + (i + 0.5)*h;
            for (std::size_t j = 0; j < Rule::x.size(); ++j)
            {
                sum += Rule::w[j]*(f(mid - 0.5*h*Rule::x[j]) + f(mid + 0.5*h*Rule::x[j]))*0.5*h*scale;
            }
        }
    }
    return sum;
}

} // namespace drum

#endif
