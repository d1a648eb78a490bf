#include <gtest/gtest.h>

#include <cmath>

#include "popup/mechanisms/box_fold.hpp"
#include "popup/mechanisms/floating_layer.hpp"
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
Scaffold card(double width = 240, double depth = 140)
{
    return fixtures::generator_card(width, depth);
}

std::string first_message(const ValidityReport& r)
{
    return r.diagnostics.empty() ? "" : r.diagnostics.front().message;
}

template <class Params> Params placed(Params p, double offset, double width)
{
    p.offset = offset;
    p.width = width;
    return p;
}
} // namespace

TEST(CardMechanisms, SymmetricTentIsValidAndFollowsTheClosedForm)
{
    Scaffold s = card();
    TentFoldParams p = placed(TentFoldParams{}, 40, 60);
    const auto parts = add_tent_fold(s, central_fold(s), p);
    ASSERT_TRUE(parts.ok);
    ASSERT_EQ(parts.value.patches.size(), 2u);
    const ValidityReport r = check_validity(s);
    EXPECT_TRUE(r.valid()) << first_message(r);
    const auto sweep = simulate_fold(s, fixtures::angle_range(180, 0, 19));
    const double a = p.foot, sl = p.slope;
    for (const FoldState& st : sweep.value.states) {
        const double z = a * std::cos(st.angle / 2) +
                         std::sqrt(sl * sl - a * a * std::pow(std::sin(st.angle / 2), 2));
        const Vec3 apex = fixtures::world_point(s, st, parts.value.patches[0],
                                                {0, 40, std::sqrt(sl * sl - a * a)});
        EXPECT_NEAR(apex.z(), z, 1e-9 * s.size());
    }
}

TEST(CardMechanisms, AsymmetricTentFoldsFlat)
{
    Scaffold s = card();
    TentFoldParams p = placed(TentFoldParams{}, 40, 60);
    p.foot = 30;
    p.foot_backdrop = 20;
    p.slope = 40;
    EXPECT_DOUBLE_EQ(tent_backdrop_slope(p), 50.0);
    ASSERT_TRUE(add_tent_fold(s, central_fold(s), p).ok);
    const ValidityReport r = check_validity(s);
    EXPECT_TRUE(r.valid()) << first_message(r);
}

TEST(CardMechanisms, StepAndVFoldAreValid)
{
    Scaffold s = card();
    ASSERT_TRUE(add_step_fold(s, central_fold(s), placed(StepFoldParams{}, 20, 50)).ok);
    VFoldParams v;
    v.offset = 120;
    ASSERT_TRUE(add_v_fold(s, central_fold(s), v).ok);
    const ValidityReport r = check_validity(s);
    EXPECT_TRUE(r.valid()) << first_message(r);
}

TEST(BoxFold, IsValidAndItsFrontPopsOutward)
{
    Scaffold s = card();
    const auto box = add_box_fold(s, central_fold(s), placed(BoxFoldParams{}, 80, 60));
    ASSERT_TRUE(box.ok);
    EXPECT_EQ(box.value.patches.size(), 9u);
    EXPECT_EQ(box.value.offered.size(), 3u);
    const ValidityReport r = check_validity(s);
    EXPECT_TRUE(r.valid()) << first_message(r);
    // The crease between FL and FR leaves the box's front (y = 80) toward smaller y.
    const auto sweep = simulate_fold(s, {fixtures::deg(90)});
    const int fl = box.value.patches[5];
    const Vec3 crease = fixtures::world_point(s, sweep.value.states[0], fl, {0, 80, 15});
    EXPECT_LT(crease.y(), 80.0 - 1.0);
}

TEST(BoxFold, WithoutFrontAndBackItShears)
{
    Scaffold s = card();
    BoxFoldParams p = placed(BoxFoldParams{}, 80, 60);
    p.front = p.back = false;
    ASSERT_TRUE(add_box_fold(s, central_fold(s), p).ok);
    const ValidityReport r = check_validity(s);
    EXPECT_FALSE(r.stable);
}

