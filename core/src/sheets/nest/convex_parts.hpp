#pragma once
// Cutting a polygon into convex parts, so that no-fit polygons become unions of convex sums.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "../../geometry/clipper_paths.hpp"
#include "bounds.hpp"
#include "convex_hull.hpp"

namespace popup::nest_detail {

/// How much area a hull may add to what it wraps and still count as the same region: a strip of
/// two units (nanometres) along its boundary, the rounding of Clipper's cut points.
inline double hull_slack(const ClipperLib::Path& hull)
{
    double perimeter = 0.0;
    for (std::size_t i = 0; i < hull.size(); ++i) {
        const ClipperLib::IntPoint& a = hull[i];
        const ClipperLib::IntPoint& b = hull[(i + 1) % hull.size()];
        perimeter += std::hypot(static_cast<double>(b.X - a.X), static_cast<double>(b.Y - a.Y));
    }
    return 2.0 * perimeter;
}

/// Merges the first two parts, in order, whose hull adds no area (the hull replaces the first,
/// the second goes), and again from the start until no two merge. Whether two parts merge
/// depends only on the two: a pair found apart is remembered by the parts' ids (a merged part
/// gets a new one), so each search again tests only the pairs a merge changed. The merges are
/// those of testing every pair every time.
inline void merge_while_hull_adds_nothing(std::vector<ClipperLib::Path>& parts)
{
    std::vector<std::size_t> ids(parts.size());
    std::iota(ids.begin(), ids.end(), std::size_t{0});
    const std::size_t id_count = 2 * parts.size(); // each merge makes one new id
    std::vector<bool> apart(id_count * id_count, false);
    std::size_t next_id = parts.size();
    for (bool merged = true; merged;) {
        merged = false;
        for (std::size_t i = 0; i < parts.size() && !merged; ++i) {
            for (std::size_t j = i + 1; j < parts.size() && !merged; ++j) {
                if (apart[ids[i] * id_count + ids[j]])
                    continue;
                ClipperLib::Path both = parts[i];
                both.insert(both.end(), parts[j].begin(), parts[j].end());
                ClipperLib::Path hull = convex_hull(std::move(both));
                const double added = ClipperLib::Area(hull) - ClipperLib::Area(parts[i]) -
                                     ClipperLib::Area(parts[j]);
                if (added <= hull_slack(hull)) {
                    parts[i] = std::move(hull);
                    ids[i] = next_id++;
                    parts.erase(parts.begin() + static_cast<std::ptrdiff_t>(j));
                    ids.erase(ids.begin() + static_cast<std::ptrdiff_t>(j));
                    merged = true;
                } else {
                    apart[ids[i] * id_count + ids[j]] = true;
                }
            }
        }
    }
}

/// Convex parts whose union is the simple polygon `outline`. Clipper cuts it into horizontal
/// slabs at its vertices' heights: with no vertex inside, every piece of a slab is a trapezoid.
/// Then parts merge while their hull adds no area, which leaves a rectangle with glue tabs as
/// one part and an L as two.
inline std::vector<ClipperLib::Path> convex_parts(const ClipperLib::Path& outline)
{
    std::vector<ClipperLib::Path> parts;
    const ClipperLib::Path whole = convex_hull(outline);
    if (ClipperLib::Area(whole) - std::abs(ClipperLib::Area(outline)) <= hull_slack(whole))
        return {whole};

    std::vector<ClipperLib::cInt> levels;
    for (const ClipperLib::IntPoint& p : outline)
        levels.push_back(p.Y);
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
    const Bounds box = bounds_of(outline);
    for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
        ClipperLib::Clipper clipper;
        clipper.StrictlySimple(true); // pieces touching at a point come out apart
        clipper.AddPath(outline, ClipperLib::ptSubject, true);
        clipper.AddPath({{box.left, levels[k]},
                         {box.right, levels[k]},
                         {box.right, levels[k + 1]},
                         {box.left, levels[k + 1]}},
                        ClipperLib::ptClip, true);
        ClipperLib::Paths slab;
        clipper.Execute(ClipperLib::ctIntersection, slab, ClipperLib::pftNonZero,
                        ClipperLib::pftNonZero);
        for (const ClipperLib::Path& piece : slab)
            parts.push_back(convex_hull(piece)); // drops collinear points, fixes the winding
    }

    merge_while_hull_adds_nothing(parts);
    return parts;
}

} // namespace popup::nest_detail
