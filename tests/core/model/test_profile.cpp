// Profiles cut patches to outlines. Expected areas and fold lengths are worked out by hand from
// the polygons below (a tree on a 60 × 20 mm riser, corners cut off a 80 × 30 mm box top), never
// read from the code under test.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "popup/mechanisms/box_fold.hpp"
#include "popup/mechanisms/horizontal_translation.hpp"
#include "popup/mechanisms/step_fold.hpp"
#include "popup/model/apply_profile.hpp"
#include "popup/model/card.hpp"
#include "popup/refers_into_argument.hpp"
#include "popup/sheets/sheet_layout.hpp"
#include "popup/sheets/verify_sheets.hpp"
#include "popup/simulation/check_validity.hpp"
#include "popup/simulation/simulate_fold.hpp"

using namespace popup;

namespace {

Scaffold card()
{
    CardParams p;
    p.width = 200;
    p.depth = 140;
    return make_card(p).value;
}

// A step 60 mm wide at y 60..120, riser 20 mm (run_backdrop) high hinged at x = 30: in the
// riser's profile frame u runs along y from its centre (y = 90), v from the ground fold toward
// the nose, so the riser is u ∈ [-30, 30], v ∈ [0, 20].
Scaffold step_card(MechanismParts* parts = nullptr)
{
    Scaffold s = card();
    StepFoldParams p;
    p.offset = 60;
    p.width = 60;
    p.run_ground = 30;
    p.run_backdrop = 20;
    Result<MechanismParts> r = add_step_fold(s, central_fold(s), p, "Step");
    EXPECT_TRUE(r.ok);
    if (parts)
        *parts = r.value;
    return s;
}

// Trunk 8 × 6 mm, crown a triangle 40 mm wide and 30 mm high above it: its apex (v = 36) is
// above the riser (v = 20), so the riser cuts the crown flat at v = 20, 64/3 mm wide.
Profile tree()
{
    Profile t;
    t.name = "Tree";
    t.outer = {{-4, 0}, {4, 0}, {4, 6}, {20, 6}, {0, 36}, {-20, 6}, {-4, 6}};
    return t;
}
constexpr double kTreeOnRiser = 8 * 6 + (40 + 64.0 / 3) / 2 * 14; // trunk + trapezoid

POPUP_REFERS_INTO_ARGUMENT const Patch& patch_named(const Scaffold& s, const std::string& name)
{
    for (const Patch& p : s.patches)
        if (p.name == name)
            return p;
    throw std::runtime_error("no patch " + name);
}

std::vector<const Hinge*> folds_between(const Scaffold& s, int a, int b)
{
    std::vector<const Hinge*> out;
    for (const Hinge& h : s.hinges)
        if ((h.patch_a == a && h.patch_b == b) || (h.patch_a == b && h.patch_b == a))
            out.push_back(&h);
    return out;
}

bool has(const Diagnostics& ds, DiagnosticCode code, Severity severity = Severity::error)
{
    for (const Diagnostic& d : ds)
        if (d.code == code && d.severity == severity)
            return true;
    return false;
}

void expect_laid_out_and_verified(const Scaffold& s)
{
    SheetOptions o;
    o.nest.paper = paper_by_name("A3").value;
    const Result<SheetSet> laid = layout_sheets(s, o);
    ASSERT_TRUE(laid.ok) << (laid.diagnostics.empty() ? "" : laid.diagnostics.front().message);
    const Result<RoundTrip> trip = verify_sheets(s, draw_sheets(laid.value));
    ASSERT_TRUE(trip.ok);
    EXPECT_TRUE(trip.value.ok);
    for (const Diagnostic& d : trip.diagnostics)
        ADD_FAILURE() << d.message;
}

} // namespace