TEST(Nesting, ThreeLevelsAndStepsOnBothBoxSides)
{
    Scaffold s = card(240, 140);
    const auto lower = add_box_fold(s, central_fold(s), placed(BoxFoldParams{}, 60, 100));
    ASSERT_TRUE(lower.ok);
    BoxFoldParams upper_params = placed(BoxFoldParams{}, 20, 60);
    upper_params.depth_ground = upper_params.depth_backdrop = 20;
    upper_params.height = 20;
    const auto upper = add_box_fold(s, lower.value.offered[0], upper_params, "Upper");
    ASSERT_TRUE(upper.ok) << upper.diagnostics.front().message;
    TentFoldParams tent = placed(TentFoldParams{}, 10, 40);
    tent.foot = tent.foot_backdrop = 10;
    tent.slope = 14;
    ASSERT_TRUE(add_tent_fold(s, upper.value.offered[0], tent).ok);
    StepFoldParams step = placed(StepFoldParams{}, 10, 60);
    step.run_ground = 15;
    step.run_backdrop = 15;
    ASSERT_TRUE(add_step_fold(s, lower.value.offered[1], step).ok);
    // Between the upper box's side and the lower box's top (its side pair's ground is TG).
    EXPECT_EQ(upper.value.offered[1].ground, lower.value.offered[0].ground);
    StepFoldParams upper_step = placed(StepFoldParams{}, 10, 40);
    upper_step.run_ground = 6;
    upper_step.run_backdrop = 8;
    ASSERT_TRUE(add_step_fold(s, upper.value.offered[1], upper_step, "UpperStep").ok);
    const ValidityReport r = check_validity(s);
    EXPECT_TRUE(r.valid()) << first_message(r);
}

TEST(MechanismParameters, BadValuesAreNamedAndLeaveTheScaffoldAlone)
{
    const Scaffold base = card();
    const BasePatchPair host = central_fold(base);
    auto expect_error = [&](auto add, const std::string& parameter) {
        Scaffold s = base;
        const auto r = add(s);
        EXPECT_FALSE(r.ok) << parameter;
        ASSERT_FALSE(r.diagnostics.empty()) << parameter;
        EXPECT_EQ(r.diagnostics.front().parameter, parameter);
        EXPECT_EQ(r.diagnostics.front().code, DiagnosticCode::bad_parameter);
        EXPECT_NE(r.diagnostics.front().message.find("must be"), std::string::npos);
        EXPECT_EQ(s.patches.size(), base.patches.size());
        EXPECT_EQ(s.hinges.size(), base.hinges.size());
    };
    for (double bad : {0.0, -3.0, std::nan(""), 1e9}) {
        expect_error(
            [&](Scaffold& s) {
                TentFoldParams p = placed(TentFoldParams{}, 40, 60);
                p.foot = bad;
                return add_tent_fold(s, host, p);
            },
            "Foot");
        expect_error(
            [&](Scaffold& s) {
                StepFoldParams p = placed(StepFoldParams{}, 40, 60);
                p.run_backdrop = bad;
                return add_step_fold(s, host, p);
            },
            "RunBackdrop");
        expect_error(
            [&](Scaffold& s) {
                BoxFoldParams p = placed(BoxFoldParams{}, 40, 60);
                p.height = bad;
                return add_box_fold(s, host, p);
            },
            "Height");
        expect_error(
            [&](Scaffold& s) {
                VFoldParams p;
                p.spine = bad;
                return add_v_fold(s, host, p);
            },
            "Spine");
        expect_error(
            [&](Scaffold& s) { return add_box_fold(s, host, placed(BoxFoldParams{}, 40, bad)); },
            "Width");
        expect_error(
            [&](Scaffold& s) {
                VBoxFoldParams p;
                p.side = bad;
                return add_v_box_fold(s, host, p);
            },
            "Side");
        expect_error(
            [&](Scaffold& s) {
                FloatingLayerParams p = placed(FloatingLayerParams{}, 40, 60);
                p.support = bad;
                return add_floating_layer(s, host, p);
            },
            "Support");
        expect_error(
            [&](Scaffold& s) {
                RotationArmParams p;
                p.offset = 40;
                p.spine = bad;
                return add_rotation_arm(s, host, p);
            },
            "Spine");
        expect_error(
            [&](Scaffold& s) {
                HorizontalTranslationParams p;
                p.offset = 40;
                p.reach = bad;
                return add_horizontal_translation(s, host, p);
            },
            "Reach");
        expect_error(
            [&](Scaffold& s) {
                VBoxFoldParams p;
                p.offset = 40;
                p.height = bad;
                return add_vertical_translation(s, host, p);
            },
            "Height");
    }
    // Inconsistent: slopes too short to meet.
    expect_error(
        [&](Scaffold& s) {
            TentFoldParams p = placed(TentFoldParams{}, 40, 60);
            p.slope = 25;
            return add_tent_fold(s, host, p);
        },
        "Slope");
    expect_error(
        [&](Scaffold& s) { return add_step_fold(s, host, placed(StepFoldParams{}, 200, 60)); },
        "Offset");
}

