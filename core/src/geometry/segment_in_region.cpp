#include "segment_in_region.hpp"

#include <algorithm>
#include <cmath>

#include "polygon_2d.hpp"

namespace popup {

namespace {

double cross(const Vec2& a, const Vec2& b)
{
    return a.x() * b.y() - a.y() * b.x();
}

} // namespace

std::vector<std::pair<double, double>> segment_in_region(const Vec2& a, const Vec2& b,
                                                         const Loop2& outer,
                                                         const std::vector<Loop2>& holes,
                                                         double tol, double shortest)
{
    std::vector<std::pair<double, double>> out;
    const Vec2 d = b - a;
    const double length = d.norm();
    if (!(length > 0))
        return out;
    // Breakpoints: where the boundary crosses the segment, and boundary vertices on it (the ends
    // of edges running along it). Between two breakpoints the segment is all in or all out.
    std::vector<double> ts{0.0, 1.0};
    auto add_loop = [&](const Loop2& loop) {
        for (size_t i = 0, n = loop.size(); i < n; ++i) {
            const Vec2& q = loop[i];
            const Vec2 e = loop[(i + 1) % n] - q;
            const double t_vertex = (q - a).dot(d) / (length * length);
            if (t_vertex > 0 && t_vertex < 1 && std::abs(cross(d, q - a)) / length <= tol)
                ts.push_back(t_vertex);
            const double denom = cross(d, e);
            if (std::abs(denom) <= 1e-12 * length * e.norm())
                continue; // parallel: its ends are vertices, handled above
            const double t = cross(q - a, e) / denom, s = cross(q - a, d) / denom;
            if (t > 0 && t < 1 && s >= 0 && s <= 1)
                ts.push_back(t);
        }
    };
    add_loop(outer);
    for (const Loop2& hole : holes)
        add_loop(hole);
    std::sort(ts.begin(), ts.end());
    auto on_paper = [&](const Vec2& q) {
        if (!point_in_polygon_or_near(outer, q, tol))
            return false;
        for (const Loop2& hole : holes)
            if (point_in_polygon_or_near(hole, q, -tol))
                return false;
        return true;
    };
    for (size_t i = 0; i + 1 < ts.size(); ++i) {
        const double t0 = ts[i], t1 = ts[i + 1];
        if (t1 - t0 <= 0 || !on_paper(a + 0.5 * (t0 + t1) * d))
            continue;
        if (!out.empty() && std::abs(out.back().second - t0) * length <= tol)
            out.back().second = t1;
        else
            out.emplace_back(t0, t1);
    }
    out.erase(
        std::remove_if(out.begin(), out.end(),
                       [&](const auto& iv) { return (iv.second - iv.first) * length < shortest; }),
        out.end());
    return out;
}

} // namespace popup
