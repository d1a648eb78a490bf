// Outlines that follow the model (thesis §5.1.3): a box fold built here on a 200 × 140 card and
// models extruded along x over exactly the box's depth, so each side's silhouette is the
// extruded polygon, whose area is a closed form (a rectangle with polygonal quarter circles).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "popup/fitting/fit_design.hpp"
#include "popup/fitting/fit_outlines.hpp"
#include "popup/mechanisms/box_fold.hpp"
#include "popup/model/apply_profile.hpp"
#include "popup/model/card.hpp"
#include "popup/refers_into_argument.hpp"
#include "popup/sheets/sheet_layout.hpp"
#include "popup/sheets/verify_sheets.hpp"
#include "popup/simulation/check_validity.hpp"
#include "synthetic_models.hpp"

using namespace popup;
using namespace popup::testing;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kOffset = 50, kWidth = 60, kDepth = 30, kHeight = 40;

struct Design {
    Scaffold scaffold;
    BasePatchPair host;
    std::vector<FittedMechanism> mechanisms;
};

Design box_design(double height = kHeight)
{
    CardParams cp;
    cp.width = 200;
    cp.depth = 140;
    Design d;
    d.scaffold = make_card(cp).value;
    d.host = central_fold(d.scaffold);
    BoxFoldParams bp;
    bp.offset = kOffset;
    bp.width = kWidth;
    bp.depth_ground = kDepth;
    bp.depth_backdrop = kDepth;
    bp.height = height;
    EXPECT_TRUE(add_box_fold(d.scaffold, d.host, bp, "B1").ok);
    FittedMechanism m;
    static_cast<DesignedMechanism&>(m) =
        DesignedMechanism::of_kind(MechanismKind::box_fold, "B1", "central fold");
    m.params = bp;
    d.mechanisms.push_back(m);
    return d;
}

/// `section` (y along the box's hinge from its offset, z up) extruded over the box's depth and
/// placed in the card frame through the host pair.
ModelMesh placed_section(const std::vector<Vec2>& section, const BasePatchPair& host)
{
    std::vector<Vec2> yz;
    for (const Vec2& q : section)
        yz.push_back({q.x() + kOffset, q.y()});
    ModelMesh m = extrude_elevation(yz, kDepth);
    for (Vec3& x : m.vertices)
        x = host.to_world(x.x(), x.y(), x.z());
    return m;
}

/// Quarter circle of radius r about c from angle a0, `n` chords, without its first point.
void arc(std::vector<Vec2>& out, const Vec2& c, double r, double a0, int n)
{
    for (int k = 1; k <= n; ++k) {
        const double a = a0 + 0.5 * kPi * k / n;
        out.push_back(c + r * Vec2(std::cos(a), std::sin(a)));
    }
}

POPUP_REFERS_INTO_ARGUMENT const Patch& patch_named(const Scaffold& s, const std::string& name)
{
    for (const Patch& p : s.patches)
        if (p.name == name)
            return p;
    throw std::runtime_error("no patch " + name);
}

} // namespace

TEST(FitOutlines, PrincipalPartsFollowFigure53)
{
    EXPECT_EQ(principal_parts(MechanismKind::box_fold),
              (std::vector<std::string>{"L", "R", "TG", "TB", "FL", "FR", "BL", "BR"}));
    EXPECT_EQ(principal_parts(MechanismKind::tent_fold),
              (std::vector<std::string>{"slope_ground", "slope_backdrop"}));
    EXPECT_EQ(principal_parts(MechanismKind::step_fold),
              (std::vector<std::string>{"riser", "tread"}));
    EXPECT_TRUE(principal_parts(MechanismKind::rotation_arm).empty()); // not a shape mechanism
}

