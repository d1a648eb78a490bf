#include "layer_footprint.hpp"

#include <cmath>
#include <utility>

#include "../geometry/clipper_paths.hpp"
#include "outline_support.hpp"
#include "popup/model/apply_profile.hpp"

namespace popup::layer_footprint {
namespace {

/// The footprint as a profile of `part` (a patch parallel to the face): pair coordinates back
/// to world points, `lift` along the face's normal, into the part's profile frame.
Profile profile_on(const Footprint& f, const BasePatchPair& pair, const Vec3& across,
                   const ProfileFrame& part, const std::string& name)
{
    auto loop = [&](const Loop2& l) {
        Loop2 out;
        for (const Vec2& q : l)
            out.push_back(part.to_frame(pair.origin + q.x() * pair.axis + q.y() * across));
        return out;
    };
    Profile p;
    p.name = name;
    p.outer = loop(f.outer.front());
    for (const Loop2& h : f.holes.front())
        p.holes.push_back(loop(h));
    return p;
}

} // namespace

const Patch* patch_named(const Scaffold& s, const std::string& name)
{
    for (const Patch& p : s.patches)
        if (p.name == name)
            return &p;
    return nullptr;
}

std::optional<Footprint> footprint(const Silhouette& sil, const ProfileFrame& face,
                                   const BasePatchPair& pair, const Vec3& across, double lo,
                                   double hi)
{
    using namespace ClipperLib;
    auto to_pair = [&](const Loop2& loop) {
        Loop2 out;
        for (const Vec2& q : loop) {
            const Vec3 d = face.to_world(q) - pair.origin;
            out.push_back({d.dot(pair.axis), d.dot(across)});
        }
        return out;
    };
    Paths shape = counter_clockwise_paths({to_pair(sil.profile.outer)});
    if (!sil.profile.holes.empty()) {
        std::vector<Loop2> holes;
        for (const Loop2& h : sil.profile.holes)
            holes.push_back(to_pair(h));
        Clipper c;
        c.AddPaths(shape, ptSubject, true);
        c.AddPaths(counter_clockwise_paths(holes), ptClip, true);
        c.Execute(ctDifference, shape, pftNonZero, pftNonZero);
    }
    const Loop2 room{{0, lo}, {pair.length, lo}, {pair.length, hi}, {0, hi}};
    PolyTree inside;
    Clipper c;
    c.AddPaths(shape, ptSubject, true);
    c.AddPaths(counter_clockwise_paths({room}), ptClip, true);
    c.Execute(ctIntersection, inside, pftNonZero, pftNonZero);
    const PolyNode* best = nullptr;
    double best_area = 0;
    for (const PolyNode* n : inside.Childs) {
        double a = std::abs(path_area(n->Contour));
        for (const PolyNode* h : n->Childs)
            a -= std::abs(path_area(h->Contour));
        if (a > best_area) {
            best_area = a;
            best = n;
        }
    }
    if (!best)
        return std::nullopt;
    Footprint f;
    f.outer.push_back(to_loop(best->Contour));
    f.holes.emplace_back();
    for (const PolyNode* h : best->Childs)
        f.holes.back().push_back(to_loop(h->Contour));
    f.area = best_area;
    f.lo = Vec2(1e300, 1e300);
    f.hi = Vec2(-1e300, -1e300);
    for (const Vec2& q : f.outer.front()) {
        f.lo = f.lo.cwiseMin(q);
        f.hi = f.hi.cwiseMax(q);
    }
    return f;
}

Result<std::optional<FittedProfile>> cut_part(Scaffold& s, const std::string& name,
                                              const std::string& part, const Footprint& f,
                                              const BasePatchPair& pair, const Vec3& across)
{
    Result<std::optional<FittedProfile>> r;
    const Patch* p = patch_named(s, name + "." + part);
    if (!p) {
        r.fail(DiagnosticCode::unknown_patch, name + " has no part " + part);
        return r;
    }
    const int id = p->id;
    const Result<ProfileFrame> frame = profile_frame(s, id);
    if (!frame.ok) {
        r.fail_with(frame.diagnostics);
        return r;
    }
    const Profile profile = profile_on(f, pair, across, frame.value, "depth layer silhouette");
    Scaffold before = s;
    const Result<ProfileApplied> applied = apply_profile(s, id, profile);
    if (!applied.ok) {
        r.fail_with(applied.diagnostics);
        return r;
    }
    if (std::abs(applied.value.area_after - applied.value.area_before) <=
        1e-6 * applied.value.area_before) {
        s = std::move(before); // covers the part: no stored outline (as fit_outlines)
        return r;
    }
    FittedProfile fp;
    fp.mechanism = name;
    fp.part = part;
    const Patch& cut = *s.find_patch(id);
    Vec2 lo(1e300, 1e300), hi(-1e300, -1e300);
    for (const Vec3& x : before.find_patch(id)->outer) {
        const Vec2 q = frame.value.to_frame(x);
        lo = lo.cwiseMin(q);
        hi = hi.cwiseMax(q);
    }
    fp.reference = hi - lo;
    outline_support::record_cut(fp, cut, applied.value);
    r.value = fp;
    return r;
}

} // namespace popup::layer_footprint
