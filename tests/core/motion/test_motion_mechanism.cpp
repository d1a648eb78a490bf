// Each motion mechanism's closed-form point path and collision volume against the simulator
// (simulate_fold of the scaffold the library's generators build), which shares no code with the
// closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "motion/collision_volume.hpp"
#include "motion/reach_floor.hpp"
#include "motion_fixtures.hpp"
#include "popup/model/card.hpp"
#include "popup/sheets/nest.hpp"
#include "popup/sheets/sheet_layout.hpp"
#include "popup/simulation/check_validity.hpp"
#include "popup/simulation/simulate_fold.hpp"

namespace popup::motion {
namespace {

using testing::sample_mechanism;

struct Built {
    Scaffold scaffold;
    std::vector<int> patches;
};

Built build(const MotionMechanism& m)
{
    const CardParams card = testing::a4_card();
    Built b;
    b.scaffold = make_card(card).value;
    std::vector<FittedMechanism> rows;
    auto parts = build_mechanism(b.scaffold, central_fold(b.scaffold), m, "M", rows);
    EXPECT_TRUE(parts.ok) << (parts.diagnostics.empty() ? "" : parts.diagnostics[0].message);
    for (const MechanismParts& part : parts.value)
        b.patches.insert(b.patches.end(), part.patches.begin(), part.patches.end());
    return b;
}

constexpr MotionKind all_kinds[] = {MotionKind::vertical, MotionKind::diagonal,
                                    MotionKind::horizontal, MotionKind::rotation,
                                    MotionKind::stationary};

// Every kind's sample, and the rotation off the fold on either side of a floating layer.
std::vector<std::pair<std::string, MotionMechanism>> samples()
{
    std::vector<std::pair<std::string, MotionMechanism>> out;
    for (MotionKind kind : all_kinds)
        out.push_back({to_string(kind), sample_mechanism(kind)});
    out.push_back({"rotation on side_ground", testing::off_fold_rotation(1)});
    out.push_back({"rotation on side_backdrop", testing::off_fold_rotation(-1)});
    return out;
}

TEST(MotionMechanism, SampleParametersAreFeasibleAndTheDesignIsValid)
{
    CardParams card;
    card.depth = 148;
    for (const auto& [kind, m] : samples()) {
        EXPECT_EQ(infeasibility(m, card), "") << kind;
        const Built b = build(m);
        const ValidityReport report = check_validity(b.scaffold);
        EXPECT_TRUE(report.valid()) << kind;
    }
}

TEST(MotionMechanism, PointPathEqualsTheSimulatorsOverTheFold)
{
    std::vector<double> angles;
    for (int k = 0; k <= 36; ++k)
        angles.push_back(M_PI * k / 36);
    for (const auto& [kind, m] : samples()) {
        const Built b = build(m);
        // The carried point at the design state lies on one of the mechanism's patches (the
        // first one built: the rotation arm's tip also touches the other wing's edge at 180°);
        // the simulator's pose of that patch carries it.
        const Vec3 design = mechanism_point(m, M_PI);
        int carrier = -1;
        for (int id : b.patches) {
            const Patch* patch = b.scaffold.find_patch(id);
            if (carrier < 0 && patch->contains(design, 1e-9))
                carrier = id;
        }
        ASSERT_GE(carrier, 0) << kind;
        const Result<FoldSweep> sweep = simulate_fold(b.scaffold, angles);
        ASSERT_TRUE(sweep.ok && sweep.value.complete) << kind;
        const int index = b.scaffold.patch_index(carrier);
        double worst = 0;
        for (const FoldState& state : sweep.value.states) {
            const Vec3 simulated = state.poses[index].apply(design);
            const Vec3 closed = mechanism_point(m, state.angle);
            worst = std::max(worst, (simulated.head<2>() - closed.head<2>()).norm());
        }
        EXPECT_LT(worst, 1e-6) << kind << ": card (x, y) differs by " << worst << " mm";
    }
}

// Points spread over a posed patch: its outline's vertices and a grid over each triangle of its
// fan (the patches are convex), so a point of any of the patch's pieces is among them.
std::vector<Vec3> points_over(const std::vector<Vec3>& outline)
{
    std::vector<Vec3> points = outline;
    constexpr int n = 8;
    for (std::size_t t = 1; t + 1 < outline.size(); ++t)
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j)
                points.push_back(outline[0] + (outline[t] - outline[0]) * i / double(n) +
                                 (outline[t + 1] - outline[0]) * j / double(n));
    return points;
}

TEST(MotionMechanism, CollisionVolumeHoldsEverySimulatedPatchOver91Angles)
{
    // Every point of every patch, posed by the simulator at 91 angles (x divided by sin(θ/2), the
    // volume's frame), lies in the box of one piece of its band whose side admits it (side s:
    // s·x >= 0): the volume and its sides hold the paper the generators build.
    std::vector<double> angles;
    for (int k = 0; k <= 90; ++k)
        angles.push_back(M_PI * k / 90);
    const VolumeOptions options;
    for (const auto& [kind, m] : samples()) {
        const CollisionVolume volume = collision_volume(m, options);
        ASSERT_EQ(int(volume.bands.size()), options.bands);
        const std::size_t pieces = volume.sides.size();
        ASSERT_EQ(volume.aligned.size(), pieces * options.bands);
        const Built b = build(m);
        const Result<FoldSweep> sweep = simulate_fold(b.scaffold, angles);
        ASSERT_TRUE(sweep.ok && sweep.value.complete);
        int outside = 0, checked = 0;
        for (const FoldState& state : sweep.value.states) {
            if (state.angle == 0.0)
                continue; // flat: the volume's frame, x / sin(θ/2), is a limit there
            const int band = std::min(options.bands - 1, int(state.angle / (M_PI / options.bands)));
            const double across = 1.0 / std::sin(state.angle / 2);
            for (int id : b.patches) {
                const Patch* patch = b.scaffold.find_patch(id);
                for (const Vec3& x :
                     points_over(posed_outline(*patch, state.poses[b.scaffold.patch_index(id)]))) {
                    ++checked;
                    const Vec3 mapped(x.x() * across, x.y(), x.z());
                    bool held = false;
                    for (std::size_t i = 0; i < pieces && !held; ++i) {
                        const OrientedBox& box = volume.aligned[band * pieces + i];
                        held = volume.sides[i] * x.x() >= -1e-9 &&
                               ((mapped - box.centre).cwiseAbs() - box.half).maxCoeff() <= 1e-9;
                    }
                    if (!held)
                        ++outside;
                }
            }
        }
        EXPECT_GT(checked, 91 * 3);
        EXPECT_EQ(outside, 0) << kind;
    }
}

TEST(MotionMechanism, InfeasibleParametersAreNamed)
{
    CardParams card;
    card.depth = 148;
    MotionMechanism m = sample_mechanism(MotionKind::rotation);
    m.p[3] = 100; // arm far beyond spine²/run = 53 mm
    const std::string why = infeasibility(m, card);
    EXPECT_NE(why.find("arm = 100"), std::string::npos) << why;
    m = sample_mechanism(MotionKind::horizontal);
    m.p[3] = 45; // run_backdrop above run_ground
    EXPECT_NE(infeasibility(m, card).find("run_backdrop"), std::string::npos);
}

TEST(MotionMechanism, AnOffFoldArmsGluedCreaseKeepsItsTabRoom)
{
    // The wing glued to the support along the diagonal of its Spine × Run corner: 20°..70° from
    // the support's edges. Spine 40: Run from 40·tan 20° = 14.56 to 40·tan 70° = 109.9 mm.
    const CardParams card = testing::a4_card();
    for (double side : {1.0, -1.0}) {
        MotionMechanism m = testing::off_fold_rotation(side); // spine 40, run 25
        m.p[3] = 10;                                          // arm under spine²/run
        EXPECT_EQ(infeasibility(m, card), "") << side;
        m.p[2] = 14.0; // 19.3° from the hinge
        EXPECT_NE(infeasibility(m, card).find("run = 14"), std::string::npos) << side;
        m.p[2] = 15.0;
        EXPECT_EQ(infeasibility(m, card), "") << side;
        m.p[2] = 100.0; // 68.2°: still in, the tallest the card allows with a 30 mm hinge
        m.p[3] = 5;
        EXPECT_EQ(infeasibility(m, card), "") << side;
    }
    MotionMechanism steep = testing::off_fold_rotation(1);
    steep.p[1] = 12; // spine 12, run 25: 64.4° in; run 40: 73.3° out
    steep.p[3] = 2;
    EXPECT_EQ(infeasibility(steep, card), "");
    steep.p[2] = 40;
    EXPECT_NE(infeasibility(steep, card).find("tan 70"), std::string::npos)
        << infeasibility(steep, card);
}

TEST(MotionMechanism, FeasibleAgreesWithInfeasibility)
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
            for (int i = 0; i < parameter_count(m.kind); ++i)
                m.p[i] += step(rng) *
                          (parameter_info(m.kind, i).role == ParameterRole::angle ? 0.3 : 15.0);
            const bool ok = infeasibility(m, card).empty();
            EXPECT_EQ(feasible(m, card), ok) << k << " trial " << trial;
            (ok ? yes : no) += 1;
        }
    }
    EXPECT_GT(yes, 100);
    EXPECT_GT(no, 100);
}