TEST(FitOutlines, AWheelArchGivesTheAnalyticArea)
{
    // Side section: the box's 60 × 40 rectangle with a semicircular arch (radius 12, 16 chords)
    // bitten out of the middle of its foot. Area = W·c − 16 · ½R² sin(π/16).
    const double radius = 12;
    const int n = 16;
    std::vector<Vec2> s{{0, 0}};
    for (int k = 0; k <= n; ++k) {
        const double a = kPi - kPi * k / n;
        s.push_back({0.5 * kWidth + radius * std::cos(a), radius * std::sin(a)});
    }
    s.push_back({kWidth, 0});
    s.push_back({kWidth, kHeight});
    s.push_back({0, kHeight});
    Design d = box_design();
    const ModelMesh model = placed_section(s, d.host);
    const OutlineOutcome out = fit_outlines(model, d.scaffold, d.mechanisms);

    const double expected = kWidth * kHeight - 8 * radius * radius * std::sin(kPi / n);
    // The polygon is within its chord error of the true half disc: R² (π/2 − 8 sin(π/16))
    // = 1.45 mm².
    EXPECT_NEAR(expected, kWidth * kHeight - 0.5 * kPi * radius * radius, 1.46);
    EXPECT_TRUE(out.dropped.empty()) << out.dropped.front().reason;
    // The top and the ends see whole rectangles: they keep no profile (nothing to cut).
    ASSERT_EQ(out.profiles.size(), 2u);
    EXPECT_EQ(out.profiles[0].part, "L");
    EXPECT_EQ(out.profiles[1].part, "R");
    for (const FittedProfile& p : out.profiles) {
        const Patch& patch = patch_named(out.scaffold, "B1." + p.part);
        EXPECT_NEAR(p.area, patch.area(), 1e-6) << p.part;
        // Outlines drop vertices within 1 µm of their neighbours' line (fit_outlines.cpp): the
        // area may move by the perimeter times 1 µm.
        double perimeter = 0;
        for (size_t k = 0; k < p.outer.size(); ++k)
            perimeter += (p.outer[(k + 1) % p.outer.size()] - p.outer[k]).norm();
        EXPECT_NEAR(p.area, expected, 1e-3 + perimeter * 1e-3) << p.part;
        EXPECT_NEAR(p.area_before, kWidth * kHeight, 1e-6);
        EXPECT_GE(p.outer.size(), size_t(n + 4)) << p.part; // the arch's points are kept
        // Reference: the side as generated, W along its foot, c up.
        EXPECT_NEAR(p.reference.x(), kWidth, 1e-9);
        EXPECT_NEAR(p.reference.y(), kHeight, 1e-9);
    }
    EXPECT_NEAR(patch_named(out.scaffold, "B1.TG").area(), kWidth * kDepth, 1e-9);
    EXPECT_TRUE(check_validity(out.scaffold).valid());

    // Deterministic: the same input gives the same outlines, point for point.
    const OutlineOutcome again = fit_outlines(model, d.scaffold, d.mechanisms);
    ASSERT_EQ(again.profiles.size(), out.profiles.size());
    for (size_t i = 0; i < out.profiles.size(); ++i) {
        EXPECT_EQ(again.profiles[i].part, out.profiles[i].part);
        EXPECT_EQ(again.profiles[i].outer, out.profiles[i].outer);
    }
}

TEST(FitOutlines, SliversAreNotCut)
{
    // The model 1 mm lower and 2 mm shorter than the box: the cut-away bands are narrower than
    // the 3 mm the sheets can cut, so no part takes a profile.
    std::vector<Vec2> s{{1, 0}, {kWidth - 1, 0}, {kWidth - 1, kHeight - 1}, {1, kHeight - 1}};
    Design d = box_design();
    const OutlineOutcome out = fit_outlines(placed_section(s, d.host), d.scaffold, d.mechanisms);
    EXPECT_TRUE(out.profiles.empty());
    EXPECT_TRUE(out.dropped.empty());
}