TEST(ProfileFrame, RiserFrameStartsMidFoldAndPointsUpTheRiser)
{
    const Scaffold s = step_card();
    const Patch& riser = patch_named(s, "Step.riser");
    const Result<ProfileFrame> f = profile_frame(s, riser.id);
    ASSERT_TRUE(f.ok);
    EXPECT_NEAR((f.value.origin - Vec3(30, 90, 0)).norm(), 0, 1e-12);
    EXPECT_NEAR((f.value.u - Vec3(0, 1, 0)).norm(), 0, 1e-12);
    EXPECT_NEAR((f.value.v - Vec3(-1, 0, 0)).norm(), 0, 1e-12); // toward the nose at x = 10
}

TEST(ApplyProfile, TreeOnRiserHasTheAnalyticAreaAndClippedFolds)
{
    MechanismParts parts;
    Scaffold s = step_card(&parts);
    const int riser = patch_named(s, "Step.riser").id, tread = patch_named(s, "Step.tread").id;
    const Result<ProfileApplied> r = apply_profile(s, "Step", "riser", tree());
    ASSERT_TRUE(r.ok) << r.diagnostics.front().message;
    EXPECT_NEAR(r.value.area_before, 1200, 1e-9);
    EXPECT_NEAR(r.value.area_after, kTreeOnRiser, 1e-5);
    EXPECT_NEAR(patch_named(s, "Step.riser").area(), kTreeOnRiser, 1e-5);
    // The ground fold keeps the trunk's 8 mm (y 86..94), the nose the crown's flat top.
    const auto ground = folds_between(s, s.ground, riser);
    ASSERT_EQ(ground.size(), 1u);
    EXPECT_NEAR((ground[0]->to - ground[0]->from).norm(), 8.0, 1e-5);
    EXPECT_NEAR(std::min(ground[0]->from.y(), ground[0]->to.y()), 86.0, 1e-5);
    const auto nose = folds_between(s, riser, tread);
    ASSERT_EQ(nose.size(), 1u);
    EXPECT_NEAR((nose[0]->to - nose[0]->from).norm(), 64.0 / 3, 1e-5);
    EXPECT_NEAR(0.5 * (nose[0]->from.y() + nose[0]->to.y()), 90.0, 1e-5);
    // The tread keeps its paper; only the fold it shares shrank.
    EXPECT_NEAR(patch_named(s, "Step.tread").area(), 60 * 30, 1e-9);
    EXPECT_TRUE(validate_scaffold(s).ok);
}

TEST(ApplyProfile, TreeOnRiserIsValidAndItsSheetsVerify)
{
    Scaffold s = step_card();
    ASSERT_TRUE(apply_profile(s, "Step", "riser", tree()).ok);
    const ValidityReport v = check_validity(s);
    EXPECT_TRUE(v.valid());
    for (const Diagnostic& d : v.diagnostics)
        ADD_FAILURE() << d.message;
    expect_laid_out_and_verified(s);
}

TEST(ApplyProfile, HalfProfileKeepsThePositiveUSide)
{
    Scaffold s = step_card();
    Profile half;
    half.name = "Half";
    half.outer = {{0, -5}, {50, -5}, {50, 50}, {0, 50}};
    ASSERT_TRUE(apply_profile(s, "Step", "riser", half).ok);
    const Patch& riser = patch_named(s, "Step.riser");
    EXPECT_NEAR(riser.area(), 30 * 20, 1e-6);
    double lowest = std::numeric_limits<double>::infinity();
    for (const Vec3& x : riser.outer)
        lowest = std::min(lowest, x.y());
    EXPECT_NEAR(lowest, 90.0, 1e-5); // u > 0 is y > 90
}

