#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "generated_scaffolds.hpp"
#include "popup/simulation/simulate_fold.hpp"
#include "sheet_designs.hpp"
#include "test_support.hpp"

using namespace popup;

// Mechanisms of many bodies are solved with sparse normal equations: the states are those of the
// dense solver they replaced, to within what the corrector's tolerance pins them to.
TEST(SimulateFold, SparseSolverFollowsTheDenseOne)
{
    std::vector<fixtures::NamedDesign> cards = fixtures::single_mechanism_cards();
    cards.push_back({"demo", fixtures::demo_card()});
    cards.push_back({"nested boxes", fixtures::nested_boxes(2)});
    cards.push_back({"box with 4 panel pairs", fixtures::box_with_panel_pairs(4)});
    const std::vector<double> angles = fixtures::angle_range(180, 0, 91);
    SimulationOptions dense;
    dense.dense_linear_algebra = true;
    for (const auto& [name, card] : cards) {
        SCOPED_TRACE(name);
        const Result<FoldSweep> a = simulate_fold(card, angles, dense);
        const Result<FoldSweep> b = simulate_fold(card, angles);
        ASSERT_TRUE(a.ok && a.value.complete);
        ASSERT_TRUE(b.ok && b.value.complete);
        ASSERT_EQ(a.value.states.size(), b.value.states.size());
        EXPECT_LE(fixtures::max_residual(b.value), 1e-10 * card.size());
        double rotation = 0.0, translation = 0.0;
        for (size_t k = 0; k < a.value.states.size(); ++k)
            for (size_t i = 0; i < card.patches.size(); ++i) {
                const Pose& p = a.value.states[k].poses[i];
                const Pose& q = b.value.states[k].poses[i];
                rotation = std::max(rotation, (p.rotation - q.rotation).norm());
                translation = std::max(translation, (p.translation - q.translation).norm());
            }
        EXPECT_LT(rotation, 1e-8);
        EXPECT_LT(translation, 1e-8 * card.size());
    }
}