TEST(FitOutlines, AnOutlineThatLeavesAFoldKeepsABridgeToIt)
{
    // The model 10 mm lower than the box: its silhouette leaves L's and R's fold to the top
    // entirely. Each side keeps the model's outline and a bridge of paper from the middle of that
    // fold down to it, as wide as the shortest crease a glue tab fits on (c, fit_outlines'
    // default): W·low + c·10. The end panels are cut to the model's height (30 × 30 mm each); the
    // top sees the whole model and keeps its rectangle. Nothing is dropped; the design is valid.
    const double low = kHeight - 10;
    const double c = shortest_tabbed_crease(SheetOptions{});
    ASSERT_GT(c, 6.0); // the bridge's floor (fit_outlines' kBridgeWidth)
    ASSERT_LT(c, kWidth);
    std::vector<Vec2> s{{0, 0}, {kWidth, 0}, {kWidth, low}, {0, low}};
    Design d = box_design();
    const OutlineOutcome out = fit_outlines(placed_section(s, d.host), d.scaffold, d.mechanisms);
    EXPECT_TRUE(out.dropped.empty()) << out.dropped.front().reason;
    ASSERT_EQ(out.profiles.size(), 6u);
    for (const FittedProfile& p : out.profiles) {
        if (p.part == "L" || p.part == "R") {
            EXPECT_NEAR(p.area, kWidth * low + c * 10, 1e-3) << p.part;
            // The bridge stands in the middle of the fold: its two top corners, c apart.
            std::vector<double> on_fold;
            double top = -1e300, left = 1e300, right = -1e300;
            for (const Vec2& q : p.outer) {
                top = std::max(top, q.y());
                left = std::min(left, q.x());
                right = std::max(right, q.x());
            }
            for (const Vec2& q : p.outer)
                if (std::abs(q.y() - top) < 1e-6)
                    on_fold.push_back(q.x());
            ASSERT_EQ(on_fold.size(), 2u) << p.part;
            std::sort(on_fold.begin(), on_fold.end());
            EXPECT_NEAR(on_fold[1] - on_fold[0], c, 1e-6) << p.part;
            EXPECT_NEAR(right - left, kWidth, 1e-6) << p.part;
            EXPECT_NEAR(on_fold[0] + on_fold[1], left + right, 1e-6) << p.part;
        } else {
            EXPECT_TRUE(p.part == "FL" || p.part == "FR" || p.part == "BL" || p.part == "BR");
            EXPECT_NEAR(p.area, kDepth * low, 1e-3) << p.part;
        }
    }
    EXPECT_NEAR(patch_named(out.scaffold, "B1.TG").area(), kWidth * kDepth, 1e-9);
    EXPECT_TRUE(check_validity(out.scaffold).valid());
}

TEST(FitOutlines, AnOutlineKeepsAStripAlongEachGluedJoint)
{
    // A T-shaped side section: a stem `foot` mm wide under a full-width block. The stem is all
    // the silhouette leaves of the side's glued joint with its page. A stem narrower than the
    // shortest crease a glue tab fits on (c, the sheets' rule) gets a strip of paper c long and
    // a default tab (8 mm) deep, centred under it: the side is the T plus that strip, area
    // foot·20 + W·(H − 20) + (c − foot)·8 (the strip's 3.56 mm shoulders beside a 4 mm stem are
    // wider than the 3 mm cut the sheets can make, so the notches above them stay cut; beside
    // an 8 mm stem they are 1.56 mm, but open onto the wide cut-away beside the stem, so they
    // stay cut too). A 20 mm stem already holds a tab: the side is the T.
    const double glued = shortest_tabbed_crease(SheetOptions{});
    const double tab = SheetOptions{}.tab_width;
    ASSERT_GT(glued, 8.0);
    ASSERT_LT(glued, 20.0);
    for (const double foot : {4.0, 8.0, 20.0}) {
        const double a = 0.5 * (kWidth - foot), b = 0.5 * (kWidth + foot);
        std::vector<Vec2> s{{a, 0},       {b, 0},  {b, 20}, {kWidth, 20}, {kWidth, kHeight},
                            {0, kHeight}, {0, 20}, {a, 20}};
        Design d = box_design();
        const OutlineOutcome out =
            fit_outlines(placed_section(s, d.host), d.scaffold, d.mechanisms);
        EXPECT_TRUE(out.dropped.empty()) << out.dropped.front().reason;
        std::vector<std::string> sides;
        for (const FittedProfile& p : out.profiles)
            if (p.part == "L" || p.part == "R")
                sides.push_back(p.part);
        EXPECT_EQ(sides, (std::vector<std::string>{"L", "R"})) << foot;
        const double strip = foot < glued ? (glued - foot) * tab : 0.0;
        const double area = foot * 20 + kWidth * (kHeight - 20) + strip;
        const Patch& side = patch_named(out.scaffold, "B1.L");
        EXPECT_NEAR(side.area(), area, 1e-3) << foot;
        // The side's joint with the page is the strip's (or the stem's) length, one piece.
        double joint = 0;
        int pieces = 0;
        for (const Hinge& h : out.scaffold.hinges)
            if (h.kind == JointKind::tab && (h.patch_a == side.id || h.patch_b == side.id) &&
                out.scaffold.find_patch(h.patch_a == side.id ? h.patch_b : h.patch_a)->name ==
                    "Card.ground") {
                joint += (h.to - h.from).norm();
                ++pieces;
            }
        EXPECT_EQ(pieces, 1) << foot;
        EXPECT_NEAR(joint, std::max(foot, glued), 1e-5) << foot;
        // The outline holds the strip's corners, centred on the side's foot (its frame's u = 0).
        if (foot < glued)
            for (const FittedProfile& p : out.profiles)
                for (const Vec2& corner : {Vec2(-0.5 * glued, 0), Vec2(0.5 * glued, 0),
                                           Vec2(-0.5 * glued, tab), Vec2(0.5 * glued, tab)}) {
                    double nearest = 1e9;
                    for (const Vec2& q : p.outer)
                        nearest = std::min(nearest, (q - corner).norm());
                    EXPECT_LT(nearest, 1e-5) << p.part << " " << foot;
                }
        EXPECT_TRUE(check_validity(out.scaffold).valid());
    }
}

