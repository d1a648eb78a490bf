// Cutting sheets (issue 4): pieces, tabs, folds, labels, assembly order, nesting, kerf and the
// round trip, on every mechanism type and the demo card.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include <nlohmann/json.hpp>
#include <polyclipping/clipper.hpp>

#include "popup/io/sheet_json.hpp"
#include "popup/mechanisms/floating_layer.hpp"
#include "popup/mechanisms/rotation_arm.hpp"
#include "popup/model/card.hpp"
#include "popup/sheets/sheet_layout.hpp"
#include "sheet_designs.hpp"
#include "validity_cases.hpp"

using namespace popup;

namespace {

constexpr double scale = 1e6;     // Clipper units per mm, as in the core
constexpr double touching = 1e-4; // mm²: shared edges are not overlaps

ClipperLib::Path path_of(const Loop2& loop)
{
    ClipperLib::Path p;
    for (const Vec2& v : loop)
        p.push_back({ClipperLib::cInt(std::llround(v.x() * scale)),
                     ClipperLib::cInt(std::llround(v.y() * scale))});
    if (!ClipperLib::Orientation(p))
        ClipperLib::ReversePath(p);
    return p;
}

double area(const ClipperLib::Paths& paths)
{
    double a = 0;
    for (const auto& p : paths)
        a += ClipperLib::Area(p) / (scale * scale);
    return a;
}

// Area (mm²) of the Clipper operation between two loops.
double clipped(const Loop2& a, const Loop2& b, ClipperLib::ClipType operation)
{
    ClipperLib::Clipper c;
    c.AddPath(path_of(a), ClipperLib::ptSubject, true);
    c.AddPath(path_of(b), ClipperLib::ptClip, true);
    ClipperLib::Paths out;
    c.Execute(operation, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    return area(out);
}

double overlap(const Loop2& a, const Loop2& b)
{
    return clipped(a, b, ClipperLib::ctIntersection);
}

double outside(const Loop2& a, const Loop2& region)
{
    return clipped(a, region, ClipperLib::ctDifference);
}

double segment_distance(const Vec2& p, const Vec2& q, const Vec2& a, const Vec2& b)
{
    auto point_segment = [](const Vec2& x, const Vec2& s, const Vec2& t) {
        const Vec2 d = t - s;
        const double u = std::clamp((x - s).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
        return (s + u * d - x).norm();
    };
    const Vec2 r = q - p, s = b - a;
    const double den = r.x() * s.y() - r.y() * s.x();
    if (std::abs(den) > 1e-300) {
        const Vec2 w = a - p;
        const double t = (w.x() * s.y() - w.y() * s.x()) / den;
        const double u = (w.x() * r.y() - w.y() * r.x()) / den;
        if (t >= 0 && t <= 1 && u >= 0 && u <= 1)
            return 0.0;
    }
    return std::min({point_segment(p, a, b), point_segment(q, a, b), point_segment(a, p, q),
                     point_segment(b, p, q)});
}

double loop_distance(const Loop2& a, const Loop2& b)
{
    double d = 1e300;
    for (size_t i = 0; i < a.size(); ++i)
        for (size_t j = 0; j < b.size(); ++j)
            d = std::min(
                d, segment_distance(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()]));
    return d;
}

SheetOptions a3()
{
    SheetOptions o;
    o.nest.paper = paper_by_name("A3").value;
    return o;
}

std::vector<std::string> errors_of(const SheetSet& set)
{
    std::vector<std::string> errors;
    for (const Diagnostic& d : set.diagnostics)
        if (d.severity == Severity::error)
            errors.push_back(d.message);
    return errors;
}

// Everything a cutter and a maker rely on, for one laid-out design.
void expect_usable(const Scaffold& s, const SheetSet& set, const std::string& name)
{
    SCOPED_TRACE(name);
    EXPECT_TRUE(errors_of(set).empty()) << errors_of(set).front();
    EXPECT_TRUE(set.round_trip.ok);
    EXPECT_LE(set.round_trip.max_error, 1e-6 * s.size());
    EXPECT_EQ(set.round_trip.angles, set.options.round_trip_angles);

    // Every patch once, exactly its own shape (edge lengths).
    std::multiset<int> seen;
    for (const SheetPiece& piece : set.pieces)
        for (const FlatPatch& fp : piece.patches) {
            seen.insert(fp.id);
            const Patch& p = *s.find_patch(fp.id);
            for (size_t i = 0; i < p.outer.size(); ++i) {
                const size_t j = (i + 1) % p.outer.size();
                EXPECT_NEAR((fp.outer[j] - fp.outer[i]).norm(), (p.outer[j] - p.outer[i]).norm(),
                            1e-9);
            }
        }
    EXPECT_EQ(seen.size(), s.patches.size());
    EXPECT_EQ(std::set<int>(seen.begin(), seen.end()).size(), s.patches.size());

    // Tabs overlap nothing of their own piece; glue areas lie on their patch, apart per side.
    std::map<std::string, int> tab_codes, glue_codes;
    for (const SheetPiece& piece : set.pieces) {
        for (size_t t = 0; t < piece.tabs.size(); ++t) {
            const GlueTab& tab = piece.tabs[t];
            ++tab_codes[tab.code];
            EXPECT_GE(tab.width, set.options.min_tab_width - 1e-9);
            for (const FlatPatch& fp : piece.patches)
                EXPECT_LE(overlap(tab.polygon, fp.outer), touching) << tab.code;
            for (size_t u = t + 1; u < piece.tabs.size(); ++u)
                EXPECT_LE(overlap(tab.polygon, piece.tabs[u].polygon), touching) << tab.code;
            // Its glue area: same code on the target piece, same crease length.
            const SheetPiece& target = set.pieces[tab.target_piece];
            const auto area = std::find_if(target.glue.begin(), target.glue.end(),
                                           [&](const GlueArea& g) { return g.code == tab.code; });
            ASSERT_NE(area, target.glue.end()) << tab.code;
            EXPECT_NEAR((area->polygon[1] - area->polygon[0]).norm(),
                        (tab.polygon[1] - tab.polygon[0]).norm(), 1e-9);
            EXPECT_EQ(area->front, tab.front);
        }
        for (size_t g = 0; g < piece.glue.size(); ++g) {
            const GlueArea& a = piece.glue[g];
            ++glue_codes[a.code];
            const auto on = std::find_if(piece.patches.begin(), piece.patches.end(),
                                         [&](const FlatPatch& fp) { return fp.id == a.patch; });
            ASSERT_NE(on, piece.patches.end());
            EXPECT_LE(outside(a.polygon, on->outer), touching) << a.code;
            for (size_t h = g + 1; h < piece.glue.size(); ++h)
                if (piece.glue[h].front == a.front) {
                    EXPECT_LE(overlap(a.polygon, piece.glue[h].polygon), touching) << a.code;
                }
        }
    }
    EXPECT_EQ(tab_codes, glue_codes);
    for (const auto& [code, count] : tab_codes)
        EXPECT_EQ(count, 1) << code;

    // Assembly: every piece but the card once, glued only to pieces placed before it.
    ASSERT_EQ(set.assembly.size(), set.pieces.size() - 1);
    for (size_t k = 0; k < set.assembly.size(); ++k) {
        const AssemblyStep& step = set.assembly[k];
        EXPECT_EQ(step.piece, int(k + 1));
        EXPECT_FALSE(step.joins.empty());
        for (const AssemblyJoin& j : step.joins) {
            const int other = j.tab_piece == step.piece ? j.target_piece : j.tab_piece;
            EXPECT_LT(other, step.piece);
        }
    }

    // On the paper, inside the margins, apart by the spacing.
    const NestOptions& n = set.options.nest;
    for (size_t i = 0; i < set.pieces.size(); ++i) {
        for (const Region& r : set.pieces[i].cut)
            for (const Vec2& p : r.outer) {
                EXPECT_GE(p.x(), n.margin - 1e-6);
                EXPECT_GE(p.y(), n.margin - 1e-6);
                EXPECT_LE(p.x(), n.paper.width - n.margin + 1e-6);
                EXPECT_LE(p.y(), n.paper.height - n.margin + 1e-6);
            }
        for (size_t j = i + 1; j < set.pieces.size(); ++j)
            if (set.pieces[i].sheet == set.pieces[j].sheet) {
                EXPECT_GE(
                    loop_distance(set.pieces[i].cut.front().outer, set.pieces[j].cut.front().outer),
                    n.spacing - 1e-6)
                    << set.pieces[i].id << " " << set.pieces[j].id;
            }
    }
    EXPECT_LE(set.sheet_count, set.shelf_sheet_count);
}

} // namespace

TEST(SheetLayout, EveryMechanismTypeLaysOutAndRefolds)
{
    for (const auto& design : fixtures::single_mechanism_cards()) {
        const Result<SheetSet> r = layout_sheets(design.scaffold, a3());
        ASSERT_TRUE(r.ok) << design.name << ": " << r.diagnostics.front().message;
        expect_usable(design.scaffold, r.value, design.name);
    }
}

TEST(SheetLayout, DemoCardFitsOneA3Sheet)
{
    const Scaffold s = fixtures::demo_card();
    const Result<SheetSet> r = layout_sheets(s, a3());
    ASSERT_TRUE(r.ok) << r.diagnostics.front().message;
    expect_usable(s, r.value, "demo");
    EXPECT_EQ(r.value.pieces.size(), 17u);
    EXPECT_EQ(r.value.sheet_count, 1);
    EXPECT_EQ(r.value.shelf_sheet_count, 2);
    // Re-read from the drawing (loops on Clipper's 1 nm grid, the kerf offset undone): within a
    // few nanometres, far inside the 1e-6 x card size tolerance.
    EXPECT_LT(r.value.round_trip.max_error, 1e-5);
}

TEST(SheetLayout, CentralFoldIsAValleyOnThePrintedInside)
{
    const Scaffold s = fixtures::single_mechanism_cards().front().scaffold;
    const SheetSet set = layout_sheets(s, a3()).value;
    const SheetPiece& card = set.pieces.front();
    ASSERT_EQ(card.folds.size(), 1u);
    EXPECT_EQ(card.folds[0].hinge, 0);
    EXPECT_EQ(card.folds[0].direction, FoldDirection::valley);
    EXPECT_EQ(card.id, "P1");
    // The tent's tabs: one onto each page, codes A and B in order.
    const SheetPiece& tent = set.pieces[1];
    ASSERT_EQ(tent.tabs.size(), 2u);
    EXPECT_EQ(tent.tabs[0].code, "A");
    EXPECT_EQ(tent.tabs[1].code, "B");
    EXPECT_EQ(card.glue.size(), 2u);
}

TEST(SheetLayout, KerfMovesCutLinesOutByHalfOfIt)
{
    const Scaffold s = fixtures::single_mechanism_cards().front().scaffold;
    SheetOptions o = a3();
    o.kerf = 0.4;
    o.min_gap = 0.5;
    const SheetSet set = layout_sheets(s, o).value;
    const SheetPiece& card = set.pieces.front();
    Eigen::AlignedBox2d nominal, cut;
    for (const Vec2& p : card.cut_nominal.front().outer)
        nominal.extend(p);
    for (const Vec2& p : card.cut.front().outer)
        cut.extend(p);
    EXPECT_NEAR(cut.sizes().x() - nominal.sizes().x(), 0.4, 1e-5);
    EXPECT_NEAR(cut.sizes().y() - nominal.sizes().y(), 0.4, 1e-5);
    // The card is its two pages: 200 × 280 mm nominal.
    EXPECT_NEAR(std::min(nominal.sizes().x(), nominal.sizes().y()), 200.0, 1e-5);
    EXPECT_NEAR(std::max(nominal.sizes().x(), nominal.sizes().y()), 280.0, 1e-5);
}

TEST(SheetLayout, KerfNeverClosesASlotOrAHole)
{
    Scaffold s;
    for (const fixtures::NamedDesign& d : fixtures::single_mechanism_cards())
        if (d.name == "horizontal translation")
            s = d.scaffold;
    ASSERT_EQ(s.slits.size(), 1u);
    const int slit = s.slits.front().id;
    const double slot_width = 2.0 * s.paper_thickness; // a slot is two paper thicknesses wide
    // A 0.6 × 20 mm hole in the ground, clockwise seen from above, clear of the mechanism.
    const double hole_width = 0.6, hole_length = 20.0;
    Patch& ground = *std::find_if(s.patches.begin(), s.patches.end(),
                                  [&](const Patch& p) { return p.id == s.ground; });
    ground.holes.push_back({{20, 10, 0},
                            {20, 10 + hole_length, 0},
                            {20 + hole_width, 10 + hole_length, 0},
                            {20 + hole_width, 10, 0}});
    for (double kerf : {0.0, 0.1, 0.3, 0.5}) {
        SCOPED_TRACE("kerf " + std::to_string(kerf));
        SheetOptions o = a3();
        o.kerf = kerf;
        const Result<SheetSet> r = layout_sheets(s, o);
        ASSERT_TRUE(r.ok);
        std::vector<const Diagnostic*> closed;
        for (const Diagnostic& d : r.value.diagnostics)
            if (d.code == DiagnosticCode::kerf_closes_opening)
                closed.push_back(&d);
        // Half a kerf on each side: an opening of width w stays open while kerf < w.
        const bool slot_closes = kerf >= slot_width, hole_closes = kerf >= hole_width;
        ASSERT_EQ(closed.size(), size_t(slot_closes) + size_t(hole_closes));
        if (slot_closes) {
            const Diagnostic& d = *closed.front();
            EXPECT_EQ(d.severity, Severity::error);
            EXPECT_EQ(d.parameter, "kerf");
            EXPECT_EQ(d.patches, std::vector<int>{s.slits.front().patch_cut});
            EXPECT_NE(d.message.find("slit " + std::to_string(slit)), std::string::npos);
            const size_t at = d.message.find("keeps it open is ");
            ASSERT_NE(at, std::string::npos) << d.message;
            const double keeps = std::stod(d.message.substr(at + 17));
            EXPECT_LE(keeps, slot_width);
            EXPECT_GE(keeps, slot_width - 0.0015);
            continue;
        }
        // Every opening is still a hole of the compensated cut, each side moved in by kerf / 2:
        // the ground's hole measures (w - kerf) × (l - kerf) there.
        size_t nominal_holes = 0, cut_holes = 0;
        bool hole_found = false;
        const double expected = (hole_width - kerf) * (hole_length - kerf);
        for (const SheetPiece& piece : r.value.pieces) {
            for (const Region& region : piece.cut_nominal)
                nominal_holes += region.holes.size();
            for (const Region& region : piece.cut) {
                cut_holes += region.holes.size();
                for (const Loop2& h : region.holes)
                    hole_found =
                        hole_found || std::abs(std::abs(area({path_of(h)})) - expected) < 1e-3;
            }
        }
        EXPECT_EQ(nominal_holes, 2u);
        EXPECT_EQ(cut_holes, nominal_holes);
        EXPECT_TRUE(hole_found) << "no hole of " << expected << " mm²";
    }
}

TEST(SheetLayout, DieCuttingWarnsOfNarrowBridgesAndSharpCorners)
{
    // A 200 × 140 card: its ground (x 0..140, y 0..200) gets a hole leaving a 1 mm bridge to the
    // outer edge, and a 20° spike on that edge; every other corner of the card is 90°.
    Scaffold s = make_card(CardParams{200, 140}).value;
    Patch& ground = *std::find_if(s.patches.begin(), s.patches.end(),
                                  [&](const Patch& p) { return p.id == s.ground; });
    const double tip = 20.0 / std::tan(10.0 * M_PI / 180.0) / 2.0; // base 20 mm, apex 20°
    ground.outer = {{0, 0, 0},     {140, 0, 0},   {140, 150, 0}, {140 + tip, 160, 0},
                    {140, 170, 0}, {140, 200, 0}, {0, 200, 0}};
    ground.holes = {{{120, 40, 0}, {120, 60, 0}, {139, 60, 0}, {139, 40, 0}}}; // 1 mm from x = 140
    // The die-cutting warnings of one layout, by code.
    auto warnings = [&](double min_feature, double min_corner_angle) {
        SheetOptions o = a3();
        o.nest.paper = paper_by_name("500x400").value;
        o.min_feature = min_feature;
        o.min_corner_angle = min_corner_angle;
        const Result<SheetSet> r = layout_sheets(s, o);
        EXPECT_TRUE(r.ok);
        std::map<DiagnosticCode, Diagnostics> found;
        for (const Diagnostic& d : r.value.diagnostics)
            found[d.code].push_back(d);
        return found;
    };
    auto found = warnings(3.0, 30.0);
    EXPECT_EQ(found[DiagnosticCode::narrow_feature].size(), 1u); // the 1 mm bridge
    ASSERT_EQ(found[DiagnosticCode::sharp_corner].size(), 1u);   // the spike
    const Diagnostic& sharp = found[DiagnosticCode::sharp_corner].front();
    EXPECT_EQ(sharp.severity, Severity::warning);
    EXPECT_NE(sharp.message.find("has a 20° corner"), std::string::npos) << sharp.message;
    EXPECT_NE(std::find(sharp.patches.begin(), sharp.patches.end(), s.ground), sharp.patches.end());
    // The limits decide: a 0.8 mm feature size keeps the bridge, 15° accepts the spike.
    EXPECT_EQ(warnings(0.8, 30.0)[DiagnosticCode::narrow_feature].size(), 0u);
    EXPECT_EQ(warnings(3.0, 15.0)[DiagnosticCode::sharp_corner].size(), 0u);
    EXPECT_EQ(warnings(3.0, 25.0)[DiagnosticCode::sharp_corner].size(), 1u);
}

TEST(SheetLayout, CutLengthIsTheSumOfTheCutLoops)
{
    const SheetSet set = layout_sheets(fixtures::demo_card(), a3()).value;
    double length = 0;
    for (const SheetPiece& p : set.pieces)
        for (const Region& r : p.cut) {
            std::vector<Loop2> loops{r.outer};
            loops.insert(loops.end(), r.holes.begin(), r.holes.end());
            for (const Loop2& l : loops)
                for (size_t i = 0; i < l.size(); ++i)
                    length += (l[(i + 1) % l.size()] - l[i]).norm();
        }
    EXPECT_NEAR(set.cut_length, length, 1e-9 * length);
    EXPECT_GT(set.cut_length, 2 * (210 + 297));
}

TEST(SheetLayout, StackHeightCountsTheLayersOfTheClosedCard)
{
    const Scaffold s = fixtures::single_mechanism_cards().front().scaffold; // tent
    const SheetSet set = layout_sheets(s, a3()).value;
    // Closed: backdrop, two tent slopes, the two tabs on them and the ground.
    EXPECT_NEAR(set.stack_height, 6 * s.paper_thickness, 1e-12);
}

TEST(SheetLayout, TabsNarrowToFitAndReportWhenNoneFits)
{
    Scaffold s = fixtures::single_mechanism_cards()[8].scaffold; // rotation arm
    SheetOptions o = a3();
    o.tab_width = 20; // wider than the arm's 40 mm spine allows with 45° sides
    const SheetSet narrowed = layout_sheets(s, o).value;
    bool narrow = false;
    for (const Diagnostic& d : narrowed.diagnostics)
        narrow =
            narrow || (d.code == DiagnosticCode::narrow_tab && d.severity == Severity::warning);
    EXPECT_TRUE(narrow);
    EXPECT_TRUE(errors_of(narrowed).empty());

    o.min_tab_width = 20;
    const SheetSet none = layout_sheets(s, o).value;
    int no_room = 0;
    for (const Diagnostic& d : none.diagnostics)
        no_room += d.code == DiagnosticCode::no_room_for_tab && d.severity == Severity::error &&
                   d.patches.size() == 2;
    EXPECT_GE(no_room, 1);
}

TEST(SheetLayout, AFoldThatNeverCompletesIsAnError)
{
    // Built at 90°, the tent's 25 mm slopes reach its 30 mm feet only while sin(θ/2) <= 25/30:
    // opening, the motion locks at θ = 2 asin(5/6).
    // Its apex becomes a tab joint, so the pieces lie flat and only the motion is wrong.
    Scaffold s = fixtures::broken_tent_card();
    for (Hinge& h : s.hinges)
        if (h.patch_a != s.ground && h.patch_a != s.backdrop && h.patch_b != s.ground &&
            h.patch_b != s.backdrop)
            h.kind = JointKind::tab;
    const Result<SheetSet> r = layout_sheets(s, a3());
    const Diagnostics& found = r.ok ? r.value.diagnostics : r.diagnostics;
    const auto locked = std::find_if(found.begin(), found.end(), [](const Diagnostic& d) {
        return d.code == DiagnosticCode::motion_locked;
    });
    ASSERT_NE(locked, found.end());
    EXPECT_EQ(locked->severity, Severity::error);
    ASSERT_TRUE(locked->angle_deg.has_value());
    EXPECT_NEAR(*locked->angle_deg, 2.0 * std::asin(5.0 / 6.0) * 180.0 / M_PI, 0.5);
    EXPECT_FALSE(locked->patches.empty());
}

TEST(SheetLayout, APieceThatOverlapsItselfFlatIsReported)
{
    Scaffold s = fixtures::single_mechanism_cards()[8].scaffold; // rotation arm
    // The spine crosses the arm wing's paper: as a fold, the wings would overlap laid flat.
    for (Hinge& h : s.hinges) {
        const std::string a = s.find_patch(h.patch_a)->name, b = s.find_patch(h.patch_b)->name;
        if (a.find("wing") != std::string::npos && b.find("wing") != std::string::npos)
            h.kind = JointKind::fold;
    }
    const SheetSet set = layout_sheets(s, a3()).value;
    bool reported = false;
    for (const Diagnostic& d : set.diagnostics)
        reported =
            reported || (d.code == DiagnosticCode::piece_overlaps_itself &&
                         d.message.find("mm²") != std::string::npos && d.patches.size() == 2);
    EXPECT_TRUE(reported);
}

TEST(SheetLayout, BadOptionsAndPaperAreNamedErrors)
{
    const Scaffold s = fixtures::demo_card();
    SheetOptions o = a3();
    o.tab_angle = 0;
    o.nest.spacing = 0.5;
    const Result<SheetSet> bad = layout_sheets(s, o);
    ASSERT_FALSE(bad.ok);
    ASSERT_EQ(bad.diagnostics.size(), 2u);
    EXPECT_EQ(bad.diagnostics[0].parameter, "spacing");
    EXPECT_NE(bad.diagnostics[0].message.find("at least kerf + min_gap = 1.1 mm"),
              std::string::npos);
    EXPECT_EQ(bad.diagnostics[1].parameter, "tab_angle");

    // The open A4 card (210 × 297) cannot fit A4 paper inside 10 mm margins.
    SheetOptions a4;
    const Result<SheetSet> small = layout_sheets(s, a4);
    ASSERT_FALSE(small.ok);
    EXPECT_NE(small.diagnostics.front().message.find("does not fit the printable area"),
              std::string::npos);
    EXPECT_EQ(small.diagnostics.front().parameter, "paper");
    EXPECT_NE(small.diagnostics.front().message.find("piece P1"), std::string::npos);

    EXPECT_FALSE(paper_by_name("A9").ok);
    const Result<Paper> custom = paper_by_name("500x400");
    ASSERT_TRUE(custom.ok);
    o = a3();
    o.nest.paper = custom.value;
    EXPECT_TRUE(layout_sheets(s, o).ok);
}

TEST(SheetLayout, JsonCarriesEverything)
{
    const SheetSet set = layout_sheets(fixtures::demo_card(), a3()).value;
    const nlohmann::json j = nlohmann::json::parse(sheet_set_to_json(set));
    EXPECT_EQ(j["format"], "popup-sheets");
    EXPECT_EQ(j["paper"]["width"], 297.0);
    EXPECT_EQ(j["pieces"].size(), set.pieces.size());
    EXPECT_EQ(j["sheets"].size(), size_t(set.sheet_count));
    EXPECT_EQ(j["assembly"].size(), set.assembly.size());
    EXPECT_EQ(j["round_trip"]["ok"], true);
    EXPECT_DOUBLE_EQ(j["cut_length"].get<double>(), set.cut_length);
    EXPECT_EQ(j["pieces"][0]["folds"][0]["direction"], "valley");
    EXPECT_EQ(j["options"]["paper_thickness"], 0.2);
}

TEST(SheetLayout, ManyPieceCardNestsTighterThanShelves)
{
    const Scaffold s = fixtures::many_piece_card(4);
    SheetOptions o = a3();
    const Result<SheetSet> r = layout_sheets(s, o);
    ASSERT_TRUE(r.ok) << r.diagnostics.front().message;
    expect_usable(s, r.value, "many pieces");
    EXPECT_EQ(r.value.pieces.size(), 53u);
    // On A3 both need two sheets (the 240 mm card takes most of one); on 300 mm squares the
    // shelves leave room that true-shape nesting fills.
    EXPECT_EQ(r.value.sheet_count, 2);
    o.nest.paper = paper_by_name("300x300").value;
    const SheetSet square = layout_sheets(s, o).value;
    expect_usable(s, square, "many pieces, 300 mm squares");
    EXPECT_LE(square.sheet_count, 0.8 * square.shelf_sheet_count);
}

TEST(SheetLayout, CrowdedJointsMakeRoomForEachOther)
{
    // A platform reaching 0.5 mm past its legs: the legs' tabs need the room under the platform
    // that the backbone's tab took first; the backbone's narrows to leave them the narrowest tab.
    Scaffold layer = make_card(CardParams{200, 140}).value;
    FloatingLayerParams p;
    p.offset = 40;
    p.width = 40.7;
    p.height = 29.8;
    p.support = 8.0;
    p.overhang = 0.5;
    ASSERT_TRUE(add_floating_layer(layer, central_fold(layer), p).ok);
    const SheetSet crowded = layout_sheets(layer, a3()).value;
    expect_usable(layer, crowded, "crowded platform");

    // A short arm: the tab along its spine is held back from the spine's ends, where the rounded
    // outline must still join it to its wing.
    Scaffold arm = make_card(CardParams{200, 140}).value;
    RotationArmParams r;
    r.offset = 40;
    r.spine = 23.3;
    r.run = 13.9;
    r.arm = 5.5;
    ASSERT_TRUE(add_rotation_arm(arm, central_fold(arm), r).ok);
    const SheetSet short_arm = layout_sheets(arm, a3()).value;
    expect_usable(arm, short_arm, "short arm");
    for (const SheetPiece& piece : short_arm.pieces)
        EXPECT_EQ(piece.cut_nominal.size(), 1u) << piece.id;
}

TEST(SheetLayout, PatchFrameMapsOntoTheFlatOutline)
{
    // Each flat patch's to_sheet takes the patch's own frame (where artwork is rendered) onto
    // its outline on the sheet: every design vertex lands on a vertex of the flat outline. It
    // is a rotation where the normal side is printed, a reflection where the back side is.
    const Scaffold s = fixtures::demo_card();
    for (const bool card_back : {false, true}) {
        SheetOptions o = a3();
        if (card_back)
            o.printed_sides["P1"] = PrintedSide::back;
        const SheetSet set = layout_sheets(s, o).value;
        int flipped = 0, upright = 0;
        for (const SheetPiece& piece : set.pieces)
            for (const FlatPatch& fp : piece.patches) {
                Patch patch = *s.find_patch(fp.id);
                patch.derive_frame();
                const Eigen::Matrix2d linear = fp.to_sheet.leftCols<2>();
                EXPECT_LT((linear.transpose() * linear - Eigen::Matrix2d::Identity()).norm(),
                          1e-12);
                ASSERT_EQ(fp.outer.size(), patch.outer.size());
                for (const Vec3& x : patch.outer) {
                    const Vec2 on_sheet = linear * patch.to_local(x) + fp.to_sheet.col(2);
                    double nearest = INFINITY;
                    for (const Vec2& y : fp.outer)
                        nearest = std::min(nearest, (y - on_sheet).norm());
                    EXPECT_LT(nearest, 1e-6) << piece.id << " patch " << fp.id;
                }
                (fp.normal_side_up() ? upright : flipped) += 1;
                if (piece.id == "P1" && fp.id == s.ground) {
                    EXPECT_EQ(fp.normal_side_up(), !card_back); // the ground's normal is +z
                }
            }
        EXPECT_GT(upright, 0);
        if (card_back) {
            EXPECT_GT(flipped, 0);
        }
    }
    const SheetSet set = layout_sheets(s, a3()).value;
    const nlohmann::json j = nlohmann::json::parse(sheet_set_to_json(set));
    const FlatPatch& first = set.pieces[0].patches[0];
    for (int row = 0; row < 2; ++row)
        for (int column = 0; column < 3; ++column)
            EXPECT_DOUBLE_EQ(j["pieces"][0]["patches"][0]["to_sheet"][row][column].get<double>(),
                             first.to_sheet(row, column));
}
