#include "prism_acceptance.hpp"

#include <algorithm>

namespace popup::prism_search {
namespace {

/// Every dimension of the prism that becomes a glued crease is at least `min_part`: the length
/// along the hinge (every mechanism's patches are glued to its host along it) and, for a box
/// fold (a rectangular prism on a flat host), each depth (its centre panel is glued to both
/// pages along them) and the height (its end panels are glued to its sides along it). A step's
/// runs and a tent's feet meet their host in folds of their own, not glued ones.
bool thick_enough(const PrismHost& h, const Prism& m, double min_part)
{
    if (m.a1 - m.a0 < min_part)
        return false;
    if (m.kind != Prism::Kind::rectangular || !h.flat)
        return true;
    return std::min(m.s1, -m.s0) >= min_part && m.height >= min_part;
}

/// Grows a too thin prism to `min_part` where its host has room: along the hinge about its
/// middle, a box's depth and height. The score then judges the grown prism like any other (it
/// must still enclose no sample), so a thin slab inside a round model becomes a thin box.
void grow_to(const PrismHost& h, Prism& m, double min_part)
{
    if (m.a1 - m.a0 < min_part && h.length >= min_part) {
        const double mid =
            std::clamp(0.5 * (m.a0 + m.a1), 0.5 * min_part, h.length - 0.5 * min_part);
        m.a0 = mid - 0.5 * min_part;
        m.a1 = mid + 0.5 * min_part;
    }
    if (m.kind != Prism::Kind::rectangular || !h.flat)
        return;
    const double reach = std::min(h.across_max, -h.across_min);
    if (m.s1 < min_part && min_part <= reach) {
        m.s1 = min_part;
        m.s0 = -min_part;
    }
    if (m.height < min_part && min_part < h.up_max)
        m.height = min_part;
}

} // namespace

bool fit_host(const PrismHost& h, Prism& m, double eps, double min_part)
{
    if (m.kind == Prism::Kind::rectangular) {
        if (h.flat) {
            // A box fold is centred on its host's hinge: equal depths (docs/DESIGN.md).
            const double reach = std::min(h.across_max, -h.across_min);
            double d = std::max(-m.s0, m.s1);
            if (d > reach + eps)
                return false;
            d = std::min(d, reach);
            m.s0 = -d;
            m.s1 = d;
        } else {
            m.s0 = 0;
            // A step must stay below its wall and on its page: one as tall as its wall (an
            // arm behind a box, flush with its top) stops just below it.
            if (m.height >= h.up_max * 0.98 && m.height <= h.up_max + eps)
                m.height = h.up_max * 0.98;
            if (m.s1 >= h.across_max || m.height > h.up_max * 0.98)
                return false;
        }
        if (m.s1 - m.s0 < eps || m.height < eps)
            return false;
    }
    m.a0 = std::max(m.a0, 0.0);
    m.a1 = std::min(m.a1, h.length);
    if (m.a1 - m.a0 <= eps)
        return false;
    grow_to(h, m, min_part);
    return thick_enough(h, m, min_part);
}

bool outside_model(const Prism& m, const PrismHost& h, const Eigen::AlignedBox3d& model, double eps)
{
    for (const Vec3& c : m.corners(h))
        if (c.z() > model.max().z() + eps)
            return true;
    return false;
}

/// True when the prism's box overlaps one of `taken` by more than ε along every axis: two
/// primitives may touch (one stands on the other) but not share volume, or their mechanisms
/// would.
bool overlaps(const Prism& m, const PrismHost& h, const std::vector<Eigen::AlignedBox3d>& taken,
              double eps)
{
    Eigen::AlignedBox3d box;
    for (const Vec3& c : m.corners(h))
        box.extend(c);
    for (const auto& t : taken) {
        const Vec3 lo = box.min().cwiseMax(t.min()), hi = box.max().cwiseMin(t.max());
        if (((hi - lo).array() > eps).all())
            return true;
    }
    return false;
}

void stop_at_taken(Prism& m, const PrismHost& h, const std::vector<Eigen::AlignedBox3d>& taken,
                   double seed_a0, double seed_a1, double eps)
{
    Eigen::AlignedBox3d box;
    for (const Vec3& c : m.corners(h))
        box.extend(c);
    for (const auto& t : taken) {
        const Vec3 lo = box.min().cwiseMax(t.min()), hi = box.max().cwiseMin(t.max());
        if (!((hi - lo).array() > eps).all())
            continue;
        // The taken box's stretch along the hinge, from its corners.
        double t0 = 1e300, t1 = -1e300;
        for (int k = 0; k < 8; ++k) {
            const double a = (t.corner(Eigen::AlignedBox3d::CornerType(k)) - h.origin).dot(h.axis);
            t0 = std::min(t0, a);
            t1 = std::max(t1, a);
        }
        if (t1 <= seed_a0 + eps)
            m.a0 = std::max(m.a0, t1);
        else if (t0 >= seed_a1 - eps)
            m.a1 = std::min(m.a1, t0);
    }
}

} // namespace popup::prism_search