TEST(MotionMechanism, AMergedArmCarriesEachPartWithItsWingAsTheSimulatorDoes)
{
    // rotation_carried_point moves a point of the arm's wing rigidly with it. Points spread over
    // the wing that carries the tip (its centroid, and halfway from there to each corner), given
    // by their card (x, y) when open, must follow the simulator's pose of that wing, on the fold
    // and on both sides of a floating layer; at the tip it is mechanism_point.
    std::vector<double> angles;
    for (int k = 0; k <= 36; ++k)
        angles.push_back(M_PI * k / 36);
    for (const auto& [name, m] : std::vector<std::pair<std::string, MotionMechanism>>{
             {"on the fold", sample_mechanism(MotionKind::rotation)},
             {"on side_ground", testing::off_fold_rotation(1)},
             {"on side_backdrop", testing::off_fold_rotation(-1)}}) {
        const Built b = build(m);
        const Vec3 tip = mechanism_point(m, M_PI);
        const Patch* wing = nullptr;
        for (int id : b.patches) {
            const Patch* patch = b.scaffold.find_patch(id);
            if (!wing && patch->contains(tip, 1e-9))
                wing = patch;
        }
        ASSERT_NE(wing, nullptr) << name;
        std::vector<Vec3> points{wing->centroid()};
        for (const Vec3& corner : wing->outer)
            points.push_back((wing->centroid() + corner) / 2);
        const Result<FoldSweep> sweep = simulate_fold(b.scaffold, angles);
        ASSERT_TRUE(sweep.ok && sweep.value.complete) << name;
        const int index = b.scaffold.patch_index(wing->id);
        double worst = 0, at_tip = 0;
        for (const FoldState& state : sweep.value.states) {
            for (const Vec3& q : points) {
                const Vec3 simulated = state.poses[index].apply(q);
                const Vec3 carried = rotation_carried_point(m, q.head<2>(), state.angle);
                worst = std::max(worst, (simulated - carried).norm());
            }
            at_tip = std::max(at_tip, (rotation_carried_point(m, tip.head<2>(), state.angle) -
                                       mechanism_point(m, state.angle))
                                          .norm());
        }
        EXPECT_LT(worst, 1e-6) << name << ": " << worst << " mm from the simulator's pose";
        EXPECT_LT(at_tip, 1e-9) << name;
    }
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

TEST(MotionMechanism, ADiagonalsWingsMustFitTheCardsSheet)
{
    // PopUp's card for A4 is 186 x 136.5 mm (open, it fills A4 inside the sheets' margins). A
    // diagonal with a 193 mm run at 40.2 deg (found on a long capture) unfolds its two wings into
    // one piece 378 mm long: diagonal_wings_fit says no, and the sheets indeed cannot lay it out
    // on A4. Feasible diagonals drawn at random that it passes all lay out on A4.
    const CardParams card = testing::card_for_a4_sheets();
    MotionMechanism long_run;
    long_run.kind = MotionKind::diagonal;
    long_run.p = {27.45, 193.22, 40.19 * M_PI / 180, 40.72, 10, 12, 16, 12};
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
        m.p[0] = offset(rng);
        m.p[1] = run(rng);
        m.p[2] = angle(rng) * M_PI / 180;
        m.p[3] = spine(rng);
        if (!infeasibility(m, card).empty())
            continue;
        if (!diagonal_wings_fit(m, card)) {
            ++refused;
            continue;
        }
        ++passed;
        EXPECT_TRUE(lays_out_on_a4(m))
            << "run " << m.p[1] << " angle " << m.p[2] << " spine " << m.p[3];
    }
    EXPECT_GE(passed, 12);
    EXPECT_GT(refused, 0);
}