TEST(Combinations, BoxFoldsTooCloseCollideAndApartPass)
{
    auto two_boxes = [](double gap) {
        Scaffold s = card(300, 140);
        BoxFoldParams p = placed(BoxFoldParams{}, 40, 60);
        p.depth_ground = p.depth_backdrop = p.height = 40;
        add_box_fold(s, central_fold(s), p, "BoxA");
        p.offset = 100 + gap;
        add_box_fold(s, central_fold(s), p, "BoxB");
        return check_validity(s);
    };
    // Closed, each front and back crease reaches d/2 = 40 mm beyond its box (thesis §4.2.2).
    const ValidityReport close = two_boxes(10);
    EXPECT_FALSE(close.intersection_free);
    const ValidityReport apart = two_boxes(90);
    EXPECT_TRUE(apart.valid()) << first_message(apart);
}

TEST(VBoxFold, IsValidAndLeansOutOfItsFrontWhenClosed)
{
    Scaffold s = card();
    VBoxFoldParams p;
    p.offset = 60;
    p.side = 40;
    p.height = 30;
    const auto parts = add_v_box_fold(s, central_fold(s), p);
    ASSERT_TRUE(parts.ok);
    EXPECT_EQ(parts.value.patches.size(), 6u);
    const ValidityReport r = check_validity(s);
    EXPECT_TRUE(r.valid()) << first_message(r);
    // Closed, the front top corner lies height/√2 in front of the front corner (thesis Fig 4.9,
    // mirrored: our front faces −y).
    const auto sweep = simulate_fold(s, {0.0});
    const Vec3 top =
        fixtures::world_point(s, sweep.value.states[0], parts.value.patches[0], {0, 60, 30});
    EXPECT_NEAR(top.y(), 60 - 30 / std::sqrt(2.0), 1e-9 * s.size());
    EXPECT_NEAR(parts.value.sweep_from, 60 - 30 / std::sqrt(2.0), 1e-9);
}

TEST(VBoxFold, TopGluedToTheBackWallIsNotFoldable)
{
    Scaffold s = card();
    VBoxFoldParams p;
    p.offset = 60;
    const auto parts = add_v_box_fold(s, central_fold(s), p);
    ASSERT_TRUE(parts.ok);
    const int BR = parts.value.patches[3], TB = parts.value.patches[5];
    s.glue.push_back({TB, BR});
    const ValidityReport r = check_validity(s);
    EXPECT_FALSE(r.foldable);
    EXPECT_GT(r.locked_at * 180 / M_PI, 170.0);
}

