#include "polygon_2d.hpp"

#include <algorithm>
#include <limits>

namespace popup {

double distance_to_segment(const Vec2& q, const Vec2& a, const Vec2& b)
{
    const Vec2 ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((q - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (a + t * ab - q).norm();
}

double distance_to_boundary(const Loop2& polygon, const Vec2& q)
{
    double d = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < polygon.size(); ++i)
        d = std::min(d, distance_to_segment(q, polygon[i], polygon[(i + 1) % polygon.size()]));
    return d;
}

bool point_in_polygon(const Loop2& polygon, const Vec2& q)
{
    bool inside = false;
    for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Vec2& a = polygon[i];
        const Vec2& b = polygon[j];
        if ((a.y() > q.y()) != (b.y() > q.y()) &&
            q.x() < (b.x() - a.x()) * (q.y() - a.y()) / (b.y() - a.y()) + a.x())
            inside = !inside;
    }
    return inside;
}

bool point_in_polygon_or_near(const Loop2& polygon, const Vec2& q, double tol)
{
    const bool inside = point_in_polygon(polygon, q);
    if (tol >= 0.0)
        return inside || distance_to_boundary(polygon, q) <= tol;
    return inside && distance_to_boundary(polygon, q) > -tol;
}

} // namespace popup
