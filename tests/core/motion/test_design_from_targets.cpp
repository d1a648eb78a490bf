// The design stages on hand-made chain paths (closed-form trajectories with known parameters):
// the result must pass the full simulator (re-run here), merge chains that collide and move
// alike, make one of two conflicting chains stationary with a reason, and repeat for a seed.
#include <gtest/gtest.h>

#include <cmath>

#include "motion/design_from_targets.hpp"
#include "motion_fixtures.hpp"
#include "popup/refers_into_argument.hpp"
#include "popup/simulation/check_validity.hpp"

namespace popup::motion {
namespace {

using testing::Chain;
using testing::targets_of;

MotionOptions quick(std::uint64_t seed = 1)
{
    MotionOptions o;
    o.view.card.width = 210;
    o.view.card.depth = 148;
    o.iterations = 1500;
    o.seed = seed;
    return o;
}

POPUP_REFERS_INTO_ARGUMENT const ChainReport& chain(const MotionResult& r, const std::string& name)
{
    for (const ChainReport& c : r.chains)
        if (c.name == name)
            return c;
    throw std::runtime_error("no chain " + name);
}

TEST(DesignFromTargets, SeparateChainsAreAnimatedAsTheirMechanismsAndTheCardIsValid)
{
    const std::vector<Chain> chains = {
        {"arm", rotation_mechanism(20, 40, 30, 25), 0.4},
        {"head", vertical_mechanism(95, 20, 30, 40 * M_PI / 180), 0.3},
        {"tail", horizontal_mechanism(150, 30, 40, 15, 60), 0.3}};
    const Result<MotionResult> r = design_from_targets(targets_of(chains), quick());
    ASSERT_TRUE(r.ok);
    EXPECT_TRUE(r.value.valid);
    EXPECT_TRUE(check_validity(r.value.scaffold).valid()); // the simulator, run again here
    EXPECT_EQ(chain(r.value, "arm").mapping, "rotation");
    EXPECT_EQ(chain(r.value, "head").mapping, "vertical");
    EXPECT_EQ(chain(r.value, "tail").mapping, "horizontal");
    for (const ChainReport& c : r.value.chains) {
        EXPECT_EQ(c.status, "animated") << c.name << ": " << c.reason;
        EXPECT_LT(c.error_mm, 0.5) << c.name;
        ASSERT_EQ(c.achieved.size(), c.s.size());
    }
    // The vertex-weighted total of eq 6.6 over the diagonal, by hand from the chain rows.
    double total = 0;
    for (const ChainReport& c : r.value.chains)
        total += c.weight * c.error_mm / 150;
    EXPECT_NEAR(r.value.weighted_error, total, 1e-12);
    // The stages' times and the whole call's, which holds them all.
    EXPECT_GE(r.value.timings.total_s + 1e-9, r.value.timings.stages_s());
    EXPECT_EQ(r.value.iterations, 2 * 1500);
}

TEST(DesignFromTargets, TwoCrossingArmsThatMoveAlikeAreMerged)
{
    const std::vector<Chain> chains = {{"left_arm", rotation_mechanism(60, 40, 30, 25), 0.5},
                                       {"right_arm", rotation_mechanism(61, 40, 30, 26), 0.5}};
    const Result<MotionResult> r = design_from_targets(targets_of(chains), quick());
    ASSERT_TRUE(r.ok);
    EXPECT_TRUE(r.value.valid);
    const ChainReport &a = chain(r.value, "left_arm"), &b = chain(r.value, "right_arm");
    EXPECT_EQ(a.status, "merged");
    EXPECT_EQ(b.status, "merged");
    EXPECT_EQ(a.mechanisms, b.mechanisms);
    EXPECT_NE(a.reason.find("right_arm"), std::string::npos) << a.reason;
    EXPECT_LT(a.error_mm, 2.0);
}

TEST(DesignFromTargets, TwoConflictingChainsThatMoveDifferentlyLeaveOneStationaryWithAReason)
{
    // A rotation and a vertical translation over the same stretch of the fold on a card too
    // short to move either out of the way, and no annealing: the repair stage must resolve it,
    // the lighter chain giving way (its floating layer would collide too: printed on the page).
    // With annealing the search may remap instead (see the next test).
    const std::vector<Chain> chains = {
        {"arm", rotation_mechanism(30, 40, 30, 25), 0.6},
        {"neck", vertical_mechanism(45, 20, 30, 40 * M_PI / 180), 0.4}};
    MotionOptions o = quick();
    o.view.card.width = 80;
    o.iterations = 0;
    const Result<MotionResult> r = design_from_targets(targets_of(chains), o);
    ASSERT_TRUE(r.ok);
    EXPECT_TRUE(r.value.valid);
    const ChainReport &arm = chain(r.value, "arm"), &neck = chain(r.value, "neck");
    EXPECT_EQ(arm.status, "animated") << arm.reason;
    EXPECT_EQ(neck.status, "stationary");
    EXPECT_NE(neck.reason.find("arm"), std::string::npos) << neck.reason;
    EXPECT_NE(neck.reason.find("move too differently"), std::string::npos) << neck.reason;
}

TEST(DesignFromTargets, ConflictingChainsAnnealedWithTheDefaultIterationsLeaveOneStationary)
{
    // The same conflict with the default annealing: the search may remap one chain, but a
    // mechanism far worse than its own (by more than 0.1 of the diagonal) does not resolve it,
    // so one chain ends stationary, named by the other, and the other follows its own path.
    const std::vector<Chain> chains = {
        {"arm", rotation_mechanism(30, 40, 30, 25), 0.6},
        {"neck", vertical_mechanism(45, 20, 30, 40 * M_PI / 180), 0.4}};
    MotionOptions o = quick();
    o.view.card.width = 80;
    o.iterations = MotionOptions{}.iterations;
    const Result<MotionResult> r = design_from_targets(targets_of(chains), o);
    ASSERT_TRUE(r.ok);
    EXPECT_EQ(r.value.iterations, 2 * MotionOptions{}.iterations);
    EXPECT_TRUE(r.value.valid);
    EXPECT_TRUE(check_validity(r.value.scaffold).valid());
    const ChainReport &arm = chain(r.value, "arm"), &neck = chain(r.value, "neck");
    const bool arm_stays = arm.status == "stationary";
    const ChainReport &still = arm_stays ? arm : neck, &moving = arm_stays ? neck : arm;
    EXPECT_EQ(still.status, "stationary");
    EXPECT_EQ(moving.status, "animated") << moving.reason;
    EXPECT_NE(still.reason.find(moving.name), std::string::npos) << still.reason;
    EXPECT_NE(still.reason.find("move too differently"), std::string::npos) << still.reason;
    // The animated one follows its own closed form (path error well under 0.1 of 150 mm).
    EXPECT_LT(moving.error_mm, 0.1 * 150) << moving.mapping;
}

TEST(DesignFromTargets, TheSameSeedGivesTheSameDesign)
{
    const std::vector<Chain> chains = {
        {"arm", rotation_mechanism(20, 40, 30, 25), 0.5},
        {"leg", rotation_mechanism(40, 40, 30, 20), 0.3},
        {"head", vertical_mechanism(95, 20, 30, 40 * M_PI / 180), 0.2}};
    const Result<MotionResult> a = design_from_targets(targets_of(chains), quick(7));
    const Result<MotionResult> b = design_from_targets(targets_of(chains), quick(7));
    ASSERT_TRUE(a.ok && b.ok);
    ASSERT_EQ(a.value.mechanisms.size(), b.value.mechanisms.size());
    for (std::size_t i = 0; i < a.value.mechanisms.size(); ++i) {
        EXPECT_EQ(a.value.mechanisms[i].name, b.value.mechanisms[i].name);
        EXPECT_EQ(a.value.mechanisms[i].parameter_values(),
                  b.value.mechanisms[i].parameter_values());
    }
    EXPECT_EQ(a.value.cost, b.value.cost);
    EXPECT_TRUE(a.value.valid);
}

TEST(DesignFromTargets, CrowdedChainsNeverEndColliding)
{
    // Five chains crowding the middle of the fold: whatever the seed, the returned card passes
    // the full simulator.
    const std::vector<Chain> chains = {{"a", rotation_mechanism(60, 40, 30, 25), 0.3},
                                       {"b", vertical_mechanism(80, 20, 30, 40 * M_PI / 180), 0.2},
                                       {"c", horizontal_mechanism(70, 30, 40, 15, 60), 0.2},
                                       {"d", rotation_mechanism(75, 30, 20, 20), 0.2},
                                       {"e", layer_mechanism(50, 40, 20, 15, 10, -18), 0.1, 0.8}};
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        const Result<MotionResult> r = design_from_targets(targets_of(chains), quick(seed));
        ASSERT_TRUE(r.ok);
        EXPECT_TRUE(r.value.valid) << "seed " << seed;
        EXPECT_TRUE(check_validity(r.value.scaffold).valid()) << "seed " << seed;
        for (const ChainReport& c : r.value.chains) {
            if (c.status == "stationary") {
                EXPECT_FALSE(c.reason.empty()) << c.name;
            }
        }
    }
}

} // namespace
} // namespace popup::motion