TEST(MotionMechanism, EveryFeasibleMechanismLaysOutOnTheCardsPaper)
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
            for (int i = 0; i < parameter_count(m.kind); ++i)
                m.p[i] += step(rng) *
                          (parameter_info(m.kind, i).role == ParameterRole::angle ? 0.3 : 30.0);
            if (!feasible(m, card) || !diagonal_wings_fit(m, card))
                continue;
            ASSERT_TRUE(lays_out_on_a4(m)) << "kind " << k;
            ++laid_out;
        }
        EXPECT_GE(laid_out, k == int(MotionKind::diagonal) ? 8 : 20) << k;
    }
}

TEST(MotionMechanism, AFloatingLayerMustUnfoldOntoTheCardsSheet)
{
    // The off-fold arm found by the test above: its 76.5 mm layer on supports 58.75 mm from the
    // fold unfolds into a strip 2 (76.5 + 58.75) + 2 tabs of 8 mm = 286.5 mm, over the A4 card's
    // open sheet (2 × 136.5 = 273 mm): refused, naming the hinge.
    const CardParams card = testing::card_for_a4_sheets();
    MotionMechanism arm;
    arm.kind = MotionKind::rotation;
    arm.p = {64.95, 54.68, 75.50, 6.47, 58.75};
    const std::string why = infeasibility(arm, card);
    EXPECT_NE(why.find("hinge"), std::string::npos) << why;
    EXPECT_NE(why.find("open sheet"), std::string::npos) << why;
    // With run 25 the layer is 26 mm high: 2 (26 + 58.75) + 16 = 185.5 mm fits.
    arm.p[2] = 25;
    EXPECT_EQ(infeasibility(arm, card), "");
    // A still part's layer with an overhang: the platform, 2 (support + overhang) + 16, is the long
    // piece. 2 (58.8 + 63.5) + 16 = 260.6 mm fits; 10 mm more overhang (280.6 mm) does not.
    MotionMechanism layer;
    layer.kind = MotionKind::stationary;
    layer.p = {71.7, 53.6, 11.3, 58.8, 63.5, -100};
    EXPECT_EQ(infeasibility(layer, card), "");
    layer.p[4] = 73.5;
    EXPECT_NE(infeasibility(layer, card).find("open sheet"), std::string::npos);
}

