#include "drum/flights/polygonClip.hpp"

#include <cmath>

namespace drum
{

double polygonArea(const Polygon& polygon)
{
    const std::size_t n = polygon.size();
    if (n < 3)
    {
        return 0.0;
    }
    double twice = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const Eigen::Vector2d& a = polygon[i];
        const Eigen::Vector2d& b = polygon[(i + 1) % n];
        twice += a.x()*b.y() - b.x()*a.y();
    }
    return 0.5*std::abs(twice);
}

Polygon clipBelowLine
(
    const Polygon& polygon,
    const Eigen::Vector2d& through,
    double inclinationRad
)
{
    const Eigen::Vector2d dir(std::cos(inclinationRad), std::sin(inclinationRad));
    // Signed distance, positive below the line
    const auto side = [&](const Eigen::Vector2d& p)
    {
        const Eigen::Vector2d d = p - through;
        return d.x()*dir.y() - d.y()*dir.x();
    };

    Polygon out;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i)
    {
        const Eigen::Vector2d& a = polygon[i];
        const Eigen::Vector2d& b = polygon[(i + 1) % n];
        const double sa = side(a);
        const double sb = side(b);
        if (sa >= 0.0)
        {
            out.push_back(a);
        }
        if ((sa >= 0.0) != (sb >= 0.0))
        {
            const double t = sa/(sa - sb);
            out.push_back(a + t*(b - a));
        }
    }
    return out;
}

Polygon rotated(const Polygon& polygon, double angleRad)
{
    const double c = std::cos(angleRad);
    const double s = std::sin(angleRad);
    Polygon out;
    out.reserve(polygon.size());
    for (const auto& p : polygon)
    {
        out.emplace_back(c*p.x() - s*p.y(), s*p.x() + c*p.y());
    }
    return out;
}

} // namespace drum