TEST(ApplyProfile, BoxTopWithCutCornersIsValidAndItsSheetsVerify)
{
    Scaffold s = card();
    BoxFoldParams p;
    p.offset = 60;
    p.width = 80;
    p.depth_ground = 30;
    p.depth_backdrop = 30;
    p.height = 30;
    ASSERT_TRUE(add_box_fold(s, central_fold(s), p, "B1").ok);
    // TG in its frame: u along the crease from its middle, v from the crease to L (30 mm).
    Profile top;
    top.name = "Chamfer";
    top.outer = {{-40, 0}, {40, 0}, {40, 20}, {30, 30}, {-30, 30}, {-40, 20}};
    const Result<ProfileApplied> r = apply_profile(s, "B1", "TG", top);
    ASSERT_TRUE(r.ok) << r.diagnostics.front().message;
    EXPECT_NEAR(r.value.area_after, 80 * 30 - 2 * 50, 1e-5);
    const int tg = patch_named(s, "B1.TG").id, l = patch_named(s, "B1.L").id;
    const auto side = folds_between(s, tg, l);
    ASSERT_EQ(side.size(), 1u);
    EXPECT_NEAR((side[0]->to - side[0]->from).norm(), 60.0, 1e-5);
    const ValidityReport v = check_validity(s);
    EXPECT_TRUE(v.valid());
    for (const Diagnostic& d : v.diagnostics)
        ADD_FAILURE() << d.message;
    expect_laid_out_and_verified(s);
}

TEST(ApplyProfile, AFoldCrossingTwoStretchesOfPaperBecomesTwoFolds)
{
    Scaffold s = step_card();
    // A comb: two teeth (u -20..-10 and 10..20) joined above the ground fold, full height.
    Profile comb;
    comb.name = "Comb";
    comb.outer = {{-20, 0}, {-10, 0}, {-10, 10}, {10, 10}, {10, 0}, {20, 0}, {20, 30}, {-20, 30}};
    ASSERT_TRUE(apply_profile(s, "Step", "riser", comb).ok);
    const int riser = patch_named(s, "Step.riser").id;
    const auto ground = folds_between(s, s.ground, riser);
    ASSERT_EQ(ground.size(), 2u);
    EXPECT_NEAR((ground[0]->to - ground[0]->from).norm(), 10.0, 1e-5);
    EXPECT_NEAR((ground[1]->to - ground[1]->from).norm(), 10.0, 1e-5);
    EXPECT_NE(ground[0]->id, ground[1]->id);
    EXPECT_NEAR(patch_named(s, "Step.riser").area(), 40 * 20 - 20 * 10, 1e-5);
    EXPECT_TRUE(validate_scaffold(s).ok);
}

TEST(ApplyProfile, LoosePaperIsDroppedWithAWarning)
{
    Scaffold s = step_card();
    // A column u -10..10 over the riser, and an arm u 20..30, v 8..12 joined to it only
    // outside the riser (below v = 0 and beyond u = 30): inside, the arm holds no fold.
    Profile p;
    p.name = "Arm";
    p.outer = {{-10, -5}, {40, -5}, {40, 12}, {20, 12}, {20, 8},
               {35, 8},   {35, -3}, {10, -3}, {10, 25}, {-10, 25}};
    const Result<ProfileApplied> r = apply_profile(s, "Step", "riser", p);
    ASSERT_TRUE(r.ok) << r.diagnostics.front().message;
    EXPECT_EQ(r.value.dropped_pieces, 1);
    EXPECT_TRUE(has(r.diagnostics, DiagnosticCode::bad_profile, Severity::warning));
    EXPECT_TRUE(has(r.value.warnings, DiagnosticCode::bad_profile, Severity::warning));
    EXPECT_NEAR(r.value.area_after, 20 * 20, 1e-5);
}

