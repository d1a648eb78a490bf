#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "popup/simulation/free_motion.hpp"
#include "popup/simulation/simulate_fold.hpp"
#include "test_support.hpp"
#include "validity_cases.hpp"

using namespace popup;

TEST(FreeMotion, NamesTheFiveBarsMovingPatchesAndNoneOfTheTents)
{
    const Scaffold loop = fixtures::five_bar_card();
    const auto open = simulate_fold(loop, {fixtures::deg(120)});
    ASSERT_EQ(open.value.states.size(), 1u);
    const FreeMotion m = free_motion(loop, open.value.states[0]);
    EXPECT_EQ(m.dimension, 1);
    EXPECT_EQ(m.moving_patches, (std::vector<int>{2, 3, 4}));
    const Scaffold tent = fixtures::valid_tent_card();
    const auto state = simulate_fold(tent, {fixtures::deg(120)});
    EXPECT_EQ(free_motion(tent, state.value.states[0]).dimension, 0);
    EXPECT_THROW(free_motion(tent, open.value.states[0]), std::invalid_argument);
}
