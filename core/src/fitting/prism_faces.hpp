#pragma once
// Internal: where a sample lies with respect to a prism standing on a host (on a face, inside,
// outside), in the host's coordinates. Inline: the search classifies every sample of every draw.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "popup/fitting/prism_types.hpp"

namespace popup::prism_search {

constexpr double kNormalAgreement = 0.94; ///< cos 20°: the largest normal deviation on a face

/// A sample in one host's coordinates.
struct Local {
    double a, s, t;    ///< along the hinge, across, up
    double na, ns, nt; ///< the normal in the same axes
};

/// Sorts samples along the hinge (by a; ties in any order: every reader counts or sorts).
inline void sort_along(std::vector<Local>& l)
{
    std::sort(l.begin(), l.end(), [](const Local& x, const Local& y) { return x.a < y.a; });
}

/// The stretch of `l` (sorted along the hinge) with from <= a < to, first and past the last.
inline std::pair<const Local*, const Local*> stretch(const std::vector<Local>& l, double from,
                                                     double to)
{
    auto by_a = [](const Local& x, double a) { return x.a < a; };
    const Local* lo = std::lower_bound(l.data(), l.data() + l.size(), from, by_a);
    const Local* hi = std::lower_bound(lo, l.data() + l.size(), to, by_a);
    return {lo, hi};
}

inline Local to_local(const PrismHost& h, const Vec3& p, const Vec3& n)
{
    const Vec3 q = p - h.origin;
    return {q.dot(h.axis), q.dot(h.across), q.dot(h.up),
            n.dot(h.axis), n.dot(h.across), n.dot(h.up)};
}

inline bool above_host(const PrismHost& h, const Local& l, double eps)
{
    if (l.a < -eps || l.a > h.length + eps || l.t < eps * 0.5)
        return false;
    if (h.flat)
        return l.s > h.across_min - eps && l.s < h.across_max + eps;
    return l.s > eps * 0.5 && l.s < h.across_max + eps && l.t < h.up_max + eps;
}

/// Whether a sample may lie on a face of a rectangular prism (classify) or be a wall across
/// the hinge (Search::extend_along): its normal within 20° of up, across or along the hinge.
inline bool may_carry_box(const Local& l)
{
    return l.nt > kNormalAgreement || std::abs(l.ns) > kNormalAgreement ||
           std::abs(l.na) > kNormalAgreement;
}

/// The same for a triangular prism: on a slope its normal's share across the hinge is at least
/// 0.94 (a slope's normal is unit in the section plane; 0.85 its square with room for
/// rounding), on an end or a wall within 20° of the hinge.
inline bool may_carry_slope(const Local& l)
{
    return l.ns * l.ns + l.nt * l.nt > 0.85 || std::abs(l.na) > kNormalAgreement;
}

/// Which face of a prism a sample lies on (within ε, normal agreeing), or inside it.
enum class Where { outside, face, inside };

struct Section {
    // Triangular: the two slopes as unit outward normals and a point on each.
    Vec2 ng, nb, g, b;
    double lg = 0, lb = 0; // slope lengths
};

inline Section section_of(const Prism& m)
{
    Section s;
    s.g = Vec2(m.s1, 0);
    s.b = Vec2(m.s0, 0);
    const Vec2 apex(m.apex_s, m.height);
    const Vec2 dg = apex - s.g, db = apex - s.b;
    s.lg = dg.norm();
    s.lb = db.norm();
    s.ng = Vec2(dg.y(), -dg.x()) / std::max(s.lg, 1e-300);
    s.nb = Vec2(-db.y(), db.x()) / std::max(s.lb, 1e-300);
    return s;
}

/// Face index: 0 top or ground slope, 1 side s1 (rect), 2 side s0 or backdrop slope, 3 end a0,
/// 4 end a1, 5 a rectangular prism's backbone (its hinge plane, s = 0, on a flat host).
inline Where classify(const Prism& m, const Section& sec, const Local& l, double eps, bool flat,
                      int* face = nullptr)
{
    const bool in_a = l.a > m.a0 - eps && l.a < m.a1 + eps;
    if (!in_a)
        return Where::outside;
    const bool deep_a = l.a > m.a0 + eps && l.a < m.a1 - eps;
    auto set = [&](int f) {
        if (face)
            *face = f;
        return Where::face;
    };
    if (m.kind == Prism::Kind::rectangular) {
        const bool in_s = l.s > m.s0 - eps && l.s < m.s1 + eps;
        const bool in_t = l.t > -eps && l.t < m.height + eps;
        if (!in_s || !in_t)
            return Where::outside;
        // A box fold's backbone C stands on its hinge from the page to the top: a wall of the
        // model there (an L's inner wall with the fold on it) lies on the box, not inside it.
        if (flat && std::abs(l.s) < eps && std::abs(l.ns) > kNormalAgreement && l.t < m.height)
            return set(5);
        if (deep_a && l.s > m.s0 + eps && l.s < m.s1 - eps && l.t > eps && l.t < m.height - eps)
            return Where::inside;
        if (std::abs(l.t - m.height) < eps && l.nt > kNormalAgreement)
            return set(0);
        if (std::abs(l.s - m.s1) < eps && l.ns > kNormalAgreement)
            return set(1);
        if (flat && std::abs(l.s - m.s0) < eps && l.ns < -kNormalAgreement)
            return set(2);
        if (std::abs(l.a - m.a0) < eps && l.na < -kNormalAgreement)
            return set(3);
        if (std::abs(l.a - m.a1) < eps && l.na > kNormalAgreement)
            return set(4);
        return Where::outside;
    }
    const Vec2 q(l.s, l.t);
    const double dg = (q - sec.g).dot(sec.ng), db = (q - sec.b).dot(sec.nb);
    if (dg > eps || db > eps || l.t < -eps)
        return Where::outside;
    if (deep_a && dg < -eps && db < -eps && l.t > eps)
        return Where::inside;
    const Vec2 n(l.ns, l.nt);
    if (std::abs(dg) < eps && n.dot(sec.ng) > kNormalAgreement)
        return set(0);
    if (std::abs(db) < eps && n.dot(sec.nb) > kNormalAgreement)
        return set(2);
    if (std::abs(l.a - m.a0) < eps && l.na < -kNormalAgreement)
        return set(3);
    if (std::abs(l.a - m.a1) < eps && l.na > kNormalAgreement)
        return set(4);
    return Where::outside;
}

} // namespace popup::prism_search