TEST(FitOutlines, WithoutTheGlueRuleAThinFootIsCutAsTheModelIs)
{
    // min_part 0 (--min-part 0) lets the maker glue by hand: no strip, the side is the T.
    const double foot = 8.0;
    const double a = 0.5 * (kWidth - foot), b = 0.5 * (kWidth + foot);
    std::vector<Vec2> s{{a, 0},       {b, 0},  {b, 20}, {kWidth, 20}, {kWidth, kHeight},
                        {0, kHeight}, {0, 20}, {a, 20}};
    Design d = box_design();
    const OutlineOutcome out =
        fit_outlines(placed_section(s, d.host), d.scaffold, d.mechanisms, nullptr, 0.0);
    EXPECT_NEAR(patch_named(out.scaffold, "B1.L").area(), foot * 20 + kWidth * (kHeight - 20),
                1e-3);
}

TEST(FitOutlines, TopHalvesCutOnBothSidesKeepTheirCreaseWithTheCentreWallWhole)
{
    // A model whose top view leaves both ends of the top crease (a 60 × 30 box's crease runs
    // along its width over x = 0): a block 30 wide in the middle of the width, the full depth
    // and height. Each top half is cut to it, and since the centre wall's one tab along the
    // crease holds both halves only where one's joint lies within the other's, both keep the
    // crease whole under a tab-deep strip: area 30·30 + 2·15·8 each. The sheets glue it.
    std::vector<Vec2> s{{15, 0}, {45, 0}, {45, kHeight}, {15, kHeight}};
    Design d = box_design();
    const OutlineOutcome out = fit_outlines(placed_section(s, d.host), d.scaffold, d.mechanisms);
    const double tab = SheetOptions{}.tab_width;
    for (const std::string part : {"TG", "TB"})
        EXPECT_NEAR(patch_named(out.scaffold, "B1." + part).area(), 30 * kDepth + 2 * 15 * tab,
                    1e-3)
            << part;
    EXPECT_TRUE(check_validity(out.scaffold).valid());
    SheetOptions o;
    o.nest.paper = paper_by_name("A3").value;
    const Result<SheetSet> laid = layout_sheets(out.scaffold, o);
    ASSERT_TRUE(laid.ok);
    for (const Diagnostic& x : laid.value.diagnostics)
        EXPECT_NE(x.severity, Severity::error) << x.message;
    EXPECT_TRUE(laid.value.round_trip.ok);
}

