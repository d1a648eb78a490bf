// Closed forms of the mechanisms against the simulator, and the §4.2.2 placement pre-check
// against the full validity check.
#include <gtest/gtest.h>

#include <cmath>

#include "popup/mechanisms/box_fold.hpp"
#include "popup/mechanisms/horizontal_translation.hpp"
#include "popup/mechanisms/rotation_arm.hpp"
#include "popup/mechanisms/step_fold.hpp"
#include "popup/mechanisms/tent_fold.hpp"
#include "popup/mechanisms/v_box_fold.hpp"
#include "popup/mechanisms/v_fold.hpp"
#include "popup/model/card.hpp"
#include "popup/simulation/check_validity.hpp"
#include "popup/simulation/simulate_fold.hpp"
#include "test_support.hpp"

using namespace popup;

namespace {
Scaffold card(double width = 300, double depth = 140)
{
    return fixtures::generator_card(width, depth);
}

// World position of a design-state point of a patch over a 0..180° sweep, against `expected`.
template <class Expected>
void expect_track(const Scaffold& s, int patch, const Vec3& point, Expected expected)
{
    const auto sweep = simulate_fold(s, fixtures::angle_range(180, 0, 181));
    ASSERT_TRUE(sweep.value.complete);
    for (const FoldState& st : sweep.value.states) {
        const Vec3 at = fixtures::world_point(s, st, patch, point);
        EXPECT_LT((at - expected(st.angle)).norm(), 1e-9 * s.size())
            << "at " << st.angle * 180 / M_PI << "°";
    }
}
} // namespace

TEST(ClosedForm, AsymmetricTentApexMatchesTheSimulator)
{
    Scaffold s = card();
    TentFoldParams p;
    p.offset = 40;
    p.width = 50;
    p.foot = 35;
    p.foot_backdrop = 20;
    p.slope = 45;
    const auto parts = add_tent_fold(s, central_fold(s), p);
    ASSERT_TRUE(parts.ok);
    const Vec2 apex0 = tent_apex(p, M_PI);
    expect_track(s, parts.value.patches[0], {apex0.x(), 40, apex0.y()}, [&](double t) {
        const Vec2 a = tent_apex(p, t);
        return Vec3(a.x(), 40, a.y());
    });
}

TEST(ClosedForm, StepNoseMatchesTheSimulator)
{
    Scaffold s = card();
    StepFoldParams p;
    p.offset = 40;
    p.width = 50;
    p.run_ground = 25;
    p.run_backdrop = 40;
    const auto parts = add_step_fold(s, central_fold(s), p);
    ASSERT_TRUE(parts.ok);
    const Vec2 nose0 = step_nose(p, M_PI);
    expect_track(s, parts.value.patches[0], {nose0.x(), 90, nose0.y()}, [&](double t) {
        const Vec2 n = step_nose(p, t);
        return Vec3(n.x(), 90, n.y());
    });
}

TEST(ClosedForm, VFoldTipMatchesTheSimulator)
{
    Scaffold s = card();
    VFoldParams p;
    p.offset = 60;
    p.run = 50;
    p.hinge_angle = fixtures::deg(40);
    p.spine = 60;
    p.spine_angle = fixtures::deg(70);
    const auto parts = add_v_fold(s, central_fold(s), p);
    ASSERT_TRUE(parts.ok);
    expect_track(s, parts.value.patches[0], v_fold_tip(p, M_PI, M_PI),
                 [&](double t) { return v_fold_tip(p, M_PI, t); });
}

TEST(ClosedForm, BoxTopAndEndCreaseMatchTheSimulator)
{
    Scaffold s = card();
    BoxFoldParams p;
    p.offset = 80;
    p.width = 60;
    p.depth_ground = p.depth_backdrop = 35;
    p.height = 25;
    const auto parts = add_box_fold(s, central_fold(s), p);
    ASSERT_TRUE(parts.ok);
    const int L = parts.value.patches[1], FL = parts.value.patches[5];
    expect_track(s, L, {35, 110, 25}, [&](double t) {
        const Vec2 q = box_fold_section(p, t).side_ground_top;
        return Vec3(q.x(), 110, q.y());
    });
    expect_track(s, FL, {0, 80, 0}, [&](double t) {
        const BoxSection b = box_fold_section(p, t);
        return Vec3(b.crease_foot.x(), 80 - b.crease_out, b.crease_foot.y());
    });
}