TEST(ApplyProfile, ErrorsNameThePatchTheFoldAndTheProfile)
{
    Scaffold s = step_card();
    const Scaffold before = s;
    auto fails = [&](Profile p, DiagnosticCode code, const std::string& words) {
        const Result<ProfileApplied> r = apply_profile(s, "Step", "riser", p);
        EXPECT_FALSE(r.ok) << words;
        EXPECT_TRUE(has(r.diagnostics, code)) << words;
        if (!r.diagnostics.empty()) {
            EXPECT_NE(r.diagnostics.front().message.find(words), std::string::npos)
                << r.diagnostics.front().message;
            EXPECT_EQ(r.diagnostics.front().parameter.value_or(""), "Profile");
            EXPECT_EQ(r.diagnostics.front().patches,
                      std::vector<int>{patch_named(s, "Step.riser").id});
        }
        EXPECT_EQ(s.patches.size(), before.patches.size());
        EXPECT_NEAR(patch_named(s, "Step.riser").area(), 1200, 1e-9); // unchanged
        EXPECT_EQ(s.hinges.size(), before.hinges.size());
    };
    Profile shrub = tree();
    shrub.name = "Shrub";
    for (Vec2& q : shrub.outer)
        q.y() *= 0.5; // 18 mm high: misses the nose at v = 20
    fails(shrub, DiagnosticCode::profile_misses_hinge, "Step.riser: profile 'Shrub'");
    fails(shrub, DiagnosticCode::profile_misses_hinge, "Step.riser–Step.tread");
    Profile two;
    two.name = "Two";
    two.outer = {{0, 0}, {1, 1}};
    fails(two, DiagnosticCode::bad_profile, "Two: the outer loop has 2 distinct points");
    Profile nan;
    nan.name = "NaN";
    nan.outer = {{0, 0}, {std::nan(""), 1}, {1, 1}};
    fails(nan, DiagnosticCode::bad_profile, "NaN: the outer loop has point 1");
    Profile flat;
    flat.name = "Flat";
    flat.outer = {{0, 0}, {1, 0}, {2, 1e-7}}; // 5e-8 mm²
    fails(flat, DiagnosticCode::bad_profile, "Flat: the outer loop encloses 5e-08 mm²");
    Profile bow;
    bow.name = "Bow";
    bow.outer = {{-20, 0}, {20, 30}, {20, 0}, {-20, 30}};
    fails(bow, DiagnosticCode::bad_profile, "Bow: the outer loop crosses itself at (");
    Profile away;
    away.name = "Away";
    away.outer = {{100, 100}, {110, 100}, {110, 110}};
    fails(away, DiagnosticCode::bad_profile, "Away' leaves no paper");
    Profile pair;
    pair.name = "Pair";
    // Joined only above the riser (v > 20): inside it, two pieces each on both folds.
    pair.outer = {{-25, -1}, {-15, -1}, {-15, 22}, {15, 22},
                  {15, -1},  {25, -1},  {25, 26},  {-25, 26}};
    fails(pair, DiagnosticCode::bad_profile, "cuts it into 2 pieces that each hold a fold");
    const Result<ProfileApplied> unknown = apply_profile(s, "Step", "mast", tree());
    EXPECT_FALSE(unknown.ok);
    EXPECT_TRUE(has(unknown.diagnostics, DiagnosticCode::unknown_patch));
    EXPECT_NE(unknown.diagnostics.front().message.find("its parts: riser, tread"),
              std::string::npos)
        << unknown.diagnostics.front().message;
}

TEST(ApplyProfile, AHoleInTheProfileIsAHoleInThePatch)
{
    Scaffold s = step_card();
    Profile t = tree();
    t.holes = {{{-2, 10}, {-2, 14}, {2, 14}, {2, 10}}}; // clockwise or not: winding is free
    ASSERT_TRUE(apply_profile(s, "Step", "riser", t).ok);
    const Patch& riser = patch_named(s, "Step.riser");
    ASSERT_EQ(riser.holes.size(), 1u);
    EXPECT_NEAR(riser.area(), kTreeOnRiser - 16, 1e-5);
    EXPECT_TRUE(validate_scaffold(s).ok);
    EXPECT_TRUE(check_validity(s).valid());
}

