#include "clipper_ops.hpp"

#include "../geometry/clipper_paths.hpp"

namespace popup::sheets {

namespace {

double total_area(const ClipperLib::Paths& paths)
{
    double area = 0.0;
    for (const ClipperLib::Path& p : paths)
        area += path_area(p);
    return area;
}

} // namespace

double overlap_area(const std::vector<Loop2>& a, const std::vector<Loop2>& b)
{
    ClipperLib::Clipper clipper;
    clipper.AddPaths(counter_clockwise_paths(a), ClipperLib::ptSubject, true);
    clipper.AddPaths(counter_clockwise_paths(b), ClipperLib::ptClip, true);
    ClipperLib::Paths result;
    clipper.Execute(ClipperLib::ctIntersection, result, ClipperLib::pftNonZero,
                    ClipperLib::pftNonZero);
    return total_area(result);
}

double area_outside(const Loop2& a, const Loop2& outer, const std::vector<Loop2>& holes)
{
    ClipperLib::Clipper region;
    region.AddPaths(counter_clockwise_paths({outer}), ClipperLib::ptSubject, true);
    region.AddPaths(counter_clockwise_paths(holes), ClipperLib::ptClip, true);
    ClipperLib::Paths paper;
    region.Execute(ClipperLib::ctDifference, paper, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    ClipperLib::Clipper clipper;
    clipper.AddPaths(counter_clockwise_paths({a}), ClipperLib::ptSubject, true);
    clipper.AddPaths(paper, ClipperLib::ptClip, true);
    ClipperLib::Paths result;
    clipper.Execute(ClipperLib::ctDifference, result, ClipperLib::pftNonZero,
                    ClipperLib::pftNonZero);
    return total_area(result);
}

double loop_area(const Loop2& loop)
{
    double twice = 0.0;
    for (size_t i = 0, n = loop.size(); i < n; ++i) {
        const Vec2& p = loop[i];
        const Vec2& q = loop[(i + 1) % n];
        twice += p.x() * q.y() - q.x() * p.y();
    }
    return 0.5 * twice;
}

void collect_regions(const ClipperLib::PolyNode& node, std::vector<Region>& regions)
{
    for (const ClipperLib::PolyNode* outer : node.Childs) {
        Region region{to_loop(outer->Contour), {}};
        for (const ClipperLib::PolyNode* hole : outer->Childs) {
            region.holes.push_back(to_loop(hole->Contour));
            collect_regions(*hole, regions);
        }
        regions.push_back(std::move(region));
    }
}

} // namespace popup::sheets