TEST(BoxFold, UnequalDepthsWithEndPanelsAreRefused)
{
    // With end panels C must stay square to the line between the sides' feet, which lies in the
    // page when the card closes unless the depths are equal (docs/MATH.md).
    Scaffold s = card();
    BoxFoldParams p;
    p.offset = 80;
    p.width = 60;
    p.depth_ground = 30;
    p.depth_backdrop = 20;
    const auto r = add_box_fold(s, central_fold(s), p);
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.diagnostics.front().parameter, "DepthBackdrop");
    EXPECT_EQ(r.diagnostics.front().message.rfind("BoxFold: DepthBackdrop = ", 0), 0u)
        << r.diagnostics.front().message;
}

TEST(PlacementPreCheck, AgreesWithTheSimulatorOnBoxesAndVFolds)
{
    enum class Next { box, v_fold, v_box };
    struct Case {
        double gap;
        Next next;
        bool conservative = false; ///< the pre-check warns, the simulator finds no crossing
    };
    // The v-box stands before the box so its front (which leans out when closed) faces it.
    for (const Case c :
         {Case{10, Next::box}, Case{30, Next::box}, Case{39, Next::box}, Case{41, Next::box},
          Case{90, Next::box}, Case{5, Next::v_fold}, Case{60, Next::v_fold},
          Case{-10, Next::v_box}, Case{5, Next::v_box, true}, Case{40, Next::v_box}}) {
        Scaffold s = card();
        BoxFoldParams box;
        box.offset = 40;
        box.width = 60;
        box.depth_ground = box.depth_backdrop = box.height = 40;
        std::vector<MechanismParts> parts{add_box_fold(s, central_fold(s), box, "BoxA").value};
        const char* what = "box";
        if (c.next == Next::v_fold) {
            VFoldParams v;
            v.offset = 140 + c.gap;
            v.run = 40;
            v.spine = 45;
            parts.push_back(add_v_fold(s, central_fold(s), v, "VFold").value);
            what = "v-fold";
        } else if (c.next == Next::v_box) {
            VBoxFoldParams v;
            v.offset = 140 + c.gap;
            v.side = 30;
            v.height = 25;
            parts.push_back(add_v_box_fold(s, central_fold(s), v, "VBox").value);
            what = "v-box";
        } else {
            box.offset = 100 + c.gap;
            parts.push_back(add_box_fold(s, central_fold(s), box, "BoxB").value);
        }
        const bool predicted = !placement_conflicts(parts).empty();
        const ValidityReport r = check_validity(s);
        // The condition is sufficient, not necessary: with a 5 mm gap the box's back crease
        // (40 mm up when closed) and the v-box's leaning front (18 mm up) share y but pass at
        // different heights. The simulator wins; the case stays here as the known difference.
        EXPECT_EQ(predicted, !r.intersection_free || c.conservative)
            << "gap " << c.gap << " (" << what << "): pre-check " << predicted << ", simulator "
            << !r.intersection_free;
        if (c.conservative) {
            EXPECT_TRUE(r.intersection_free);
        }
    }
}

// docs/MATH.md, "Vertical translation": the printed P_y = −h sin α cos δ (thesis eq 4.5) only
// holds at the ends; the simulator follows −h sin α cos δ / √(cos²α + sin²α cos²δ).
TEST(ClosedForm, VerticalSpineTipCorrectsThesisEquation45)
{
    Scaffold s = card();
    VFoldParams p;
    p.offset = 60;
    p.run = 50;
    p.hinge_angle = fixtures::deg(35);
    p.spine = 40;
    p.spine_angle = M_PI / 2;
    const auto parts = add_v_fold(s, central_fold(s), p);
    ASSERT_TRUE(parts.ok);
    const double h = p.spine, a = p.hinge_angle;
    double worst_thesis = 0.0;
    expect_track(s, parts.value.patches[0], {0, 60, h}, [&](double t) {
        const double c = std::cos(t / 2);
        const double py = -h * std::sin(a) * c /
                          std::sqrt(std::pow(std::cos(a), 2) + std::pow(std::sin(a) * c, 2));
        worst_thesis = std::max(worst_thesis, std::abs(py + h * std::sin(a) * c));
        return Vec3(0, 60 + py, std::sqrt(h * h - py * py));
    });
    EXPECT_GT(worst_thesis, 1.0); // the printed form is off by more than a millimetre mid-way
}