TEST(ApplyProfile, ASlitKeepsOnlyThePaperAlongIt)
{
    // A horizontal translation's slit runs along its riser's nose, 5 mm short of each end
    // (u -25..25 of the 60 mm riser). The tree leaves the nose u ∈ [-32/3, 32/3]: the slit too.
    Scaffold s = card();
    HorizontalTranslationParams p;
    p.offset = 60;
    p.width = 60;
    p.run_ground = 30;
    p.run_backdrop = 20;
    p.reach = 40;
    ASSERT_TRUE(add_horizontal_translation(s, central_fold(s), p, "H").ok);
    ASSERT_EQ(s.slits.size(), 1u);
    EXPECT_NEAR((s.slits[0].to - s.slits[0].from).norm(), 50, 1e-9);
    ASSERT_TRUE(apply_profile(s, "H", "riser", tree()).ok);
    ASSERT_EQ(s.slits.size(), 1u);
    EXPECT_NEAR((s.slits[0].to - s.slits[0].from).norm(), 64.0 / 3, 1e-5);
    EXPECT_NEAR(0.5 * (s.slits[0].from.y() + s.slits[0].to.y()), 90, 1e-5);
    EXPECT_TRUE(validate_scaffold(s).ok);
    // A trunk alone (no crown) leaves no paper along the slit: named.
    Scaffold t = card();
    ASSERT_TRUE(add_horizontal_translation(t, central_fold(t), p, "H").ok);
    Profile posts;
    posts.name = "Posts";
    posts.outer = {{-30, -1}, {-27, -1}, {-27, 21}, {-30, 21}}; // u -30..-27: beyond the slit
    const Result<ProfileApplied> r = apply_profile(t, "H", "riser", posts);
    EXPECT_FALSE(r.ok);
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_EQ(r.diagnostics.front().code, DiagnosticCode::profile_misses_hinge);
    EXPECT_NE(r.diagnostics.front().message.find("along slit"), std::string::npos)
        << r.diagnostics.front().message;
}

TEST(ApplyProfile, ABoxFrontPanelWithChamferedCornersStaysValid)
{
    // FL (30 × 30) is built from L: its base hinge is the joint with L (x = 30, z 0..30), so u
    // runs up that joint from its middle and v across FL toward the end crease. Chamfering the
    // two corners on the joint by 10 × 10 leaves 800 mm² and 10 mm of the joint.
    Scaffold s = card();
    BoxFoldParams p;
    p.offset = 60;
    p.width = 80;
    p.depth_ground = 30;
    p.depth_backdrop = 30;
    p.height = 30;
    ASSERT_TRUE(add_box_fold(s, central_fold(s), p, "B1").ok);
    const int fl = patch_named(s, "B1.FL").id, l = patch_named(s, "B1.L").id;
    const Result<ProfileFrame> f = profile_frame(s, fl);
    ASSERT_TRUE(f.ok);
    EXPECT_NEAR(std::abs(f.value.u.z()), 1.0, 1e-12); // along the joint: vertical
    EXPECT_NEAR((f.value.origin - Vec3(30, 60, 15)).norm(), 0, 1e-9);
    Profile chamfer;
    chamfer.name = "Chamfer";
    chamfer.outer = {{-5, 0}, {5, 0}, {15, 10}, {15, 30}, {-15, 30}, {-15, 10}};
    const Result<ProfileApplied> r = apply_profile(s, fl, chamfer);
    ASSERT_TRUE(r.ok) << r.diagnostics.front().message;
    EXPECT_NEAR(r.value.area_after, 800, 1e-5);
    const auto joint = folds_between(s, fl, l);
    ASSERT_EQ(joint.size(), 1u);
    EXPECT_NEAR((joint[0]->to - joint[0]->from).norm(), 10, 1e-5);
    const ValidityReport v = check_validity(s);
    EXPECT_TRUE(v.valid());
    for (const Diagnostic& d : v.diagnostics)
        ADD_FAILURE() << d.message;
    expect_laid_out_and_verified(s);
}

