// The ranges infeasibility() names, feasible() agreeing with it, and the paper: feasible
// mechanisms lay out on the sheets of the card PopUp sizes to A4.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "motion/motion_feasibility.hpp"
#include "motion_fixtures.hpp"
#include "popup/model/card.hpp"
#include "popup/sheets/nest.hpp"
#include "popup/sheets/sheet_layout.hpp"

namespace popup::motion {
namespace {

using testing::sample_mechanism;

TEST(MotionFeasibility, InfeasibleParametersAreNamed)
{
    CardParams card;
    card.depth = 148;
    MotionMechanism m = sample_mechanism(MotionKind::rotation);
    m.rotation().arm = 100; // arm far beyond spine²/run = 53 mm
    const std::string why = infeasibility(m, card);
    EXPECT_NE(why.find("arm = 100"), std::string::npos) << why;
    m = sample_mechanism(MotionKind::horizontal);
    m.horizontal().run_backdrop = 45; // run_backdrop above run_ground
    EXPECT_NE(infeasibility(m, card).find("run_backdrop"), std::string::npos);
}

TEST(MotionFeasibility, AnOffFoldArmsGluedCreaseKeepsItsTabRoom)
{
    // The wing glued to the support along the diagonal of its Spine × Run corner: 20°..70° from
    // the support's edges. Spine 40: Run from 40·tan 20° = 14.56 to 40·tan 70° = 109.9 mm.
    const CardParams card = testing::a4_card();
    for (double side : {1.0, -1.0}) {
        MotionMechanism m = testing::off_fold_rotation(side); // spine 40, run 25
        RotationMotion& r = m.rotation();
        r.arm = 10; // arm under spine²/run
        EXPECT_EQ(infeasibility(m, card), "") << side;
        r.run = 14.0; // 19.3° from the hinge
        EXPECT_NE(infeasibility(m, card).find("run = 14"), std::string::npos) << side;
        r.run = 15.0;
        EXPECT_EQ(infeasibility(m, card), "") << side;
        r.run = 100.0; // 68.2°: still in, the tallest the card allows with a 30 mm hinge
        r.arm = 5;
        EXPECT_EQ(infeasibility(m, card), "") << side;
    }
    MotionMechanism steep = testing::off_fold_rotation(1);
    steep.rotation().spine = 12; // spine 12, run 25: 64.4° in; run 40: 73.3° out
    steep.rotation().arm = 2;
    EXPECT_EQ(infeasibility(steep, card), "");
    steep.rotation().run = 40;
    EXPECT_NE(infeasibility(steep, card).find("tan 70"), std::string::npos)
        << infeasibility(steep, card);
}

TEST(MotionFeasibility, FeasibleAgreesWithInfeasibility)
{
    // feasible() is infeasibility() without its words: over random steps from each kind's sample
    // (and the off-fold arm) both answers occur and the two always agree.
    const CardParams card = testing::a4_card();
    std::mt19937_64 rng(7);
    std::normal_distribution<double> step(0.0, 1.0);
    int yes = 0, no = 0;
    for (int k = 0; k <= motion_kind_count; ++k) {
        const MotionMechanism start =
            k < motion_kind_count ? sample_mechanism(MotionKind(k)) : testing::off_fold_rotation(1);
        for (int trial = 0; trial < 400; ++trial) {
            MotionMechanism m = start;
            for (int i = 0; i < parameter_count(m.kind()); ++i)
                parameter(m, i) +=
                    step(rng) *
                    (parameter_info(m.kind(), i).role == ParameterRole::angle ? 0.3 : 15.0);
            const bool ok = infeasibility(m, card).empty();
            EXPECT_EQ(feasible(m, card), ok) << k << " trial " << trial;
            (ok ? yes : no) += 1;
        }
    }
    EXPECT_GT(yes, 100);
    EXPECT_GT(no, 100);
}

// m built on the card PopUp makes for A4 lays out on A4 sheets.
bool lays_out_on_a4(const MotionMechanism& m)
{
    Scaffold s = make_card(testing::card_for_a4_sheets()).value;
    std::vector<FittedMechanism> rows;
    EXPECT_TRUE(build_mechanism(s, central_fold(s), m, "M", rows).ok);
    SheetOptions a4;
    a4.nest.paper = paper_by_name("A4").value;
    const auto sheets = layout_sheets(s, a4);
    if (!sheets.ok)
        ADD_FAILURE() << "does not lay out: " << sheets.diagnostics.front().message;
    return sheets.ok;
}

TEST(MotionFeasibility, ADiagonalsWingsMustFitTheCardsSheet)
{
    // PopUp's card for A4 is 186 x 136.5 mm (open, it fills A4 inside the sheets' margins). A
    // diagonal with a 193 mm run at 40.2 deg (found on a long capture) unfolds its two wings into
    // one piece 378 mm long: diagonal_wings_fit says no, and the sheets indeed cannot lay it out
    // on A4. Feasible diagonals drawn at random that it passes all lay out on A4.
    const CardParams card = testing::card_for_a4_sheets();
    const MotionMechanism long_run =
        diagonal_mechanism(27.45, 193.22, 40.19 * M_PI / 180, 40.72, 10, 12, 16, 12);
    EXPECT_EQ(infeasibility(long_run, card), "");
    EXPECT_FALSE(diagonal_wings_fit(long_run, card));
    {
        Scaffold built = make_card(card).value;
        std::vector<FittedMechanism> rows;
        ASSERT_TRUE(build_mechanism(built, central_fold(built), long_run, "M", rows).ok);
        SheetOptions a4;
        a4.nest.paper = paper_by_name("A4").value;
        EXPECT_FALSE(layout_sheets(built, a4).ok);
    }
    EXPECT_TRUE(diagonal_wings_fit(sample_mechanism(MotionKind::rotation), card));
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> offset(0, 120), run(20, 200), angle(10, 80),
        spine(30, 120);
    int passed = 0, refused = 0;
    for (int trial = 0; trial < 5000 && passed < 12; ++trial) {
        MotionMechanism m = long_run;
        VFoldParams& v = m.diagonal().v_fold;
        v.offset = offset(rng);
        v.run = run(rng);
        v.hinge_angle = angle(rng) * M_PI / 180;
        v.spine = spine(rng);
        if (!infeasibility(m, card).empty())
            continue;
        if (!diagonal_wings_fit(m, card)) {
            ++refused;
            continue;
        }
        ++passed;
        EXPECT_TRUE(lays_out_on_a4(m))
            << "run " << v.run << " angle " << v.hinge_angle << " spine " << v.spine;
    }
    EXPECT_GE(passed, 12);
    EXPECT_GT(refused, 0);
}

TEST(MotionFeasibility, EveryFeasibleMechanismLaysOutOnTheCardsPaper)
{
    // The search bounds only the diagonal's pieces by the paper (diagonal_wings_fit); every other
    // kind's are bounded by its ranges. Mechanisms drawn at random around each kind's sample
    // (the off-fold arm on both sides too) that infeasibility and diagonal_wings_fit accept all
    // build and lay out on A4 with the card PopUp sizes to it.
    const CardParams card = testing::card_for_a4_sheets();
    std::mt19937_64 rng(5);
    std::normal_distribution<double> step(0.0, 1.0);
    for (int k = 0; k <= motion_kind_count + 1; ++k) {
        const MotionMechanism start =
            k < motion_kind_count ? sample_mechanism(MotionKind(k))
                                  : testing::off_fold_rotation(k == motion_kind_count ? 1 : -1);
        int laid_out = 0;
        for (int trial = 0; trial < 3000 && laid_out < 20; ++trial) {
            MotionMechanism m = start;
            for (int i = 0; i < parameter_count(m.kind()); ++i)
                parameter(m, i) +=
                    step(rng) *
                    (parameter_info(m.kind(), i).role == ParameterRole::angle ? 0.3 : 30.0);
            if (!feasible(m, card) || !diagonal_wings_fit(m, card))
                continue;
            ASSERT_TRUE(lays_out_on_a4(m)) << "kind " << k;
            ++laid_out;
        }
        EXPECT_GE(laid_out, k == int(MotionKind::diagonal) ? 8 : 20) << k;
    }
}

TEST(MotionFeasibility, AFloatingLayerMustUnfoldOntoTheCardsSheet)
{
    // The off-fold arm found by the test above: its 76.5 mm layer on supports 58.75 mm from the
    // fold unfolds into a strip 2 (76.5 + 58.75) + 2 tabs of 8 mm = 286.5 mm, over the A4 card's
    // open sheet (2 × 136.5 = 273 mm): refused, naming the hinge.
    const CardParams card = testing::card_for_a4_sheets();
    MotionMechanism arm = rotation_mechanism(64.95, 54.68, 75.50, 6.47, 58.75);
    const std::string why = infeasibility(arm, card);
    EXPECT_NE(why.find("hinge"), std::string::npos) << why;
    EXPECT_NE(why.find("open sheet"), std::string::npos) << why;
    // With run 25 the layer is 26 mm high: 2 (26 + 58.75) + 16 = 185.5 mm fits.
    arm.rotation().run = 25;
    EXPECT_EQ(infeasibility(arm, card), "");
    // A still part's layer with an overhang: the platform, 2 (support + overhang) + 16, is the long
    // piece. 2 (58.8 + 63.5) + 16 = 260.6 mm fits; 10 mm more overhang (280.6 mm) does not.
    MotionMechanism layer = layer_mechanism(71.7, 53.6, 11.3, 58.8, 63.5, -100);
    EXPECT_EQ(infeasibility(layer, card), "");
    layer.stationary().overhang = 73.5;
    EXPECT_NE(infeasibility(layer, card).find("open sheet"), std::string::npos);
}

} // namespace
} // namespace popup::motion