// docs/MATH.md, "Rotation": thesis eq 4.10 holds; P_x = −h sin δ.
TEST(ClosedForm, RotationArmFollowsThesisEquation410)
{
    Scaffold s = card();
    RotationArmParams p;
    p.offset = 60;
    p.spine = 40;
    p.run = 30;
    p.arm = 45; // <= l²/w = 53.3
    const auto parts = add_rotation_arm(s, central_fold(s), p);
    ASSERT_TRUE(parts.ok) << parts.diagnostics.front().message;
    const double l = p.spine, w = p.run, h = p.arm;
    expect_track(s, parts.value.patches[0], {-h, 60 + l, 0}, [&](double t) {
        const double c = std::cos(t / 2);
        const double py =
            (l * l * l - l * w * w * c * c - 2 * l * w * h * c * c) / (l * l + w * w * c * c);
        const Vec3 tip = rotation_arm_tip(p, t);
        EXPECT_NEAR(tip.x(), -h * std::sin(t / 2), 1e-12);
        EXPECT_NEAR(tip.y(), 60 + py, 1e-9);
        return tip;
    });
    const ValidityReport r = check_validity(s);
    EXPECT_TRUE(r.valid()) << (r.diagnostics.empty() ? "" : r.diagnostics.front().message);
}

TEST(RotationArm, ArmLongerThanSpineSquaredOverRunDipsUnderTheBackdrop)
{
    Scaffold s = card();
    RotationArmParams p;
    p.offset = 60;
    p.spine = 40;
    p.run = 30;
    p.arm = 1.01 * p.spine * p.spine / p.run;
    const auto refused = add_rotation_arm(s, central_fold(s), p);
    EXPECT_FALSE(refused.ok);
    EXPECT_EQ(refused.diagnostics.front().parameter, "Arm");
    // Built anyway from raw patches, the simulator finds the arm passing through the backdrop.
    p.arm = 1.2 * p.spine * p.spine / p.run;
    const Vec3 O(0, 60, 0), R(0, 100, 0), S(30, 100, 0), Sb(-30, 100, 0), P(-p.arm, 100, 0);
    Patch wing, other;
    wing.id = 2;
    wing.outer = {O, S, P};
    other.id = 3;
    other.outer = {O, R, Sb};
    s.patches.push_back(wing);
    s.patches.push_back(other);
    s.hinges.push_back({1, 0, 2, O, S, FoldDirection::valley});
    s.hinges.push_back({2, 1, 3, O, Sb, FoldDirection::valley});
    s.hinges.push_back({3, 2, 3, O, R, FoldDirection::mountain});
    const ValidityReport r = check_validity(s);
    EXPECT_FALSE(r.intersection_free);
    bool arm_through_backdrop = false;
    for (const Crossing& c : r.crossings)
        arm_through_backdrop |= (c.patch_a == 1 && c.patch_b == 2);
    EXPECT_TRUE(arm_through_backdrop);
}

// docs/MATH.md, "Diagonal translation": a step fold on the wings of a vertical-spine v-fold.
TEST(ClosedForm, StepOnVFoldWingsTranslatesDiagonally)
{
    Scaffold s = card();
    VFoldParams v;
    v.offset = 60;
    v.run = 40;
    v.hinge_angle = fixtures::deg(45);
    v.spine = 45;
    v.spine_angle = M_PI / 2;
    const auto vfold = add_v_fold(s, central_fold(s), v);
    ASSERT_TRUE(vfold.ok);
    ASSERT_EQ(vfold.value.offered.size(), 1u);
    const BasePatchPair& wings = vfold.value.offered[0];
    EXPECT_NEAR(wings.opening, M_PI / 2, 1e-12); // 2α
    StepFoldParams step;
    step.offset = 10;
    step.width = 20;
    step.run_ground = step.run_backdrop = 8;
    const auto parts = add_step_fold(s, wings, step, "Step");
    ASSERT_TRUE(parts.ok) << parts.diagnostics.front().message;
    auto nose = [&](double theta) {
        const BasePatchPair w = v_fold_wings(v, M_PI, theta);
        const Vec2 n = step_nose(step, w.opening);
        return w.to_world(n.x(), step.offset, n.y());
    };
    expect_track(s, parts.value.patches[0], nose(M_PI), nose);
    const ValidityReport r = check_validity(s);
    EXPECT_TRUE(r.valid()) << (r.diagnostics.empty() ? "" : r.diagnostics.front().message);
}

