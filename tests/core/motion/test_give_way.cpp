// A floating layer gives way (give_way.cpp, clear_layer; docs/MATH.md "Motion before depth"):
// it takes another shape about its point, which eq 6.6 alone sees, or stays as it is.
#include <gtest/gtest.h>

#include <cmath>

#include "motion/give_way.hpp"
#include "motion/motion_feasibility.hpp"
#include "motion_fixtures.hpp"

namespace popup::motion {
namespace {

// One still chain on a layer 60 mm wide along the fold (y 40..100, its point's y = 70), its
// anchor 18 mm out on the ground page; the chain's target is the layer's own path.
AnnealProblem one_layer(AnnealState& state)
{
    AnnealProblem p;
    p.card = testing::a4_card();
    p.diagonal = 150;
    const MotionMechanism layer = layer_mechanism(40, 60, 30, 20, 10, 18);
    ChainTarget t;
    t.name = "statue";
    t.weight = 1;
    t.depth = 0.5;
    for (int k = 0; k <= 8; ++k) {
        t.s.push_back(k / 8.0);
        t.target.push_back(mechanism_point(layer, M_PI * k / 8.0).head<2>());
    }
    p.chains = {t};
    p.still = {true};
    state.slots = {{layer, {0}}};
    return p;
}

TEST(GiveWay, AFloatingLayerNarrowsAboutItsPointToClearAMechanism)
{
    AnnealState state;
    const AnnealProblem p = one_layer(state);
    // An extruding patch over y 92..106: within the 60 mm layer's reach (its end panels lie
    // along the fold as it closes, 20 mm past each end), beyond a narrow one's on short supports.
    Slot patch{horizontal_mechanism(92, 14, 40, 15, 60), {0}};
    ASSERT_TRUE(feasible(patch.mechanism, p.card)) << infeasibility(patch.mechanism, p.card);
    const CollisionVolume room = slot_volume(p, patch);
    ASSERT_TRUE(collide(room, slot_volume(p, state.slots[0])));
    const double before = carried_error(state.slots[0], p.chains[0]);

    ASSERT_TRUE(clear_layer(p, state, 0, room));
    const Slot& after = state.slots[0];
    EXPECT_FALSE(after.printed);
    EXPECT_FALSE(collide(room, slot_volume(p, after)));
    EXPECT_TRUE(feasible(after.mechanism, p.card));
    const StationaryMotion& f = after.mechanism.stationary();
    EXPECT_LT(f.width, 60.0);
    EXPECT_GE(f.width, shortest_crease() - 1e-12);
    // By hand (docs/MATH.md, "A printed part's path"): the platform point at anchor a from the
    // crease sits at h·ẑ + |a|·g(θ), g = (sin(θ/2), cos(θ/2)) in (x, z), y at the layer's middle;
    // seen down z, (a sin(θ/2), offset + width/2) = (18 sin(θ/2), 70) whatever the width, height,
    // support and overhang.
    for (int k = 0; k <= 12; ++k) {
        const double theta = M_PI * k / 12;
        const Vec3 q = mechanism_point(after.mechanism, theta);
        EXPECT_NEAR(q.x(), 18 * std::sin(theta / 2), 1e-9) << theta;
        EXPECT_NEAR(q.y(), 70.0, 1e-9) << theta;
    }
    EXPECT_NEAR(carried_error(after, p.chains[0]), before, 1e-9);
}

TEST(GiveWay, AFloatingLayerWhosePointIsTakenStaysAsItIs)
{
    AnnealState state;
    const AnnealProblem p = one_layer(state);
    // A patch over y 63..77 covers the point's y = 70: no narrower layer about it is clear.
    Slot patch{horizontal_mechanism(63, 14, 40, 15, 60), {0}};
    const CollisionVolume room = slot_volume(p, patch);
    ASSERT_TRUE(collide(room, slot_volume(p, state.slots[0])));
    const AnnealState kept = state;
    EXPECT_FALSE(clear_layer(p, state, 0, room));
    EXPECT_EQ(state.slots[0].mechanism.stationary().width,
              kept.slots[0].mechanism.stationary().width);
    EXPECT_EQ(state.slots[0].mechanism.stationary().offset,
              kept.slots[0].mechanism.stationary().offset);
}

} // namespace
} // namespace popup::motion