TEST(FloatingLayer, PlatformStaysParallelToEachBaseAtItsHeight)
{
    Scaffold s = card();
    FloatingLayerParams p;
    p.offset = 60;
    p.width = 80;
    p.height = 25;
    p.support = 20;
    p.overhang = 15;
    const auto layer = add_floating_layer(s, central_fold(s), p);
    ASSERT_TRUE(layer.ok);
    ASSERT_EQ(layer.value.offered.size(), 3u);
    EXPECT_DOUBLE_EQ(layer.value.offered[0].ground_depth, 35.0);
    const ValidityReport r = check_validity(s);
    EXPECT_TRUE(r.valid()) << first_message(r);
    // The platform's ground half stays parallel to the ground; C keeps the crease on the
    // bisector, so its outer edge is at c·ẑ + 35·g(θ): c·sin(θ/2) above the ground.
    const int TG = layer.value.patches[3];
    const auto sweep = simulate_fold(s, fixtures::angle_range(180, 0, 37));
    for (const FoldState& st : sweep.value.states) {
        const double h = st.angle / 2;
        const Vec3 edge = fixtures::world_point(s, st, TG, {35, 70, 25});
        const Vec3 ground_normal(-std::cos(h), 0, std::sin(h));
        const Vec3 ground_dir(std::sin(h), 0, std::cos(h));
        EXPECT_NEAR(edge.dot(ground_normal), 25.0 * std::sin(h), 1e-9 * s.size());
        EXPECT_NEAR(edge.dot(ground_dir), 35.0 + 25.0 * std::cos(h), 1e-9 * s.size());
        const Vec3 other = fixtures::world_point(s, st, TG, {35, 120, 25});
        EXPECT_NEAR((other - edge).dot(ground_normal), 0.0, 1e-9 * s.size());
    }
}

TEST(FloatingLayer, CarriesATentOnItsPlatform)
{
    Scaffold s = card();
    FloatingLayerParams p;
    p.offset = 60;
    p.width = 80;
    const auto layer = add_floating_layer(s, central_fold(s), p);
    ASSERT_TRUE(layer.ok);
    TentFoldParams t;
    t.offset = 20;
    t.width = 40;
    t.foot = t.foot_backdrop = 12;
    t.slope = 16;
    ASSERT_TRUE(add_tent_fold(s, layer.value.offered[0], t).ok);
    const ValidityReport r = check_validity(s);
    EXPECT_TRUE(r.valid()) << first_message(r);
}

TEST(BoxFold, SeveralPanelPairsPerEndStayValid)
{
    Scaffold s = card();
    BoxFoldParams p = placed(BoxFoldParams{}, 80, 60);
    p.panel_pairs = 3;
    const auto box = add_box_fold(s, central_fold(s), p);
    ASSERT_TRUE(box.ok);
    EXPECT_EQ(box.value.patches.size(), 5u + 2 * 2 * 3); // C, L, R, TG, TB and 3 pairs per end
    const ValidityReport r = check_validity(s);
    EXPECT_TRUE(r.valid()) << first_message(r);
    p.panel_pairs = 0;
    Scaffold other = card();
    const auto bad = add_box_fold(other, central_fold(other), p);
    EXPECT_FALSE(bad.ok);
    EXPECT_EQ(bad.diagnostics.front().parameter, "PanelPairs");
}

TEST(Generators, ABasePairOfAnotherDesignIsRefused)
{
    // A pair from a larger card: its hinge runs past this card's fold, and a pair naming a patch
    // this design lacks: both refused, the design untouched.
    const Scaffold other = fixtures::generator_card(400);
    Scaffold s = fixtures::generator_card(200);
    const size_t patches = s.patches.size(), hinges = s.hinges.size();
    BasePatchPair foreign = central_fold(other);
    TentFoldParams p;
    p.width = 40;
    p.offset = 20; // fits either fold: only the pair itself is wrong
    for (BasePatchPair host : {foreign, [&] {
                                   BasePatchPair missing = central_fold(s);
                                   missing.backdrop = 77;
                                   return missing;
                               }()}) {
        const Result<MechanismParts> r = add_tent_fold(s, host, p, "Tent");
        ASSERT_FALSE(r.ok);
        EXPECT_EQ(r.diagnostics.front().code, DiagnosticCode::bad_host)
            << r.diagnostics.front().message;
        EXPECT_EQ(r.diagnostics.front().parameter, "Host");
        EXPECT_EQ(s.patches.size(), patches);
        EXPECT_EQ(s.hinges.size(), hinges);
    }
}