TEST(MechanismBuilder, AMechanismTooBigForItsHostIsTakenOutAgain)
{
    Scaffold s = card();
    VFoldParams v;
    v.offset = 60;
    v.run = 40;
    v.spine = 45;
    v.spine_angle = M_PI / 2;
    const auto vfold = add_v_fold(s, central_fold(s), v);
    ASSERT_TRUE(vfold.ok);
    const size_t patches = s.patches.size(), hinges = s.hinges.size();
    StepFoldParams step;
    step.offset = 30; // near the tip the triangular wings are too narrow for 12 mm runs
    step.width = 14;
    step.run_ground = step.run_backdrop = 12;
    const auto r = add_step_fold(s, vfold.value.offered[0], step, "Step");
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.diagnostics.front().code, DiagnosticCode::mechanism_does_not_fit);
    EXPECT_NE(r.diagnostics.front().message.find("VFold.wing"), std::string::npos);
    EXPECT_EQ(s.patches.size(), patches);
    EXPECT_EQ(s.hinges.size(), hinges);
}

// docs/MATH.md, "Vertical translation": the half v-box's front top corner.
TEST(ClosedForm, VerticalTranslationMovesAlongTheFold)
{
    Scaffold s = card();
    VBoxFoldParams p;
    p.offset = 80;
    p.side = 40;
    p.height = 30;
    p.wall_angle = fixtures::deg(40);
    const auto parts = add_vertical_translation(s, central_fold(s), p);
    ASSERT_TRUE(parts.ok) << parts.diagnostics.front().message;
    EXPECT_EQ(parts.value.patches.size(), 4u); // FL, FR, TG, TB
    const double h = p.height, a = p.wall_angle;
    expect_track(s, parts.value.patches[0], {0, 80, 30}, [&](double t) {
        const Vec3 corner = v_box_front_corner(p, t);
        const double c = std::cos(t / 2);
        const double py = -h * std::sin(a) * c /
                          std::sqrt(std::pow(std::cos(a), 2) + std::pow(std::sin(a) * c, 2));
        EXPECT_NEAR(corner.x(), 0.0, 1e-12);
        EXPECT_NEAR(corner.y(), 80 + py, 1e-9);
        return corner;
    });
    const ValidityReport r = check_validity(s);
    EXPECT_TRUE(r.valid()) << (r.diagnostics.empty() ? "" : r.diagnostics.front().message);
}

// docs/MATH.md, "Horizontal translation": M through a slit along a step fold's nose.
TEST(ClosedForm, HorizontalTranslationSlidesThroughTheSlit)
{
    Scaffold s = card();
    HorizontalTranslationParams p;
    p.offset = 60;
    p.width = 50;
    p.run_ground = 40;
    p.run_backdrop = 20;
    p.reach = 70;
    const auto parts = add_horizontal_translation(s, central_fold(s), p);
    ASSERT_TRUE(parts.ok) << parts.diagnostics.front().message;
    ASSERT_EQ(parts.value.patches.size(), 3u); // riser, tread, M
    ASSERT_EQ(s.slits.size(), 1u);
    const int M = parts.value.patches[2];
    expect_track(s, M, {70, 80, 0}, [&](double t) {
        const Vec2 tip = horizontal_translation_tip(p, t);
        // |C| = √(a² + b² + 2ab cos θ): thesis eq 4.3 with its square root.
        const double l = std::sqrt(40.0 * 40 + 20.0 * 20 + 2 * 40.0 * 20 * std::cos(t));
        EXPECT_NEAR(step_nose(p, t).norm(), l, 1e-12);
        return Vec3(tip.x(), 80, tip.y());
    });
    const ValidityReport r = check_validity(s);
    EXPECT_TRUE(r.valid()) << (r.diagnostics.empty() ? "" : r.diagnostics.front().message);
    // Without the slit, M would fall freely about the hinge.
    Scaffold loose = s;
    loose.slits.clear();
    EXPECT_FALSE(check_validity(loose).stable);
}

// docs/MATH.md, "A rotation arm on a floating layer's side" (thesis §4.3.4, last paragraph): the
// arm stands on a side pair open 90° at the design state, which opens at θ/2 while the card
// opens at θ, so the arm turns about the support's foot at x = ±support, off the central fold.
namespace {
struct LayerArm {
    FloatingLayerParams layer;
    RotationArmParams arm;
};

LayerArm layer_arm()
{
    LayerArm d;
    d.layer.offset = 60;
    d.layer.width = 70;
    d.layer.height = 35;
    d.layer.support = 30;
    d.layer.overhang = 0;
    d.arm.offset = 15;
    d.arm.spine = 40;
    d.arm.run = 25; // < the support's height 35
    d.arm.arm = 30; // <= min(l²/w = 64, 35)
    return d;
}
} // namespace

