#pragma once
// Convex hulls of integer points (Andrew's monotone chain).
#include <algorithm>

#include "../../geometry/clipper_paths.hpp"

namespace popup::nest_detail {

/// The hull of the points, counter-clockwise, without collinear points.
inline ClipperLib::Path convex_hull(ClipperLib::Path points)
{
    using ClipperLib::IntPoint;
    std::sort(points.begin(), points.end(), [](const IntPoint& a, const IntPoint& b) {
        return a.X < b.X || (a.X == b.X && a.Y < b.Y);
    });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3)
        return points;
    // Differences of coordinates are exact in double; a product's rounding only matters for
    // points within a far fraction of a unit from a hull edge.
    const auto turns_left = [](const IntPoint& o, const IntPoint& a, const IntPoint& b) {
        return static_cast<double>(a.X - o.X) * static_cast<double>(b.Y - o.Y) -
                   static_cast<double>(a.Y - o.Y) * static_cast<double>(b.X - o.X) >
               0.0;
    };
    ClipperLib::Path hull(2 * points.size());
    std::size_t size = 0;
    for (std::size_t i = 0; i < points.size(); ++i) { // lower chain
        while (size >= 2 && !turns_left(hull[size - 2], hull[size - 1], points[i]))
            --size;
        hull[size++] = points[i];
    }
    const std::size_t lower_size = size + 1;
    for (std::size_t i = points.size() - 1; i-- > 0;) { // upper chain
        while (size >= lower_size && !turns_left(hull[size - 2], hull[size - 1], points[i]))
            --size;
        hull[size++] = points[i];
    }
    hull.resize(size - 1); // the last point repeats the first
    return hull;
}

} // namespace popup::nest_detail