// A box 100/3 mm high: its top folds (z = 100/3) lie off Clipper's nanometre grid, which the
// profile's clipping rounds to. L stands in the plane x = 20 (the ground depth), y 60..120; in
// its frame u runs along y from y = 90 and v up from the ground. The notch keeps 20 mm of its
// ground fold (y 80..100) and its joints with the end panels from v = 10 up. Profiles change no
// fold line, so the card moves as the same box without a profile; and the sheets of the
// profiled card must refold onto that motion at every angle, not only at the design angle
// (docs/DESIGN.md, "Profiles keep their folds exact").
TEST(ApplyProfile, FoldsOffTheNanometreGridStayExactAndTheSheetsRefoldAtEveryAngle)
{
    const double height = 100.0 / 3;
    auto box = [&] {
        Scaffold s = card();
        BoxFoldParams p;
        p.offset = 60;
        p.width = 60;
        p.depth_ground = 20;
        p.depth_backdrop = 20;
        p.height = height;
        EXPECT_TRUE(add_box_fold(s, central_fold(s), p, "B1").ok);
        return s;
    };
    const Scaffold plain = box();
    Scaffold s = box();
    Profile notch;
    notch.name = "Notch";
    notch.outer = {{-10, 0}, {10, 0},   {10, 10},  {35, 10},
                   {35, 40}, {-35, 40}, {-35, 10}, {-10, 10}};
    ASSERT_TRUE(apply_profile(s, "B1", "L", notch).ok);

    const Patch& l = patch_named(s, "B1.L");
    int on_top = 0;
    for (const Vec3& x : l.outer) {
        EXPECT_NEAR(x.x(), 20.0, 1e-12);
        if (std::abs(x.z() - height) < 1e-3) {
            ++on_top;
            EXPECT_NEAR(x.z(), height, 1e-12); // on the top fold, not a grid unit off it
            EXPECT_NEAR(std::min(std::abs(x.y() - 60), std::abs(x.y() - 120)), 0, 1e-12);
        }
    }
    EXPECT_EQ(on_top, 2);
    const auto ground = folds_between(s, s.ground, l.id);
    ASSERT_EQ(ground.size(), 1u);
    EXPECT_NEAR((ground[0]->to - ground[0]->from).norm(), 20, 1e-12);
    for (const char* end : {"B1.FL", "B1.BL"}) {
        const auto joint = folds_between(s, l.id, patch_named(s, end).id);
        ASSERT_EQ(joint.size(), 1u) << end;
        EXPECT_NEAR((joint[0]->to - joint[0]->from).norm(), height - 10, 1e-12) << end;
        for (const Vec3* x : {&joint[0]->from, &joint[0]->to})
            EXPECT_NEAR(std::abs(x->z() - 5 - height / 2), height / 2 - 5, 1e-12) << end;
    }

    std::vector<double> angles;
    for (int k = 0; k <= 12; ++k)
        angles.push_back(M_PI * (1 - k / 12.0));
    const Result<FoldSweep> as_plain = simulate_fold(plain, angles);
    ASSERT_TRUE(as_plain.ok && as_plain.value.complete);
    const Result<FoldSweep> profiled = simulate_fold(s, angles);
    ASSERT_TRUE(profiled.ok && profiled.value.complete);
    for (size_t k = 0; k < angles.size(); ++k)
        for (size_t i = 0; i < plain.patches.size(); ++i) {
            const Loop3 a = posed_outline(plain.patches[i], as_plain.value.states[k].poses[i]);
            const Loop3 b = posed_outline(plain.patches[i], profiled.value.states[k].poses[i]);
            for (size_t j = 0; j < a.size(); ++j)
                EXPECT_NEAR((a[j] - b[j]).norm(), 0, 1e-6) << plain.patches[i].name;
        }

    SheetOptions o;
    o.nest.paper = paper_by_name("A3").value;
    const Result<SheetSet> laid = layout_sheets(s, o);
    ASSERT_TRUE(laid.ok) << (laid.diagnostics.empty() ? "" : laid.diagnostics.front().message);
    const Result<RoundTrip> trip = verify_sheets(s, draw_sheets(laid.value));
    ASSERT_TRUE(trip.ok);
    for (const Diagnostic& d : trip.diagnostics)
        ADD_FAILURE() << d.message;
    EXPECT_TRUE(trip.value.ok);
    EXPECT_EQ(trip.value.angles, 13);      // every angle asked for, not the design angle alone
    EXPECT_LE(trip.value.max_error, 1e-6); // mm, each refolded patch against the simulated one
}
