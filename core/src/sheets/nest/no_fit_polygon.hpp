#pragma once
// The no-fit polygon of two outlines: where one outline's reference point must not go.
#include <vector>

#include "../../geometry/clipper_paths.hpp"
#include "convex_hull.hpp"

namespace popup::nest_detail {

inline ClipperLib::Path translated(const ClipperLib::Path& path, const ClipperLib::IntPoint& by)
{
    ClipperLib::Path result(path);
    for (ClipperLib::IntPoint& p : result) {
        p.X += by.X;
        p.Y += by.Y;
    }
    return result;
}

/// The positions of the moving outline's frame origin at which it would overlap the fixed one
/// (both given as convex parts in the same frame): fixed ⊕ (−moving), the union of the sums of
/// their parts. Two convex parts sum to the hull of their vertices' differences, which is far
/// cheaper than Clipper's MinkowskiSum (a union of one quadrilateral per pair of edges).
inline ClipperLib::Paths no_fit_polygon(const std::vector<ClipperLib::Path>& fixed_parts,
                                        const std::vector<ClipperLib::Path>& moving_parts)
{
    ClipperLib::Clipper clipper;
    for (const ClipperLib::Path& fixed : fixed_parts) {
        for (const ClipperLib::Path& moving : moving_parts) {
            ClipperLib::Path sums;
            sums.reserve(fixed.size() * moving.size());
            for (const ClipperLib::IntPoint& a : fixed)
                for (const ClipperLib::IntPoint& b : moving)
                    sums.push_back({a.X - b.X, a.Y - b.Y});
            clipper.AddPath(convex_hull(std::move(sums)), ClipperLib::ptSubject, true);
        }
    }
    ClipperLib::Paths nfp;
    clipper.Execute(ClipperLib::ctUnion, nfp, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    return nfp;
}

} // namespace popup::nest_detail
