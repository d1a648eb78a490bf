#include "design_distance.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace popup {
namespace {

/// Distance from x to a planar patch (its outline, holes ignored: a patch covers its face).
double distance_to_patch(const Patch& patch, const std::vector<Vec2>& outline, const Vec3& x)
{
    const double off = (x - patch.origin).dot(patch.normal);
    const Vec2 q = patch.to_local(x);
    bool inside = false;
    double edge = 1e300;
    for (size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
        const Vec2 &a = outline[j], &b = outline[i];
        if ((a.y() > q.y()) != (b.y() > q.y()) &&
            q.x() < a.x() + (q.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
            inside = !inside;
        const Vec2 d = b - a;
        const double t = std::clamp((q - a).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
        edge = std::min(edge, (a + t * d - q).norm());
    }
    return inside ? std::abs(off) : std::hypot(off, edge);
}

/// The scaffold's patches with their frames derived, and each outline in its patch's frame.
std::pair<std::vector<Patch>, std::vector<std::vector<Vec2>>>
framed_outlines(const Scaffold& scaffold)
{
    std::vector<Patch> patches = scaffold.patches;
    std::vector<std::vector<Vec2>> outlines;
    for (Patch& p : patches) {
        p.derive_frame();
        std::vector<Vec2> o;
        for (const Vec3& v : p.outer)
            o.push_back(p.to_local(v));
        outlines.push_back(o);
    }
    return {patches, outlines};
}

} // namespace

double coverage_of(const Scaffold& scaffold, const SurfaceSamples& samples, double eps)
{
    const auto [patches, outlines] = framed_outlines(scaffold);
    size_t near = 0;
    // A sample farther than ε from a patch's plane is farther from the patch: most pairs stop
    // there (the margin keeps hypot's rounding on the far side of ε).
    const double off_plane = eps * (1 + 1e-9);
    for (const Vec3& x : samples.points)
        for (size_t k = 0; k < patches.size(); ++k)
            if (std::abs((x - patches[k].origin).dot(patches[k].normal)) <= off_plane &&
                distance_to_patch(patches[k], outlines[k], x) <= eps) {
                ++near;
                break;
            }
    return samples.points.empty() ? 0.0 : double(near) / double(samples.points.size());
}

double mean_distance_to(const Scaffold& scaffold, const SurfaceSamples& samples)
{
    const auto [patches, outlines] = framed_outlines(scaffold);
    const size_t step = std::max<size_t>(1, samples.points.size() / 3000);
    double sum = 0;
    size_t n = 0;
    for (size_t i = 0; i < samples.points.size(); i += step, ++n) {
        double nearest = 1e300;
        for (size_t k = 0; k < patches.size(); ++k)
            nearest =
                std::min(nearest, distance_to_patch(patches[k], outlines[k], samples.points[i]));
        sum += nearest;
    }
    return n ? sum / double(n) : 0.0;
}

} // namespace popup
