// The model's bulk as two parts, one on the other's top (bulk_stack): a bust's shoulders and
// head, a house's walls and roof, recovered from samples of such parts.
#include <gtest/gtest.h>

#include "fitting/bulk_stack.hpp"
#include "fitting/card_hinge.hpp"
#include "fitting/synthetic_models.hpp"

using namespace popup;
using namespace popup::testing;

TEST(BulkStack, RecoversShouldersAndAHead)
{
    // Card frame: y along the fold (a), x across (s), z up (t). Shoulders 80 long, 40 deep and
    // 20 high; a head 30 long, 24 deep and 40 high on them, 40 from their start.
    const ModelMesh bust =
        join({box_mesh({-20, 50, 0}, {20, 130, 20}), box_mesh({-12, 90, 20}, {12, 120, 60})});
    const SurfaceSamples samples = sample_surface(bust, 12000, 1);
    const BulkBox single = bulk_box(samples, card_hinge(), 11.1);
    const std::optional<BulkStack> stack = bulk_stack(samples, card_hinge(), 11.1, single);
    ASSERT_TRUE(stack.has_value());
    // The shoulders' faces each hold more samples than a quantile step of all samples, so the
    // descent lands on them exactly (as BulkBox.RecoversABoxStandingOnTheFold); the head's
    // sides are candidates only as far as a quantile of the samples above a cut meets them.
    EXPECT_NEAR(stack->lower.a0, 50, 1e-9);
    EXPECT_NEAR(stack->lower.a1, 130, 1e-9);
    EXPECT_NEAR(stack->lower.s1, 20, 1e-9);
    EXPECT_NEAR(stack->lower.height, 20, 1e-9);
    // The head on the shoulders' top: along from the shoulders' start (90 − 50, 120 − 50).
    EXPECT_EQ(stack->upper.host, 1);
    EXPECT_NEAR(stack->upper.a0, 40, 1e-9);
    EXPECT_NEAR(stack->upper.a1, 70, 1e-9);
    EXPECT_NEAR(stack->upper.s0, -12, 0.5);
    EXPECT_NEAR(stack->upper.s1, 12, 0.5);
    EXPECT_NEAR(stack->upper.height, 40, 1e-9);
    // Within the head's half-millimetre on its sides, against several for the one box.
    EXPECT_LT(stack->mean_distance, 0.1);
    EXPECT_GT(single.mean_distance, 1.0);
}

TEST(BulkStack, AHouseGetsATentRoof)
{
    // Walls 80 long, 40 deep and 25 high; a gable roof over them, its ridge 15 above the eaves.
    const ModelMesh house =
        join({box_mesh({-20, 50, 0}, {20, 130, 25}),
              extrude_section({Vec2(-20, 25), Vec2(20, 25), Vec2(0, 40)}, 50, 130)});
    const SurfaceSamples samples = sample_surface(house, 12000, 1);
    const BulkBox single = bulk_box(samples, card_hinge(), 11.1);
    const std::optional<BulkStack> stack = bulk_stack(samples, card_hinge(), 11.1, single);
    ASSERT_TRUE(stack.has_value());
    EXPECT_NEAR(stack->lower.height, 25, 1e-9);
    EXPECT_NEAR(stack->lower.s1, 20, 1e-9);
    // A tent on the walls' top: its feet just inside the eaves (half a percent, as a fitted
    // tent's), its ridge over the hinge, about as long as the walls (a tent has no gable ends of
    // paper, so samples on the gables pull its ends in by a few millimetres).
    EXPECT_EQ(stack->upper.kind, Prism::Kind::triangular);
    EXPECT_EQ(stack->upper.host, 1);
    EXPECT_NEAR(stack->upper.a0, 0, 5.0);
    EXPECT_NEAR(stack->upper.a1, 80, 5.0);
    EXPECT_NEAR(stack->upper.s1, 20, 0.5);
    EXPECT_LE(stack->upper.s1, 0.995 * 20 + 1e-12);
    EXPECT_DOUBLE_EQ(stack->upper.s0, -stack->upper.s1);
    EXPECT_DOUBLE_EQ(stack->upper.apex_s, 0);
    EXPECT_NEAR(stack->upper.height, 15, 0.5);
    EXPECT_LT(stack->mean_distance, 0.2);
    EXPECT_LT(stack->mean_distance, 0.9 * single.mean_distance);
}
