#include "fold_bridges.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "../geometry/clipper_paths.hpp"

namespace popup::fold_bridges {

namespace {

/// One fold, glued joint or slit of the patch, in the profile frame.
struct Edge {
    Vec2 from, to;
    bool glued = false; ///< a glued joint: its bridge carries a tab's depth along it
};

std::vector<Edge> edges_of(const Scaffold& s, int patch, const ProfileFrame& frame)
{
    std::vector<Edge> out;
    for (const Hinge& h : s.hinges)
        if (h.patch_a == patch || h.patch_b == patch)
            out.push_back({frame.to_frame(h.from), frame.to_frame(h.to), h.kind == JointKind::tab});
    for (const Slit& sl : s.slits)
        if (sl.patch_cut == patch)
            out.push_back({frame.to_frame(sl.from), frame.to_frame(sl.to), false});
    return out;
}

/// Length of segment [a, b] along which `shape` has area within a micrometre of it (either
/// side): the sum of the stretches it meets.
double length_met(const ClipperLib::Paths& shape, const Vec2& a, const Vec2& b)
{
    using namespace ClipperLib;
    const Vec2 along = (b - a).normalized();
    const Vec2 across(-along.y(), along.x());
    const double thin = 1e-3;
    const Path band =
        to_path({a - thin * across, b - thin * across, b + thin * across, a + thin * across});
    Paths met;
    Clipper c;
    c.AddPaths(shape, ptSubject, true);
    c.AddPath(band, ptClip, true);
    c.Execute(ctIntersection, met, pftNonZero, pftNonZero);
    double total = 0;
    for (const Path& piece : met) {
        if (!(std::abs(path_area(piece)) > 0))
            continue;
        double lo = 1e300, hi = -1e300;
        for (const IntPoint& p : piece) {
            const double t = (to_vec2(p) - a).dot(along);
            lo = std::min(lo, t);
            hi = std::max(hi, t);
        }
        total += hi - lo;
    }
    return total;
}

/// The point of segment [a, b] nearest to `x`.
Vec2 nearest_on(const Vec2& a, const Vec2& b, const Vec2& x)
{
    const Vec2 d = b - a;
    const double t =
        d.squaredNorm() > 0 ? std::clamp((x - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    return a + t * d;
}

/// The nearest pair of points between segment [a, b] (first) and the boundary of `shape`
/// (second); of pairs as near within a micrometre, the one nearest the segment's middle (a
/// bridge over a uniform gap stands in the middle). Between two segments that do not cross, the
/// nearest pair has an end of one of them.
std::pair<Vec2, Vec2> nearest_pair(const Vec2& a, const Vec2& b, const ClipperLib::Paths& shape)
{
    std::pair<Vec2, Vec2> best{a, a};
    double best_d = 1e300;
    const Vec2 middle = 0.5 * (a + b);
    auto consider = [&](const Vec2& on_fold, const Vec2& on_shape) {
        const double d = (on_fold - on_shape).norm();
        const bool as_near = std::abs(d - best_d) <= 1e-3;
        if ((d < best_d && !as_near) ||
            (as_near && (on_fold - middle).norm() < (best.first - middle).norm())) {
            best_d = d;
            best = {on_fold, on_shape};
        }
    };
    for (const ClipperLib::Path& path : shape)
        for (size_t i = 0; i < path.size(); ++i) {
            const Vec2 p = to_vec2(path[i]), q = to_vec2(path[(i + 1) % path.size()]);
            consider(nearest_on(a, b, p), p);
            consider(a, nearest_on(p, q, a));
            consider(b, nearest_on(p, q, b));
            consider(middle, nearest_on(p, q, middle));
        }
    return best;
}

/// The convex hull of `points`, counter-clockwise (Andrew's monotone chain).
Loop2 convex_hull(std::vector<Vec2> points)
{
    std::sort(points.begin(), points.end(), [](const Vec2& a, const Vec2& b) {
        return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
    });
    auto turn = [](const Vec2& o, const Vec2& a, const Vec2& b) {
        return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
    };
    Loop2 hull(2 * points.size());
    size_t k = 0;
    for (size_t i = 0; i < points.size(); ++i) { // lower chain
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 0)
            --k;
        hull[k++] = points[i];
    }
    for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) { // upper chain
        while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i]) <= 0)
            --k;
        hull[k++] = points[i];
    }
    hull.resize(k - 1);
    return hull;
}

/// Whether `x` lies on `paper` (outer loops and holes: an odd number of loops hold it).
bool on_paper(const ClipperLib::Paths& paper, const Vec2& x)
{
    int inside = 0;
    for (const ClipperLib::Path& path : paper)
        inside += ClipperLib::PointInPolygon(to_int_point(x), path) != 0;
    return inside % 2 == 1;
}

} // namespace

ClipperLib::Paths bridges(const Scaffold& s, int patch, const ProfileFrame& frame,
                          const ClipperLib::Paths& paper, const ClipperLib::Paths& shape,
                          double width, double tab_depth, double smallest)
{
    std::vector<Loop2> out;
    if (shape.empty())
        return {};
    const double outward = 1.0;
    for (const Edge& e : edges_of(s, patch, frame)) {
        const double length = (e.to - e.from).norm();
        if (length < 1e-9 || length_met(shape, e.from, e.to) >= std::min(smallest, length))
            continue;
        const Vec2 along = (e.to - e.from) / length;
        const auto [q, p] = nearest_pair(e.from, e.to, shape);
        // Across the fold toward the outline; where the outline lies on the fold's own line
        // (beyond its end), toward the patch's paper.
        Vec2 in(-along.y(), along.x());
        const double side = (p - q).dot(in);
        if (std::abs(side) > 1e-6)
            in *= side > 0 ? 1.0 : -1.0;
        else if (!on_paper(paper, 0.5 * (e.from + e.to) + 1e-3 * in))
            in = -in;
        // The bridge's foot on the fold: `width` long, as near q as the fold allows, half as
        // deep (a glued joint's a tab's depth); its head about p, reaching into the outline.
        double half = 0.5 * std::min(width, length);
        double t = std::clamp((q - e.from).dot(along), half, length - half);
        // A gap narrower than the sheets can cut between the foot and an end of the fold would
        // stay paper (significant_cut), less deep than the foot: the foot runs to that end.
        const double lo = t - half < smallest ? 0.0 : t - half;
        const double hi = length - (t + half) < smallest ? length : t + half;
        half = 0.5 * (hi - lo);
        t = 0.5 * (lo + hi);
        const Vec2 foot = e.from + t * along;
        const double depth = e.glued ? std::max(tab_depth, half) : half;
        const double reach = std::min(half, 2.0);
        out.push_back(
            convex_hull({foot - half * along - outward * in, foot + half * along - outward * in,
                         foot + half * along + depth * in, foot - half * along + depth * in,
                         p - half * along - reach * in, p + half * along - reach * in,
                         p + half * along + reach * in, p - half * along + reach * in}));
    }
    return counter_clockwise_paths(out);
}

} // namespace popup::fold_bridges
