#include "popup/mechanisms/tent_fold.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "mechanism_builder.hpp"

namespace popup {

double tent_backdrop_slope(const TentFoldParams& p)
{
    return p.foot + p.slope - p.foot_backdrop;
}

Vec2 tent_apex(const TentFoldParams& p, double opening)
{
    const Vec2 g(std::sin(opening / 2), std::cos(opening / 2));
    const Vec2 b(-g.x(), g.y());
    const Vec2 A = p.foot * g, D = p.foot_backdrop * b;
    const double s1 = p.slope, s2 = tent_backdrop_slope(p);
    const double gap = (D - A).norm();
    if (gap < 1e-12 * (p.foot + p.slope))
        return A + s1 * g; // closed with equal feet: the limit along the page
    // On the circles |C − A| = s1 and |C − D| = s2, on the open side of AD (docs/MATH.md).
    const Vec2 along = (D - A) / gap;
    const double t = (s1 * s1 - s2 * s2 + gap * gap) / (2 * gap);
    const double h = std::sqrt(std::max(0.0, s1 * s1 - t * t));
    Vec2 normal(-along.y(), along.x());
    if (normal.y() < 0)
        normal = -normal;
    return A + t * along + h * normal;
}

Result<MechanismParts> add_tent_fold(Scaffold& scaffold, const BasePatchPair& host,
                                     const TentFoldParams& p, const std::string& name)
{
    Result<MechanismParts> r;
    Diagnostics& e = r.diagnostics;
    check_placement(name, host, p, e);
    check_run(e, name, "Foot", p.foot, host.ground_depth, "ground");
    check_run(e, name, "FootBackdrop", p.foot_backdrop, host.backdrop_depth, "backdrop");
    const Vec2 g = host.ground_direction(), b = host.backdrop_direction();
    const Vec2 A = p.foot * g, D = p.foot_backdrop * b;
    const double gap = (A - D).norm();
    if (e.empty()) {
        // The slopes meet above the feet when |s1 − s2| < |AD| < s1 + s2, s2 = a1 + s1 − a2.
        const double lowest =
            std::max((gap - p.foot + p.foot_backdrop) / 2, p.foot_backdrop - p.foot);
        if (!(p.slope > lowest && p.slope <= 2000)) {
            // 2000 mm: the bound of every mechanism's height (a 1e300 mm slope passed and made
            // the slopes degenerate, an error that could not name Slope).
            std::ostringstream m;
            m << "> " << lowest << " mm so both slopes reach the apex (the backdrop slope is "
              << "Foot + Slope − FootBackdrop) and <= 2000 mm";
            range_error(e, name, "Slope", p.slope, "mm", m.str());
        } else if (!(std::abs(p.foot - p.foot_backdrop) < gap)) {
            range_error(e, name, "FootBackdrop", p.foot_backdrop, "mm",
                        "closer to Foot: the slopes cannot meet at the design state");
        }
    }
    if (e.empty())
        check_part_sizes(scaffold, name,
                         {{"Width", p.width},
                          {"Foot", p.foot},
                          {"FootBackdrop", p.foot_backdrop},
                          {"Slope", p.slope}},
                         e);
    if (!e.empty()) {
        r.ok = false;
        return r;
    }
    const Vec2 C = tent_apex(p, host.opening);

    MechanismBuilder m(scaffold, host, name);
    const double y0 = p.offset, y1 = p.offset + p.width;
    auto at = [](const Vec2& q, double y) { return Vec3(q.x(), y, q.y()); };
    const int slope_g =
        m.patch({at(A, y0), at(A, y1), at(C, y1), at(C, y0)}, PatchRole::support, "slope_ground");
    const int slope_b =
        m.patch({at(C, y0), at(C, y1), at(D, y1), at(D, y0)}, PatchRole::support, "slope_backdrop");
    m.tab(host.ground, slope_g, at(A, y0), at(A, y1));
    m.tab(host.backdrop, slope_b, at(D, y0), at(D, y1));
    m.hinge(slope_g, slope_b, at(C, y0), at(C, y1));
    m.sweeps(y0, y1); // it moves only across the hinge
    return m.finish();
}

} // namespace popup
