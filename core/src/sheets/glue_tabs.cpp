#include "glue_tabs.hpp"

#include "popup/sheets/sheet_set.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <tuple>

#include "../geometry/polygon_2d.hpp"
#include "clipper_ops.hpp"

namespace popup::sheets {

namespace {

constexpr double overlap_tolerance = 1e-4; // mm²: touching along an edge is not overlapping
constexpr double narrowing = 0.85;         // each retry keeps this share of the width
// A tab's far edge keeps a tenth of its crease: its depth is at most this share of the crease
// times tan(tab_angle).
constexpr double depth_per_crease = 0.45;
// Where the paper is in the way, a tab is held back from each end of its crease by these shares.
constexpr double insets[] = {0.0, 0.1, 0.2};

// A trapezoid standing on the segment from→to, `depth` deep toward `side` (a unit normal),
// its sides leaning in at `angle` (radians) from the segment. The first edge is the segment.
Loop2 trapezoid(const Vec2& from, const Vec2& to, const Vec2& side, double depth, double angle)
{
    const Vec2 along = (to - from).normalized();
    const double lean = angle >= M_PI / 2 ? 0.0 : depth / std::tan(angle);
    return {from, to, to + depth * side - lean * along, from + depth * side + lean * along};
}

// Unit normal to the segment pointing away from `away_from`.
Vec2 outward(const Vec2& from, const Vec2& to, const Vec2& away_from)
{
    Vec2 n = left_normal((to - from).normalized());
    return n.dot(away_from - from) > 0 ? Vec2(-n) : n;
}

Vec2 mean(const Loop2& loop)
{
    Vec2 sum = Vec2::Zero();
    for (const Vec2& p : loop)
        sum += p;
    return sum / double(loop.size());
}

// The segment runs through the polygon's inside (touching its edge is not crossing).
bool crosses(const Loop2& polygon, const Vec2& a, const Vec2& b)
{
    constexpr int samples = 64;
    for (int k = 1; k < samples; ++k) {
        const Vec2 q = a + (b - a) * (double(k) / samples);
        if (point_in_polygon_or_near(polygon, q, -1e-6))
            return true;
    }
    return false;
}

std::string patch_name(const Scaffold& s, int id)
{
    return patch_subject(*s.find_patch(id));
}

} // namespace

std::string tab_code(int index)
{
    std::string code;
    for (int k = index + 1; k > 0; k = (k - 1) / 26)
        code.insert(code.begin(), char('A' + (k - 1) % 26));
    return code;
}

namespace {

struct Fit {
    Loop2 tab, area;
    double width = 0.0;
    bool front = true;                            ///< the tab lies on the target's printed side
    FoldDirection crease = FoldDirection::valley; ///< seen from the carrier's printed side
};

// The widest tab from `carrier_patch` (on `carrier`) onto `target_patch` (on `target`) along the
// joint h that overlaps nothing; width 0 when even the narrowest does.
Fit fit_tab(const Scaffold& s, const Hinge& h, const LocalPiece& carrier, int carrier_patch,
            const LocalPiece& target, int target_patch, const BendSamples& bends,
            const SheetOptions& options, const std::vector<Loop2>& reserved = {})
{
    bool bent = false;
    const bool front =
        bend_direction(s, bends, target_patch, target.printed_normal(s, target_patch),
                       carrier_patch, h.from, bent) == FoldDirection::valley;
    const double angle = options.tab_angle * M_PI / 180.0;
    const Vec2 a = carrier.flat_point(s, carrier_patch, h.from);
    const Vec2 b = carrier.flat_point(s, carrier_patch, h.to);
    const Vec2 ta = target.flat_point(s, target_patch, h.from);
    const Vec2 tb = target.flat_point(s, target_patch, h.to);
    const Vec2 away = outward(a, b, mean(carrier.outline(carrier_patch)));
    const Vec2 into = -outward(ta, tb, mean(target.outline(target_patch)));
    // Keep the tab's far edge at least a tenth of the crease.
    const double widest =
        angle >= M_PI / 2 ? options.tab_width : depth_per_crease * (b - a).norm() * std::tan(angle);

    std::vector<Loop2> own = carrier.flat.outlines;
    for (const GlueTab& t : carrier.tabs)
        own.push_back(t.polygon);
    std::vector<Loop2> taken = reserved;
    for (const GlueArea& g : target.glue)
        if (g.front == front) // the paper's other face is free
            taken.push_back(g.polygon);
    // Where other pieces stand on the target patch's same face: a glue area reaching under them
    // would be glued over by their own tabs.
    std::vector<std::array<Vec2, 2>> standing;
    for (const Hinge& other : s.hinges) {
        if (other.kind != JointKind::tab || other.id == h.id ||
            (other.patch_a != target_patch && other.patch_b != target_patch))
            continue;
        const int on = other.patch_a == target_patch ? other.patch_b : other.patch_a;
        const bool on_front =
            bend_direction(s, bends, target_patch, target.printed_normal(s, target_patch), on,
                           other.from, bent) == FoldDirection::valley;
        if (on_front == front) // a piece on the paper's other face is no obstacle
            standing.push_back({target.flat_point(s, target_patch, other.from),
                                target.flat_point(s, target_patch, other.to)});
    }
    const int slot = target.index_of.at(target_patch);
    const Loop2& paper = target.flat.outlines[slot];
    const std::vector<Loop2>& paper_holes = target.flat.holes[slot];
    // A crease inside the target's paper leaves room on both sides: prefer the inner side.
    // Tabs held back from the crease's ends clear acute corners next to them.
    for (double width = std::min(options.tab_width, widest); width >= options.min_tab_width - 1e-9;
         width *= narrowing)
        for (double inset : insets)
            for (const Vec2& side : {into, Vec2(-into)}) {
                const Vec2 ia = a + inset * (b - a), ib = b - inset * (b - a);
                const Vec2 ita = ta + inset * (tb - ta), itb = tb - inset * (tb - ta);
                Fit fit{trapezoid(ia, ib, away, width, angle),
                        trapezoid(ita, itb, side, width, angle), width, front};
                if (overlap_area({fit.tab}, own) <= overlap_tolerance &&
                    area_outside(fit.area, paper, paper_holes) <= overlap_tolerance &&
                    overlap_area({fit.area}, taken) <= overlap_tolerance &&
                    std::none_of(standing.begin(), standing.end(), [&](const auto& line) {
                        return crosses(fit.area, line[0], line[1]);
                    })) {
                    // The crease folds the tab onto the side of the joint its area is on.
                    fit.crease = tab_direction(s, bends, h, carrier, carrier_patch, target,
                                               target_patch, mean(fit.area), bent);
                    return fit;
                }
            }
    return {};
}

// A joint along a crease that already has a tab on the same patch (a panel standing on the
// central fold is joined to both pages along one edge): one tab holds both. The joint may be
// only part of that crease (an outline cut the other patch's edge short, e.g. a box's profiled
// top half beside its whole centre wall): the tab glued along the whole crease holds it too.
// verify_sheets accepts the same (joint within a tab's crease).
bool already_tabbed(const Scaffold& s, const Hinge& h, const std::vector<LocalPiece>& pieces,
                    const std::map<int, int>& position)
{
    for (int patch : {h.patch_a, h.patch_b}) {
        const LocalPiece& piece = pieces[position.at(patch)];
        const Vec2 a = piece.flat_point(s, patch, h.from), b = piece.flat_point(s, patch, h.to);
        auto same = [&](const Vec2& p, const Vec2& q) {
            const double tol = 1e-6 * std::max(s.size(), 1.0);
            return distance_to_segment(a, p, q) <= tol && distance_to_segment(b, p, q) <= tol;
        };
        for (const GlueTab& t : piece.tabs)
            if (t.patch == patch && same(t.polygon[0], t.polygon[1]))
                return true;
        for (const GlueArea& g : piece.glue)
            if (g.patch == patch && same(g.polygon[0], g.polygon[1]))
                return true;
    }
    return false;
}

const Hinge& hinge_by_id(const Scaffold& s, int id)
{
    return *std::find_if(s.hinges.begin(), s.hinges.end(),
                         [&](const Hinge& h) { return h.id == id; });
}

// When a joint finds no room, the glue areas already in its way may narrow to leave it the
// narrowest tab: each is fitted again around that reservation. Returns the joint's fit (width 0
// when that fails too, and then `pieces` is as it was).
Fit fit_making_room(const Scaffold& s, const Hinge& h, std::vector<LocalPiece>& pieces,
                    const std::map<int, int>& position, int carrier_patch, int target_patch,
                    const BendSamples& bends, const SheetOptions& options)
{
    const double angle = options.tab_angle * M_PI / 180.0;
    LocalPiece& target = pieces[position.at(target_patch)];
    const Vec2 ta = target.flat_point(s, target_patch, h.from);
    const Vec2 tb = target.flat_point(s, target_patch, h.to);
    const Vec2 into = -outward(ta, tb, mean(target.outline(target_patch)));
    for (const Vec2& side : {into, Vec2(-into)}) {
        const Loop2 need = trapezoid(ta, tb, side, options.min_tab_width, angle);
        const std::vector<LocalPiece> before = pieces;
        std::vector<GlueArea> in_the_way;
        for (const GlueArea& g : pieces[position.at(target_patch)].glue)
            if (overlap_area({need}, {g.polygon}) > overlap_tolerance)
                in_the_way.push_back(g);
        bool moved = !in_the_way.empty();
        for (const GlueArea& g : in_the_way) {
            LocalPiece& other = pieces[g.tab_piece];
            LocalPiece& under = pieces[position.at(g.patch)];
            const auto tab = std::find_if(other.tabs.begin(), other.tabs.end(),
                                          [&](const GlueTab& t) { return t.hinge == g.hinge; });
            const GlueTab kept = *tab;
            other.tabs.erase(tab);
            other.folds.erase(
                std::find_if(other.folds.begin(), other.folds.end(), [&](const FoldLine& f) {
                    return f.kind == JointKind::tab && f.hinge == g.hinge;
                }));
            under.glue.erase(std::find_if(under.glue.begin(), under.glue.end(),
                                          [&](const GlueArea& a) { return a.hinge == g.hinge; }));
            const Fit refit = fit_tab(s, hinge_by_id(s, g.hinge), other, kept.patch, under, g.patch,
                                      bends, options, {need});
            if (refit.width == 0.0) {
                moved = false;
                break;
            }
            other.tabs.push_back({kept.code, kept.hinge, kept.patch, refit.tab, refit.width,
                                  kept.target_piece, kept.target_patch, refit.front});
            other.folds.push_back(
                {g.hinge, refit.tab[0], refit.tab[1], refit.crease, JointKind::tab});
            under.glue.push_back({g.code, g.hinge, g.patch, refit.area, g.tab_piece, refit.front});
        }
        if (moved) {
            const Fit fit =
                fit_tab(s, h, pieces[position.at(carrier_patch)], carrier_patch,
                        pieces[position.at(target_patch)], target_patch, bends, options);
            if (fit.width > 0.0)
                return fit;
        }
        pieces = before;
    }
    return {};
}

} // namespace

void add_glue_tabs(const Scaffold& s, std::vector<LocalPiece>& pieces,
                   const std::map<int, int>& position, const BendSamples& bends,
                   const SheetOptions& options, Diagnostics& diagnostics)
{
    int next_code = 0;
    for (size_t k = 0; k < pieces.size(); ++k) {
        for (const Hinge& h : s.hinges) {
            if (h.kind != JointKind::tab)
                continue;
            const int pa = position.at(h.patch_a), pb = position.at(h.patch_b);
            if (pa == pb || size_t(std::max(pa, pb)) != k || already_tabbed(s, h, pieces, position))
                continue;
            // The later piece carries the tab onto the earlier one, already in place; where it
            // has no room (its crease inside the later piece), the earlier one carries it.
            const int later = pa > pb ? h.patch_a : h.patch_b;
            const int earlier = pa > pb ? h.patch_b : h.patch_a;
            int carrier_patch = later, target_patch = earlier;
            Fit fit = fit_tab(s, h, pieces[position.at(later)], later, pieces[position.at(earlier)],
                              earlier, bends, options);
            if (fit.width == 0.0) {
                std::swap(carrier_patch, target_patch);
                fit = fit_tab(s, h, pieces[position.at(earlier)], earlier,
                              pieces[position.at(later)], later, bends, options);
            }
            for (const auto& [carrier, target] :
                 {std::pair(later, earlier), std::pair(earlier, later)})
                if (fit.width == 0.0) {
                    std::tie(carrier_patch, target_patch) = std::tie(carrier, target);
                    fit = fit_making_room(s, h, pieces, position, carrier, target, bends, options);
                }
            const DiagnosticSubject joined = about_patches({h.patch_a, h.patch_b});
            if (fit.width == 0.0) {
                diagnostics.push_back(Diagnostic::error(
                    DiagnosticCode::no_room_for_tab,
                    "hinge " + std::to_string(h.id) + ": no glue tab of at least " +
                        std::to_string(options.min_tab_width) + " mm fits between " +
                        patch_name(s, later) + " and " + patch_name(s, earlier) +
                        ": glue them by hand",
                    joined));
                continue;
            }
            const std::string code = tab_code(next_code++);
            if (fit.width < options.tab_width - 1e-9) {
                std::ostringstream m;
                m.precision(3);
                m << "glue tab " << code << " narrowed to " << fit.width << " mm (asked "
                  << options.tab_width << " mm) to fit its crease and the paper around it";
                diagnostics.push_back(
                    Diagnostic::warning(DiagnosticCode::narrow_tab, m.str(), joined));
            }
            LocalPiece& carrier = pieces[position.at(carrier_patch)];
            LocalPiece& target = pieces[position.at(target_patch)];
            const int target_piece = position.at(target_patch);
            carrier.tabs.push_back({code, h.id, carrier_patch, fit.tab, fit.width, target_piece,
                                    target_patch, fit.front});
            carrier.folds.push_back({h.id, fit.tab[0], fit.tab[1], fit.crease, JointKind::tab});
            target.glue.push_back(
                {code, h.id, target_patch, fit.area, position.at(carrier_patch), fit.front});
        }
    }
}

} // namespace popup::sheets

namespace popup {

double shortest_tabbed_crease(const SheetOptions& options)
{
    const double angle = options.tab_angle * M_PI / 180.0;
    if (angle >= M_PI / 2)
        return options.min_tab_width;
    return std::max(options.min_tab_width,
                    options.min_tab_width / (sheets::depth_per_crease * std::tan(angle) *
                                             (1.0 - 2.0 * sheets::insets[2])));
}

} // namespace popup