TEST(FitOutlines, FitDesignProfilesTheArchedBlockDeterministically)
{
    // The arched section of the test above, 40 mm deep, fitted by the whole pipeline.
    const double rho = 10;
    const int n = 8;
    std::vector<Vec2> s{{rho, 0}, {kWidth - rho, 0}};
    arc(s, {kWidth - rho, rho}, rho, -0.5 * kPi, n);
    s.push_back({kWidth, kHeight});
    s.push_back({0, kHeight});
    s.push_back({0, rho});
    arc(s, {rho, rho}, rho, kPi, n);
    s.pop_back();
    ModelMesh block = extrude_elevation(s, 20);
    block.source = "arched block";
    FitOptions o;
    const Result<FitResult> a = fit_design(block, o);
    const Result<FitResult> b = fit_design(block, o);
    ASSERT_TRUE(a.ok);
    ASSERT_TRUE(a.value.valid);
    EXPECT_TRUE(check_validity(a.value.scaffold).valid());
    ASSERT_FALSE(a.value.profiles.empty());
    ASSERT_EQ(a.value.profiles.size(), b.value.profiles.size());
    for (size_t i = 0; i < a.value.profiles.size(); ++i) {
        const FittedProfile &p = a.value.profiles[i], &q = b.value.profiles[i];
        EXPECT_EQ(p.mechanism + p.part, q.mechanism + q.part);
        EXPECT_EQ(p.outer, q.outer);
        // The patch in the returned scaffold, re-measured, is the profiled one.
        EXPECT_NEAR(p.area, patch_named(a.value.scaffold, p.mechanism + "." + p.part).area(), 1e-6);
        EXPECT_LT(p.area, p.area_before); // only outlines that cut something are kept
    }
    bool timed = false;
    for (const auto& [stage, seconds] : a.value.timings.stages)
        timed |= stage == "outlines";
    EXPECT_TRUE(timed);

    // Switched off: the same mechanisms, their parts as generated.
    o.outlines = false;
    const Result<FitResult> plain = fit_design(block, o);
    EXPECT_TRUE(plain.value.profiles.empty());
    for (const FittedProfile& p : a.value.profiles)
        EXPECT_NEAR(patch_named(plain.value.scaffold, p.mechanism + "." + p.part).area(),
                    p.area_before, 1e-6);
}

TEST(FitOutlines, ATopOutlineKeepingPartOfItsJointWithTheCentreWallStillGlues)
{
    // The top half on the backdrop side (TB) is joined to the centre wall (C) along the top's
    // crease, where C is also joined to TG: one tab of C holds both joints. An outline that cuts
    // TB's end of that crease away on a slant (the way a silhouette leaves it: here it leaves
    // the crease at u = 15 mm, 24° off it, as a wavy silhouette did) keeps only part of the
    // C–TB joint. The sheets must see that part as held by C's tab along the whole crease.
    Design d = box_design();
    const auto tabs_of = [](const SheetSet& set) {
        size_t n = 0;
        for (const SheetPiece& p : set.pieces)
            n += p.tabs.size();
        return n;
    };
    SheetOptions o;
    o.nest.paper = paper_by_name("A3").value;
    const Result<SheetSet> whole = layout_sheets(d.scaffold, o);
    ASSERT_TRUE(whole.ok);
    const int c = patch_named(d.scaffold, "B1.C").id, tb = patch_named(d.scaffold, "B1.TB").id;
    const double slope = std::tan(24 * kPi / 180);
    Profile notch;
    notch.name = "notched top";
    notch.outer = {{-40, -5}, {15, -5}, {15, 0}, {40, 25 * slope}, {40, 40}, {-40, 40}};
    ASSERT_TRUE(apply_profile(d.scaffold, "B1", "TB", notch).ok);
    // The joint keeps u from −30 to 15: 45 mm of the box's 60 mm width.
    double joint = 0;
    for (const Hinge& h : d.scaffold.hinges)
        if ((h.patch_a == c && h.patch_b == tb) || (h.patch_a == tb && h.patch_b == c))
            joint += (h.to - h.from).norm();
    EXPECT_NEAR(joint, 0.5 * kWidth + 15, 1e-5);
    EXPECT_TRUE(check_validity(d.scaffold).valid());

    const Result<SheetSet> laid = layout_sheets(d.scaffold, o);
    ASSERT_TRUE(laid.ok);
    for (const Diagnostic& x : laid.value.diagnostics) {
        EXPECT_NE(x.code, DiagnosticCode::no_room_for_tab) << x.message;
        EXPECT_NE(x.code, DiagnosticCode::joint_without_tab) << x.message;
        EXPECT_NE(x.severity, Severity::error) << x.message;
    }
    EXPECT_TRUE(laid.value.round_trip.ok);
    // As many tabs as the uncut box: C's tab along the crease still holds TG and TB.
    EXPECT_EQ(tabs_of(laid.value), tabs_of(whole.value));
    // The sheets as a cutting file holds them verify on their own too.
    const Result<RoundTrip> trip = verify_sheets(d.scaffold, draw_sheets(laid.value));
    ASSERT_TRUE(trip.ok);
    EXPECT_TRUE(trip.value.ok);
    for (const Diagnostic& x : trip.diagnostics)
        EXPECT_NE(x.severity, Severity::error) << x.message;
}