TEST(MotionMechanism, EveryPatchStaysWithinTheCardsReachAcrossTheFold)
{
    // The premise of the reach floor (reach_floor.hpp): at fold angle θ no paper is seen farther
    // than depth·sin(θ/2) from the fold. The simulator's poses of every patch of each sample
    // design, pages included, at 37 angles (independent of the closed forms) ...
    const CardParams card = testing::a4_card();
    std::vector<double> angles;
    for (int k = 0; k <= 36; ++k)
        angles.push_back(M_PI * k / 36);
    for (const auto& [kind, m] : samples()) {
        const Built b = build(m);
        const Result<FoldSweep> sweep = simulate_fold(b.scaffold, angles);
        ASSERT_TRUE(sweep.ok && sweep.value.complete) << kind;
        double worst = -1e9;
        for (const FoldState& state : sweep.value.states)
            for (std::size_t i = 0; i < b.scaffold.patches.size(); ++i)
                for (const Vec3& x : posed_outline(b.scaffold.patches[i], state.poses[i]))
                    worst = std::max(worst, std::abs(x.x()) - card_reach(card, state.angle));
        EXPECT_LE(worst, 1e-6) << kind;
        EXPECT_GT(worst, -1e-6) << kind << ": the pages' far edges reach it exactly";
    }
    // ... and the closed forms' pieces of random feasible mechanisms of every kind.
    std::mt19937_64 rng(11);
    std::normal_distribution<double> step(0.0, 1.0);
    for (int k = 0; k <= motion_kind_count + 1; ++k) {
        const MotionMechanism start =
            k < motion_kind_count ? sample_mechanism(MotionKind(k))
                                  : testing::off_fold_rotation(k == motion_kind_count ? 1 : -1);
        int tried = 0;
        double worst = -1e9;
        for (int trial = 0; trial < 3000; ++trial) {
            MotionMechanism m = start;
            for (int i = 0; i < parameter_count(m.kind); ++i)
                m.p[i] += step(rng) *
                          (parameter_info(m.kind, i).role == ParameterRole::angle ? 0.2 : 12.0);
            if (!feasible(m, card))
                continue;
            ++tried;
            for (double theta : angles)
                for (const Vec3& v : mechanism_vertices(m, theta))
                    worst = std::max(worst, std::abs(v.x()) - card_reach(card, theta));
        }
        EXPECT_GT(tried, 50) << k;
        EXPECT_LE(worst, 1e-6) << k; // the trilaterated corners round off by ~4e-7 mm
    }
}

} // namespace
} // namespace popup::motion
