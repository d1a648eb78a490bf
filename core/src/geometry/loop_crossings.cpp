// A CGAL translation unit: no OCCT headers here (their Handle macro breaks CGAL).
#include "loop_crossings.hpp"

#include <iterator>
#include <map>

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Sweep_line_2_algorithms.h>
#include <CGAL/version_macros.h>

namespace popup {

namespace {
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Segment = CGAL::Arr_segment_traits_2<Kernel>::Curve_2;
using Point = Kernel::Point_2;

bool any_curves_meet(const std::vector<Segment>& edges)
{
#if CGAL_VERSION_MAJOR > 6 || (CGAL_VERSION_MAJOR == 6 && CGAL_VERSION_MINOR >= 2)
    // CGAL 6.2 (Debian sid) deprecates do_curves_intersect for this, its own body.
    return CGAL::Surface_sweep_2::do_intersect(edges.begin(), edges.end(), false);
#else
    return CGAL::do_curves_intersect(edges.begin(), edges.end());
#endif
}
} // namespace

std::optional<Vec2> first_loop_crossing(const std::vector<Loop2>& loops)
{
    std::vector<Segment> edges;
    for (const Loop2& loop : loops) // exact numbers cannot hold inf or NaN (GMP would trap)
        for (const Vec2& p : loop)
            if (!p.allFinite())
                return p;
    for (const Loop2& loop : loops)
        for (size_t i = 0; i < loop.size(); ++i) {
            const Vec2& a = loop[i];
            const Vec2& b = loop[(i + 1) % loop.size()];
            if (a != b)
                edges.emplace_back(Point(a.x(), a.y()), Point(b.x(), b.y()));
        }
    // Edges of a simple loop meet only at their shared ends, never in an edge's interior.
    if (!any_curves_meet(edges))
        return std::nullopt;
    // Where: a meeting point that is no loop vertex, or a vertex more than two edges end at.
    std::map<Point, int> ends;
    for (const Segment& e : edges) {
        ++ends[e.source()];
        ++ends[e.target()];
    }
    std::vector<Point> meets;
    CGAL::compute_intersection_points(edges.begin(), edges.end(), std::back_inserter(meets));
    for (const Point& p : meets) {
        const auto at = ends.find(p);
        if (at == ends.end() || at->second > 2)
            return Vec2(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
    }
    const Point& p = meets.empty() ? edges.front().source() : meets.front();
    return Vec2(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
}

} // namespace popup
