#include "glued_joints.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "../geometry/clipper_paths.hpp"

namespace popup::glued_joints {

namespace {

bool inside_loop(const std::vector<Vec2>& loop, const Vec2& q)
{
    bool inside = false;
    for (size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
        const Vec2 &a = loop[j], &b = loop[i];
        if ((a.y() > q.y()) != (b.y() > q.y()) &&
            q.x() < a.x() + (q.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
            inside = !inside;
    }
    return inside;
}

/// A patch (its frame derived) and whether a point of its plane lies on its paper.
class Paper {
public:
    explicit Paper(const Patch& p) : patch_(p)
    {
        patch_.derive_frame();
        for (const Vec3& v : patch_.outer)
            outer_.push_back(patch_.to_local(v));
        for (const Loop3& h : patch_.holes) {
            holes_.emplace_back();
            for (const Vec3& v : h)
                holes_.back().push_back(patch_.to_local(v));
        }
    }

    bool holds(const Vec3& x) const
    {
        const Vec2 q = patch_.to_local(x);
        if (!inside_loop(outer_, q))
            return false;
        for (const auto& h : holes_)
            if (inside_loop(h, q))
                return false;
        return true;
    }

    /// The unit vector across hinge `h` (of this patch) that points onto the paper.
    Vec3 inward(const Hinge& h, double depth) const
    {
        const Vec3 inward = patch_.normal.cross(h.to - h.from).normalized();
        return holds(0.5 * (h.from + h.to) + 1e-3 * depth * inward) ? inward : Vec3(-inward);
    }

private:
    Patch patch_;
    std::vector<Vec2> outer_;
    std::vector<std::vector<Vec2>> holes_;
};

/// The other patch of a glued joint of `patch`, or null (a fold, or not this patch's).
const Patch* glued_to(const Scaffold& s, const Hinge& h, int patch)
{
    if ((h.patch_a != patch && h.patch_b != patch) || h.kind != JointKind::tab)
        return nullptr;
    return s.find_patch(h.patch_a == patch ? h.patch_b : h.patch_a);
}

/// Stretches [from, to] (mm from `a` along `along`, a unit vector) where `shape` meets the
/// segment from `a` of length `length`: the shape cut to a band 1 µm deep over it.
std::vector<std::pair<double, double>> stretches_met(const ClipperLib::Paths& shape, const Vec2& a,
                                                     const Vec2& along, const Vec2& in,
                                                     double length)
{
    using namespace ClipperLib;
    const double thin = 1e-3;
    const Path band =
        to_path({a, a + length * along, a + length * along + thin * in, a + thin * in});
    Paths met;
    Clipper c;
    c.AddPaths(shape, ptSubject, true);
    c.AddPath(band, ptClip, true);
    c.Execute(ctIntersection, met, pftNonZero, pftNonZero);
    std::vector<std::pair<double, double>> out;
    for (const Path& piece : met) {
        if (!(std::abs(path_area(piece)) > 0))
            continue;
        double lo = length, hi = 0;
        for (const IntPoint& p : piece) {
            const double t = (to_vec2(p) - a).dot(along);
            lo = std::min(lo, t);
            hi = std::max(hi, t);
        }
        out.push_back({std::max(0.0, lo), std::min(length, hi)});
    }
    return out;
}

/// Whether glued joint `h` of `patch` shares its crease with another glued joint of the other
/// patch (a box's centre wall joined to both top halves along one line): the sheets glue both
/// with one tab along one of them, which holds the other only where it lies within that one.
bool shares_crease(const Scaffold& s, const Hinge& h, int patch)
{
    const int other = h.patch_a == patch ? h.patch_b : h.patch_a;
    const Vec3 along = (h.to - h.from).normalized();
    const double length = (h.to - h.from).norm();
    const double tol = 1e-6 * std::max(1.0, s.size());
    auto off_line = [&](const Vec3& x) {
        return (x - h.from - (x - h.from).dot(along) * along).norm();
    };
    for (const Hinge& g : s.hinges) {
        if (g.id == h.id || g.kind != JointKind::tab ||
            (g.patch_a != other && g.patch_b != other) || g.patch_a == patch || g.patch_b == patch)
            continue;
        if (off_line(g.from) > tol || off_line(g.to) > tol)
            continue;
        const double a = (g.from - h.from).dot(along), b = (g.to - h.from).dot(along);
        if (std::min(std::max(a, b), length) - std::max(std::min(a, b), 0.0) > tol)
            return true;
    }
    return false;
}

} // namespace

std::map<std::string, double> joint_lengths(const Scaffold& s, int patch)
{
    std::map<std::string, double> out;
    for (const Hinge& h : s.hinges) {
        const Patch* p = glued_to(s, h, patch);
        if (!p)
            continue;
        const double length = (h.to - h.from).norm();
        out[p->name] = out.count(p->name) ? std::min(out[p->name], length) : length;
    }
    return out;
}

std::set<std::string> joints_without_room(const Scaffold& s, int patch, double depth)
{
    std::set<std::string> out;
    const Paper paper(*s.find_patch(patch));
    for (const Hinge& h : s.hinges) {
        const Patch* other = glued_to(s, h, patch);
        const Vec3 along = h.to - h.from;
        if (!other || along.norm() < 1e-9)
            continue;
        const Vec3 inward = paper.inward(h, depth);
        // Every half millimetre along the joint, its ends left out (the corners of the patch).
        const int steps = std::max(2, int(std::ceil(along.norm() / 0.5)));
        for (int k = 1; k < steps; ++k) {
            const double u = double(k) / steps;
            if (!paper.holds(h.from + u * along + 0.999 * depth * inward)) {
                out.insert(other->name);
                break;
            }
        }
    }
    return out;
}

ClipperLib::Paths joint_strips(const Scaffold& s, int patch, const ProfileFrame& frame,
                               const ClipperLib::Paths& shape, double crease, double depth)
{
    std::vector<Loop2> strips;
    const Paper paper(*s.find_patch(patch));
    const double outward = 1.0;
    for (const Hinge& h : s.hinges) {
        const double length = (h.to - h.from).norm();
        if (!glued_to(s, h, patch) || length < 1e-9)
            continue;
        // The joint in the frame: from a, along a unit vector, the paper on the `in` side.
        const Vec2 a = frame.to_frame(h.from);
        const Vec2 along = (frame.to_frame(h.to) - a).normalized();
        const Vec2 in = frame.to_frame(h.from + paper.inward(h, depth)) - a;
        const double wanted = std::min(crease, length);
        std::vector<std::pair<double, double>> met = stretches_met(shape, a, along, in, length);
        if (!met.empty() && shares_crease(s, h, patch))
            met = {{0.0, length}}; // kept whole: the tab on the other joint then holds it
        for (auto [lo, hi] : met) {
            if (hi - lo < wanted) { // lengthened about its middle, kept on the joint
                const double mid = std::clamp(0.5 * (lo + hi), 0.5 * wanted, length - 0.5 * wanted);
                lo = mid - 0.5 * wanted;
                hi = mid + 0.5 * wanted;
            }
            strips.push_back({a + lo * along - outward * in, a + hi * along - outward * in,
                              a + hi * along + depth * in, a + lo * along + depth * in});
        }
    }
    return counter_clockwise_paths(strips);
}

} // namespace popup::glued_joints