TEST(ClosedForm, RotationArmOnAFloatingLayersSideTurnsAboutTheSupport)
{
    for (LayerSide side : {LayerSide::ground, LayerSide::backdrop}) {
        SCOPED_TRACE(side == LayerSide::ground ? "side_ground" : "side_backdrop");
        Scaffold s = card();
        const LayerArm d = layer_arm();
        const auto layer = add_floating_layer(s, central_fold(s), d.layer, "Layer");
        ASSERT_TRUE(layer.ok) << layer.diagnostics.front().message;
        const BasePatchPair& host = layer.value.offered[side == LayerSide::ground ? 1 : 2];
        // The closed-form frame at the design angle is the offered pair.
        const BasePatchPair at_design = floating_layer_side(d.layer, side, M_PI);
        EXPECT_LT((at_design.origin - host.origin).norm(), 1e-12);
        EXPECT_LT((at_design.up - host.up).norm(), 1e-12);
        EXPECT_NEAR(at_design.opening, host.opening, 1e-12);
        const auto arm = add_rotation_arm(s, host, d.arm, "Arm");
        ASSERT_TRUE(arm.ok) << arm.diagnostics.front().message;
        // The tip vertex of the arm's wing at the design state, read off the built patch.
        const Patch* wing = s.find_patch(arm.value.patches[0]);
        ASSERT_EQ(wing->outer.size(), 3u);
        const Vec3 tip0 = wing->outer[2];
        EXPECT_LT((tip0 - rotation_arm_tip_on_layer_side(d.arm, d.layer, side, M_PI)).norm(), 1e-9);
        // The support's foot is the centre of the turn: at 180° the tip's distance to the
        // hinge line (x = ±30, z = 0) is that of P from the host hinge, √(P_x² + P_z²).
        const Vec3 local = rotation_arm_tip(d.arm, M_PI / 2);
        const double sign = side == LayerSide::ground ? 1 : -1;
        EXPECT_NEAR(std::hypot(tip0.x() - sign * 30, tip0.z()), std::hypot(local.x(), local.z()),
                    1e-9);
        const auto sweep = simulate_fold(s, {M_PI, 170 * M_PI / 180, 120 * M_PI / 180,
                                             75 * M_PI / 180, 30 * M_PI / 180, 5 * M_PI / 180});
        ASSERT_TRUE(sweep.value.complete);
        for (const FoldState& st : sweep.value.states) {
            const Vec3 at = fixtures::world_point(s, st, wing->id, tip0);
            const Vec3 expected = rotation_arm_tip_on_layer_side(d.arm, d.layer, side, st.angle);
            EXPECT_LT((at - expected).norm(), 1e-6) << "at " << st.angle * 180 / M_PI << "°";
        }
        const ValidityReport r = check_validity(s);
        EXPECT_TRUE(r.valid()) << (r.diagnostics.empty() ? "" : r.diagnostics.front().message);
    }
}

TEST(RotationArm, OnAFloatingLayersSideNamesItsBadParameters)
{
    const LayerArm d = layer_arm();
    auto refused = [&](RotationArmParams arm, const std::string& parameter,
                       const std::string& mentions) {
        Scaffold s = card();
        const auto layer = add_floating_layer(s, central_fold(s), d.layer, "Layer");
        ASSERT_TRUE(layer.ok);
        const size_t patches = s.patches.size();
        const auto r = add_rotation_arm(s, layer.value.offered[1], arm, "Arm");
        ASSERT_FALSE(r.ok);
        EXPECT_EQ(r.diagnostics.front().parameter, parameter);
        EXPECT_NE(r.diagnostics.front().message.find(mentions), std::string::npos)
            << r.diagnostics.front().message;
        EXPECT_EQ(s.patches.size(), patches);
    };
    RotationArmParams a = d.arm;
    a.run = 35; // the support is 35 mm high: the backdrop wing would run off it
    refused(a, "Run", "< 35 mm");
    a = d.arm;
    a.arm = 36; // longer than the support
    refused(a, "Arm", "<= 35 mm");
    a = d.arm;
    a.spine = 71; // the layer is 70 mm wide
    refused(a, "Spine", "<= 70 mm");
    // A host closed at the design state has no opening to build on.
    Scaffold s = card();
    BasePatchPair closed = central_fold(s);
    closed.opening = 0;
    const auto r = add_rotation_arm(s, closed, d.arm, "Arm");
    ASSERT_FALSE(r.ok);
    EXPECT_EQ(r.diagnostics.front().parameter, "Host");
}