TEST(Generators, ParametersThatMakeAPartVanishAreTheMechanismsError)
{
    // In range, yet degenerate: a 1e300 mm slope runs off to infinity, a wall angle a hair below
    // 90° leaves a fold a fraction of a micrometre long.
    Scaffold s = fixtures::generator_card(200);
    const size_t patches = s.patches.size(), hinges = s.hinges.size();
    TentFoldParams tent = placed(TentFoldParams{}, 40, 60);
    tent.slope = 1e300;
    const Result<MechanismParts> huge = add_tent_fold(s, central_fold(s), tent, "Tent");
    ASSERT_FALSE(huge.ok);
    EXPECT_EQ(huge.diagnostics.front().code, DiagnosticCode::bad_parameter);
    EXPECT_EQ(huge.diagnostics.front().message.rfind("Tent: Slope = 1e+300 mm, must be > ", 0), 0u)
        << huge.diagnostics.front().message;
    VBoxFoldParams vbox;
    vbox.offset = 60;
    vbox.wall_angle = (90.0 - 1e-3) * M_PI / 180.0;
    const Result<MechanismParts> thin = add_v_box_fold(s, central_fold(s), vbox, "VBox");
    ASSERT_FALSE(thin.ok);
    // Both name their property and a range that exists.
    EXPECT_EQ(thin.diagnostics.front().message.rfind(
                  "VBox: WallAngle = 89.999 °, must be > 0° and <= 89.28", 0),
              0u)
        << thin.diagnostics.front().message;
    EXPECT_EQ(s.patches.size(), patches);
    EXPECT_EQ(s.hinges.size(), hinges);
}

TEST(Generators, APartShorterThanTheShortestFoldIsNamedWithItsRange)
{
    // Boxes nested with fitted defaults shrink with each host until a part is shorter than a
    // fold can be; the part's own property carries the error, not a fold number.
    Scaffold s = fixtures::generator_card(200);
    const double shortest = shortest_fold(s);
    EXPECT_NEAR(shortest, 1e-5 * s.size(), 1e-12);
    const size_t patches = s.patches.size();
    BoxFoldParams box = placed(BoxFoldParams{}, 40, 60);
    box.height = 0.5 * shortest;
    const Result<MechanismParts> r = add_box_fold(s, central_fold(s), box, "Box");
    ASSERT_FALSE(r.ok);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics.front().parameter, "Height");
    EXPECT_EQ(r.diagnostics.front().message.rfind("Box: Height = ", 0), 0u)
        << r.diagnostics.front().message;
    EXPECT_NE(r.diagnostics.front().message.find("must be >= "), std::string::npos);
    EXPECT_EQ(s.patches.size(), patches);
    box.height = 2 * shortest; // just long enough: built
    EXPECT_TRUE(add_box_fold(s, central_fold(s), box, "Box").ok);
}

TEST(Generators, APartTooLongForItsHostIsNamedNotAnOffsetRangeThatDoesNotExist)
{
    // A v-box 2·Side·cos(WallAngle) long on a shorter fold: no Offset fits, so Side is at fault.
    Scaffold s = fixtures::generator_card(200, 300);
    const BasePatchPair fold = central_fold(s);
    VBoxFoldParams v;
    v.offset = 20;
    v.wall_angle = M_PI / 4;
    v.side = 200; // reaches 141 mm into the 300 mm pages, but runs 283 mm along the 200 mm fold
    const Result<MechanismParts> mover = add_vertical_translation(s, fold, v, "Mover");
    ASSERT_FALSE(mover.ok);
    const std::string& message = mover.diagnostics.front().message;
    EXPECT_EQ(message.rfind("Mover: Side = ", 0), 0u) << message;
    EXPECT_EQ(message.find("Offset"), std::string::npos) << message;
    EXPECT_EQ(mover.diagnostics.front().parameter, "Side");
}
