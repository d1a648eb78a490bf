#include "piece_outline.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "../geometry/clipper_paths.hpp"
#include "clipper_ops.hpp"

namespace popup::sheets {

namespace {

using ClipperLib::Paths;

constexpr double miter_limit = 8.0; // keeps tab and card corners sharp under the kerf offset
constexpr double hairline = 1e-4;   // mm: gaps this narrow between a piece's parts are rounding

Paths region_paths(const std::vector<Region>& regions)
{
    Paths paths;
    for (const Region& r : regions) {
        paths.push_back(to_path(r.outer));
        for (const Loop2& h : r.holes)
            paths.push_back(to_path(h));
    }
    return paths;
}

Paths offset_paths(const Paths& paths, double distance)
{
    ClipperLib::ClipperOffset offsetter(miter_limit);
    offsetter.AddPaths(paths, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
    Paths out;
    offsetter.Execute(out, distance * clipper_scale);
    return out;
}

std::vector<Region> offset(const Paths& paths, double distance)
{
    ClipperLib::ClipperOffset offsetter(miter_limit);
    offsetter.AddPaths(paths, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
    ClipperLib::PolyTree tree;
    offsetter.Execute(tree, distance * clipper_scale);
    std::vector<Region> regions;
    collect_regions(tree, regions);
    return regions;
}

// Widest inward offset that leaves something of the opening: half its narrowest width, to 1 µm.
double inner_radius(const Loop2& opening)
{
    const Paths path = counter_clockwise_paths({opening});
    double low = 0.0, high = 0.0;
    for (const Vec2& p : opening)
        high = std::max(high, (p - opening.front()).norm());
    while (high - low > 1e-5) {
        const double mid = 0.5 * (low + high);
        (offset_paths(path, -mid).empty() ? high : low) = mid;
    }
    return low;
}

} // namespace

void check_openings_survive_kerf(const LocalPiece& piece, const std::string& piece_id, double kerf,
                                 Diagnostics& diagnostics)
{
    if (kerf <= 0.0)
        return;
    auto check = [&](const Loop2& opening, const std::string& what, std::vector<int> patches) {
        // The compensated path runs half a kerf inside the opening on every side.
        if (!offset_paths(counter_clockwise_paths({opening}), -0.5 * kerf).empty())
            return;
        const double keeps = std::floor(2.0 * inner_radius(opening) * 1000.0) / 1000.0;
        std::ostringstream m;
        m.precision(4);
        m << what << " of " << piece_id << " closes under kerf compensation: kerf " << kerf
          << " mm, the largest kerf that keeps it open is " << keeps << " mm";
        diagnostics.push_back(Diagnostic::error(DiagnosticCode::kerf_closes_opening, m.str(),
                                                {std::move(patches), "kerf", std::nullopt}));
    };
    for (const SlitSlot& slot : piece.slots)
        check(slot.loop, "the slot of slit " + std::to_string(slot.slit), {slot.patch});
    for (size_t i = 0; i < piece.flat.holes.size(); ++i)
        for (size_t h = 0; h < piece.flat.holes[i].size(); ++h)
            check(piece.flat.holes[i][h],
                  "hole " + std::to_string(h + 1) + " of patch " +
                      std::to_string(piece.flat.patches[i]),
                  {piece.flat.patches[i]});
}

void add_slit_slots(const Scaffold& s, LocalPiece& piece)
{
    for (const Slit& slit : s.slits) {
        if (!piece.has(slit.patch_cut))
            continue;
        const Vec2 a = piece.flat_point(s, slit.patch_cut, slit.from);
        const Vec2 b = piece.flat_point(s, slit.patch_cut, slit.to);
        const Vec2 across = s.paper_thickness * left_normal((b - a).normalized());
        piece.slots.push_back(
            {slit.id, slit.patch_cut, {a - across, b - across, b + across, a + across}});
    }
}

void cut_outline(LocalPiece& piece, double kerf)
{
    std::vector<Loop2> paper = piece.flat.outlines;
    for (const GlueTab& t : piece.tabs)
        paper.push_back(t.polygon);
    std::vector<Loop2> openings;
    for (const SlitSlot& slot : piece.slots)
        openings.push_back(slot.loop);
    for (const auto& holes : piece.flat.holes)
        openings.insert(openings.end(), holes.begin(), holes.end());

    ClipperLib::Clipper merge;
    merge.AddPaths(counter_clockwise_paths(paper), ClipperLib::ptSubject, true);
    Paths merged;
    merge.Execute(ClipperLib::ctUnion, merged, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    // A tab held back from its crease's ends meets its patch between vertices, where rounding to
    // whole nanometres can leave a hairline gap: close it (grow, then shrink back).
    merged = offset_paths(offset_paths(merged, hairline), -hairline);

    ClipperLib::Clipper clipper;
    clipper.AddPaths(merged, ClipperLib::ptSubject, true);
    clipper.AddPaths(counter_clockwise_paths(openings), ClipperLib::ptClip, true);
    ClipperLib::PolyTree tree;
    clipper.Execute(ClipperLib::ctDifference, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    piece.cut_nominal.clear();
    collect_regions(tree, piece.cut_nominal);
    piece.cut = kerf > 0 ? offset(region_paths(piece.cut_nominal), 0.5 * kerf) : piece.cut_nominal;
}

void check_die_cutting(const LocalPiece& piece, const std::string& piece_id,
                       const SheetOptions& options, Diagnostics& diagnostics)
{
    const Paths nominal = region_paths(piece.cut_nominal);
    const double half = 0.5 * options.min_feature;
    const Paths opened = region_paths(offset(region_paths(offset(nominal, -half)), half));
    ClipperLib::Clipper clipper;
    clipper.AddPaths(nominal, ClipperLib::ptSubject, true);
    clipper.AddPaths(opened, ClipperLib::ptClip, true);
    Paths lost;
    clipper.Execute(ClipperLib::ctDifference, lost, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    // Slivers along the outline are rounding; a lost part at least half a feature across counts.
    const double significant = 0.25 * options.min_feature * options.min_feature;
    for (const ClipperLib::Path& part : lost) {
        if (path_area(part) < significant)
            continue;
        Vec2 centre = Vec2::Zero();
        for (const auto& p : part)
            centre += to_vec2(p);
        centre /= double(part.size());
        std::ostringstream m;
        m.precision(4);
        m << piece_id << " has paper narrower than " << options.min_feature << " mm near ("
          << centre.x() << ", " << centre.y() << ") in its own frame (" << path_area(part)
          << " mm² would break off or tear in die cutting)";
        diagnostics.push_back(Diagnostic::warning(DiagnosticCode::narrow_feature, m.str(),
                                                  about_patches(piece.flat.patches)));
    }

    const double limit = options.min_corner_angle * M_PI / 180.0;
    for (const Region& region : piece.cut_nominal) {
        const Loop2& loop = region.outer; // counter-clockwise: convex corners turn left
        const size_t n = loop.size();
        for (size_t i = 0; i < n; ++i) {
            const Vec2 in = loop[i] - loop[(i + n - 1) % n];
            const Vec2 out = loop[(i + 1) % n] - loop[i];
            const double turn = in.x() * out.y() - in.y() * out.x();
            const double corner =
                std::acos(std::clamp(-in.normalized().dot(out.normalized()), -1.0, 1.0));
            if (turn > 0 && corner < limit) {
                std::ostringstream m;
                m.precision(4);
                m << piece_id << " has a " << corner * 180.0 / M_PI << "° corner at ("
                  << loop[i].x() << ", " << loop[i].y() << "), sharper than "
                  << options.min_corner_angle << "°: round it for die cutting";
                diagnostics.push_back(Diagnostic::warning(DiagnosticCode::sharp_corner, m.str(),
                                                          about_patches(piece.flat.patches)));
            }
        }
    }
}

} // namespace popup::sheets
