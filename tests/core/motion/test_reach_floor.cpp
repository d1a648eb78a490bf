// The reach floor against values worked by hand (docs/MATH.md, "The reach floor").
#include <gtest/gtest.h>

#include <cmath>

#include "motion/reach_floor.hpp"
#include "motion_fixtures.hpp"

namespace popup::motion {
namespace {

TEST(ReachFloor, APartFarFromTheFoldCannotBeFollowedWhileTheCardIsNearlyClosed)
{
    // 100 mm from the fold: closed (s = 0) the card shows nothing there, 100 mm short; at 90°
    // (s = 0.5) it reaches 148·sin 45° = 104.65 mm, past it; open, 148 mm. RMS = 100/√3.
    ChainTarget t;
    t.s = {0.0, 0.5, 1.0};
    t.target = {Vec2(-100, 50), Vec2(-100, 60), Vec2(-100, 70)};
    EXPECT_NEAR(reach_floor_mm(t, testing::a4_card()), 100 / std::sqrt(3.0), 1e-9);
    // At 30° (s = 1/6) the card reaches 148·sin 15° = 38.305 mm: 61.695 mm short.
    t.s = {1.0 / 6};
    t.target = {Vec2(100, 0)};
    EXPECT_NEAR(reach_floor_mm(t, testing::a4_card()), 100 - 148 * std::sin(M_PI / 12), 1e-9);
}

TEST(ReachFloor, APathTheCardAlwaysReachesHasNoFloor)
{
    // Along the fold, or printed on the page (x = x_open·sin(θ/2)): no floor; y does not count.
    ChainTarget t;
    for (int k = 0; k <= 8; ++k) {
        const double s = k / 8.0;
        t.s.push_back(s);
        t.target.push_back(Vec2(140 * std::sin(M_PI * s / 2), 400.0 * k));
    }
    EXPECT_EQ(reach_floor_mm(t, testing::a4_card()), 0.0);
    EXPECT_EQ(reach_floor_mm(ChainTarget{}, testing::a4_card()), 0.0);
}

} // namespace
} // namespace popup::motion
