// True-shape nesting with no-fit polygons and bottom-left placement (the placement of SVGnest and
// Deepnest). Sheets are filled one at a time: shapes are offered in an order, and each one that
// still fits takes its lowest, then leftmost, spot over its allowed quarter turns. The sheet keeps
// the fill, among a few orders, that covers the most area: the usual greedy orders (largest
// area, longest side, largest bounding box, widest) and then swaps of two shapes in the best one
// (a short hill climb, seeded, so every run gives the same nesting).
// Spots come from Clipper: the inner-fit rectangle minus the union of the no-fit polygons with
// the shapes already on the sheet (each the union of the sums of convex parts). Outlines are grown
// by half the spacing (plus a hair against rounding) so that touching grown outlines keep the full
// spacing. Only outer loops count: no shape goes into another's hole (holes in pop-up pieces are
// slits and windows, seldom roomy).
#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <numeric>
#include <optional>
#include <random>
#include <tuple>

#include "convex_hull.hpp"
#include "convex_parts.hpp"
#include "nest_input.hpp"
#include "no_fit_polygon.hpp"
#include "popup/sheets/nest.hpp"
#include "quarter_turn.hpp"

namespace popup {

namespace {

using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;
using nest_detail::Bounds;
using nest_detail::Outline;

constexpr int kSwapsPerSheet = 12;          // orders tried per sheet after the greedy ones
constexpr std::size_t kMaxConvexParts = 16; // see orientations_of
constexpr double kSafety = 1e-4; // mm added to half the spacing: Clipper rounds to whole nm

/// One allowed quarter turn of a shape, in a frame where the turned outline's bounding box
/// starts at the origin.
struct Orientation {
    int quarter_turns = 0;
    IntPoint frame_origin; ///< the turned shape's point that sits at the frame's origin
    cInt width = 0;        ///< of the outline (not grown)
    cInt height = 0;
    std::vector<Path> grown_parts; ///< convex parts of the outline grown by half the spacing
    Bounds grown_box;
};

struct Variants {
    std::vector<Orientation> orientations;
    std::size_t first_twin = 0; ///< the first shape with the same outline: shares no-fit polygons
};

struct Placed {
    std::size_t shape = 0;
    std::size_t orientation = 0;
    IntPoint position; ///< of the frame's origin on the sheet
};

struct Sheet {
    std::vector<Placed> placed;
    double used_area = 0.0;  ///< of the outlines, mm²
    std::size_t content = 0; ///< equal for sheets holding the same outlines at the same spots
};

bool same_loop(const Path& a, const Path& b)
{
    if (a.size() != b.size())
        return false;
    const auto start = std::find(b.begin(), b.end(), a.front());
    if (start == b.end())
        return false;
    const std::size_t offset = static_cast<std::size_t>(start - b.begin());
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!(a[i] == b[(i + offset) % b.size()]))
            return false;
    return true;
}

Path grown_outline(const Path& outline, double spacing)
{
    // Mitred corners keep rectangles rectangular; a mitre contains the round offset it replaces.
    ClipperLib::ClipperOffset offset;
    offset.AddPath(outline, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
    Paths grown;
    offset.Execute(grown, (0.5 * spacing + kSafety) * clipper_scale);
    // A narrow inlet may close into a hole; the outer loop is the one with the largest area.
    return *std::max_element(grown.begin(), grown.end(), [](const Path& a, const Path& b) {
        return ClipperLib::Area(a) < ClipperLib::Area(b);
    });
}

/// The allowed quarter turns of one outline; a turn that only shifts the outline (a rectangle
/// turned by a half) is left out.
std::vector<Orientation> orientations_of(const Outline& outline, const NestOptions& options)
{
    const Path grown = grown_outline(outline.path, options.spacing);
    std::vector<Path> grown_parts = nest_detail::convex_parts(grown);
    // A wiggly outline (a model's silhouette) splits into many convex parts, and two shapes'
    // no-fit polygon grows with the product of their parts: past kMaxConvexParts the grown
    // outline's convex hull, which contains it, stands in (the piece nests a little looser and
    // never overlaps another).
    if (grown_parts.size() > kMaxConvexParts)
        grown_parts = {nest_detail::convex_hull(grown)};
    std::vector<Orientation> orientations;
    std::vector<Path> turned_outlines;
    for (int quarter_turns = 0; quarter_turns < (options.rotate ? 4 : 1); ++quarter_turns) {
        Path turned;
        for (const IntPoint& p : outline.path)
            turned.push_back(nest_detail::quarter_turn(p, quarter_turns));
        const Bounds box = nest_detail::bounds_of(turned);
        const IntPoint frame_origin{box.left, box.bottom};
        turned = nest_detail::translated(turned, {-frame_origin.X, -frame_origin.Y});
        if (std::any_of(turned_outlines.begin(), turned_outlines.end(),
                        [&](const Path& earlier) { return same_loop(turned, earlier); }))
            continue;
        turned_outlines.push_back(turned);

        Orientation orientation;
        orientation.quarter_turns = quarter_turns;
        orientation.frame_origin = frame_origin;
        orientation.width = box.width();
        orientation.height = box.height();
        const auto to_frame = [&](const Path& path) {
            Path turned_path;
            for (const IntPoint& p : path) {
                const IntPoint q = nest_detail::quarter_turn(p, quarter_turns);
                turned_path.push_back({q.X - frame_origin.X, q.Y - frame_origin.Y});
            }
            return turned_path;
        };
        for (const Path& part : grown_parts)
            orientation.grown_parts.push_back(to_frame(part));
        orientation.grown_box = nest_detail::bounds_of(to_frame(grown));
        orientations.push_back(std::move(orientation));
    }
    return orientations;
}

/// Bottom-left order of spots: lowest bottom edge, then leftmost; earlier turns win ties.
struct Spot {
    std::size_t orientation = 0;
    IntPoint position;
    bool operator<(const Spot& other) const
    {
        return std::tie(position.Y, position.X, orientation) <
               std::tie(other.position.Y, other.position.X, other.orientation);
    }
};

class Nester {
public:
    Nester(const std::vector<Outline>& outlines, const NestOptions& options)
        : outlines_(outlines), printable_(nest_detail::printable_area(options))
    {
        for (std::size_t i = 0; i < outlines.size(); ++i) {
            Variants variants;
            variants.first_twin = i;
            for (std::size_t j = 0; j < i; ++j) {
                if (outlines[j].path == outlines[i].path) {
                    variants.first_twin = variants_[j].first_twin;
                    break;
                }
            }
            variants.orientations = variants.first_twin == i
                                        ? orientations_of(outlines[i], options)
                                        : variants_[variants.first_twin].orientations;
            variants_.push_back(std::move(variants));
        }
    }

    /// An empty sheet filled from `candidates`, in order, with every shape that still fits.
    Sheet fill_sheet(const std::vector<std::size_t>& candidates)
    {
        const double printable_mm2 = static_cast<double>(printable_.width()) * printable_.height() /
                                     (clipper_scale * clipper_scale);
        Sheet sheet;
        for (std::size_t shape : candidates) {
            // Outlines never overlap, so a sheet without the area left has no room either.
            if (sheet.used_area + outlines_[shape].area > printable_mm2)
                continue;
            if (const std::optional<Spot> spot = best_spot(shape, sheet))
                add(sheet, {shape, spot->orientation, spot->position});
        }
        return sheet;
    }

    /// How high the sheet is filled: of two fills covering as much, the lower leaves more room.
    cInt top_of(const Sheet& sheet) const
    {
        cInt top = 0;
        for (const Placed& placed : sheet.placed)
            top =
                std::max(top, placed.position.Y +
                                  variants_[placed.shape].orientations[placed.orientation].height);
        return top;
    }

    Nesting nesting(const std::vector<Sheet>& sheets) const
    {
        Nesting result;
        result.placements.resize(outlines_.size());
        for (std::size_t s = 0; s < sheets.size(); ++s) {
            for (const Placed& placed : sheets[s].placed) {
                const Orientation& orientation =
                    variants_[placed.shape].orientations[placed.orientation];
                Placement& placement = result.placements[placed.shape];
                placement.sheet = static_cast<int>(s);
                placement.rotation_deg = 90.0 * orientation.quarter_turns;
                // sheet point = turned (p - shift) - frame_origin + position, in units
                placement.translation = to_vec2({placed.position.X - orientation.frame_origin.X,
                                                 placed.position.Y - orientation.frame_origin.Y}) -
                                        nest_detail::quarter_turn(outlines_[placed.shape].shift,
                                                                  orientation.quarter_turns);
            }
        }
        result.sheet_count = static_cast<int>(sheets.size());
        return result;
    }

private:
    void add(Sheet& sheet, const Placed& placed)
    {
        const auto content = contents_.emplace(
            std::make_tuple(sheet.content, variants_[placed.shape].first_twin, placed.orientation,
                            placed.position.X, placed.position.Y),
            contents_.size() + 1);
        sheet.content = content.first->second;
        sheet.placed.push_back(placed);
        sheet.used_area += outlines_[placed.shape].area;
    }

    std::optional<Spot> best_spot(std::size_t shape, const Sheet& sheet)
    {
        std::optional<Spot> best;
        const std::vector<Orientation>& orientations = variants_[shape].orientations;
        for (std::size_t o = 0; o < orientations.size(); ++o) {
            const std::optional<IntPoint> position = cached_lowest_spot(shape, o, sheet);
            if (position && (!best || Spot{o, *position} < *best))
                best = Spot{o, *position};
        }
        return best;
    }

    /// Orders that start alike fill a sheet alike for a while: spots are remembered per content.
    std::optional<IntPoint> cached_lowest_spot(std::size_t shape, std::size_t o, const Sheet& sheet)
    {
        const auto key = std::make_tuple(sheet.content, variants_[shape].first_twin, o);
        auto found = lowest_spots_.find(key);
        if (found == lowest_spots_.end())
            found = lowest_spots_.emplace(key, lowest_spot(shape, o, sheet)).first;
        return found->second;
    }

    /// The bottom-left position of the shape in this orientation on the sheet, if any.
    std::optional<IntPoint> lowest_spot(std::size_t shape, std::size_t o, const Sheet& sheet)
    {
        const Orientation& moving = variants_[shape].orientations[o];
        // Inner-fit rectangle: the frame origin keeps the outline within the printable area.
        const Bounds inner_fit{printable_.left, printable_.bottom, printable_.right - moving.width,
                               printable_.top - moving.height};
        if (inner_fit.width() < 0 || inner_fit.height() < 0)
            return std::nullopt;
        // Clipper drops a zero-width rectangle: widen it by one unit (a nanometre, far inside
        // the safety added to the spacing) and clamp the spot back.
        const cInt right = std::max(inner_fit.right, inner_fit.left + 1);
        const cInt top = std::max(inner_fit.top, inner_fit.bottom + 1);

        ClipperLib::Clipper clipper;
        clipper.AddPath({{inner_fit.left, inner_fit.bottom},
                         {right, inner_fit.bottom},
                         {right, top},
                         {inner_fit.left, top}},
                        ClipperLib::ptSubject, true);
        for (const Placed& placed : sheet.placed) {
            const Bounds& fixed_box =
                variants_[placed.shape].orientations[placed.orientation].grown_box;
            // The no-fit polygon lies within the sum of the boxes; skip it when that misses.
            if (placed.position.X + fixed_box.right - moving.grown_box.left <= inner_fit.left ||
                placed.position.X + fixed_box.left - moving.grown_box.right >= right ||
                placed.position.Y + fixed_box.top - moving.grown_box.bottom <= inner_fit.bottom ||
                placed.position.Y + fixed_box.bottom - moving.grown_box.top >= top)
                continue;
            for (const Path& loop : cached_no_fit_polygon(placed, shape, o))
                clipper.AddPath(nest_detail::translated(loop, placed.position), ClipperLib::ptClip,
                                true);
        }
        Paths free;
        clipper.Execute(ClipperLib::ctDifference, free, ClipperLib::pftNonZero,
                        ClipperLib::pftNonZero);

        std::optional<IntPoint> lowest;
        for (const Path& loop : free) {
            for (const IntPoint& p : loop) {
                const IntPoint spot{std::min(p.X, inner_fit.right), std::min(p.Y, inner_fit.top)};
                if (!lowest || std::tie(spot.Y, spot.X) < std::tie(lowest->Y, lowest->X))
                    lowest = spot;
            }
        }
        return lowest;
    }

    const Paths& cached_no_fit_polygon(const Placed& fixed, std::size_t shape, std::size_t o)
    {
        const std::array<std::size_t, 4> key{variants_[fixed.shape].first_twin, fixed.orientation,
                                             variants_[shape].first_twin, o};
        auto found = no_fit_polygons_.find(key);
        if (found == no_fit_polygons_.end()) {
            const std::vector<Path>& fixed_parts =
                variants_[fixed.shape].orientations[fixed.orientation].grown_parts;
            const std::vector<Path>& moving_parts = variants_[shape].orientations[o].grown_parts;
            found = no_fit_polygons_
                        .emplace(key, nest_detail::no_fit_polygon(fixed_parts, moving_parts))
                        .first;
        }
        return found->second;
    }

    const std::vector<Outline>& outlines_;
    const Bounds printable_;
    std::vector<Variants> variants_;
    std::map<std::array<std::size_t, 4>, Paths> no_fit_polygons_;
    /// Sheet contents as a tree: (content before, twin, orientation, position) -> content.
    std::map<std::tuple<std::size_t, std::size_t, std::size_t, cInt, cInt>, std::size_t> contents_;
    std::map<std::tuple<std::size_t, std::size_t, std::size_t>, std::optional<IntPoint>>
        lowest_spots_;
};

/// The shapes by decreasing size; equal sizes keep their order.
std::vector<std::size_t> largest_first(std::vector<std::size_t> shapes,
                                       const std::vector<Outline>& outlines,
                                       const std::function<double(const Outline&)>& size)
{
    std::stable_sort(shapes.begin(), shapes.end(), [&](std::size_t a, std::size_t b) {
        return size(outlines[a]) > size(outlines[b]);
    });
    return shapes;
}

} // namespace

Result<Nesting> nest_shapes(const std::vector<NestShape>& shapes, const NestOptions& options)
{
    const Result<std::vector<Outline>> prepared = nest_detail::prepare_outlines(shapes, options);
    if (!prepared.ok)
        return nest_detail::failed_nesting(prepared);
    const std::vector<Outline>& outlines = prepared.value;
    const std::array<std::function<double(const Outline&)>, 4> sizes{
        [](const Outline& o) { return o.area; },
        [](const Outline& o) { return static_cast<double>(std::max(o.width, o.height)); },
        [](const Outline& o) { return static_cast<double>(o.width) * o.height; },
        [](const Outline& o) { return static_cast<double>(std::min(o.width, o.height)); },
    };

    Nester nester(outlines, options);
    std::mt19937 random(20261122u); // its output is fixed by the standard; the % below too
    std::vector<std::size_t> remaining(outlines.size());
    std::iota(remaining.begin(), remaining.end(), 0);
    std::vector<Sheet> sheets;
    while (!remaining.empty()) {
        Sheet best;
        std::vector<std::size_t> best_order;
        const auto try_order = [&](const std::vector<std::size_t>& order) {
            Sheet sheet = nester.fill_sheet(order);
            if (best_order.empty() || std::make_tuple(sheet.used_area, -nester.top_of(sheet)) >
                                          std::make_tuple(best.used_area, -nester.top_of(best))) {
                best = std::move(sheet);
                best_order = order;
            }
        };
        for (const auto& size : sizes)
            try_order(largest_first(remaining, outlines, size));
        for (int swap = 0; swap < kSwapsPerSheet && best.placed.size() < remaining.size(); ++swap) {
            std::vector<std::size_t> order = best_order;
            std::swap(order[random() % order.size()], order[random() % order.size()]);
            try_order(order);
        }

        const auto on_sheet = [&](std::size_t shape) {
            return std::any_of(best.placed.begin(), best.placed.end(),
                               [&](const Placed& placed) { return placed.shape == shape; });
        };
        remaining.erase(std::remove_if(remaining.begin(), remaining.end(), on_sheet),
                        remaining.end());
        sheets.push_back(std::move(best));
    }
    Result<Nesting> result;
    result.value = nester.nesting(sheets);
    return result;
}

} // namespace popup
