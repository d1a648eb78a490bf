#include <gtest/gtest.h>

#include "fitting/plan_edits.hpp"
#include "popup/mechanisms/designed_card.hpp"
#include "popup/model/card.hpp"

using namespace popup;

namespace {

MechanismPlan box(const std::string& name, const std::string& host, int parent, double offset,
                  double width, double depth, double height)
{
    MechanismPlan p;
    static_cast<DesignedMechanism&>(p) =
        DesignedMechanism::of_kind(MechanismKind::box_fold, name, host);
    p.parent = parent;
    BoxFoldParams& q = p.as<BoxFoldParams>();
    q.offset = offset;
    q.width = width;
    q.depth_ground = depth;
    q.depth_backdrop = depth;
    q.height = height;
    return p;
}

} // namespace

TEST(PlanEdits, ScalingKeepsTheMiddleAndCarriesWhatStandsOnIt)
{
    // B1 [40, 140] at 80 %: width 80 about 90, so [50, 130]; B2 on its top at 20 keeps its place
    // relative to B1 (16 along the top, 50 + 16 = 66 = 90 + 0.8 (60 − 90)).
    const std::vector<MechanismPlan> plans = {box("B1", "central fold", -1, 40, 100, 30, 40),
                                              box("B2", "B1.top", 0, 20, 40, 20, 20)};
    const auto e = scale_about_place(plans, 0, 0.8, 11.0);
    ASSERT_TRUE(e);
    EXPECT_NEAR(e->plans[0].offset(), 50, 1e-12);
    EXPECT_NEAR(e->plans[0].value("width"), 80, 1e-12);
    EXPECT_NEAR(e->plans[0].value("height"), 32, 1e-12);
    EXPECT_NEAR(e->plans[1].offset(), 16, 1e-12);
    EXPECT_NEAR(e->plans[1].value("depth_ground"), 16, 1e-12);
    EXPECT_EQ(e->carried, (std::vector<int>{1}));
    // At 50 % B2's height 20 would be 10, below a smallest part of 11.
    EXPECT_FALSE(scale_about_place(plans, 0, 0.5, 11.0));
}

TEST(PlanEdits, CuttingKeepsWhatStandsOnItInPlace)
{
    // B1 [40, 140] cut to [70, 140]: B2 on its top [20, 60] stays at [60, 100] along the fold,
    // which is [−10, 30] along the new top: it loses what lies before it, [margin, 30].
    const double margin = 0.001;
    const std::vector<MechanismPlan> plans = {box("B1", "central fold", -1, 40, 100, 30, 40),
                                              box("B2", "B1.top", 0, 20, 40, 20, 20)};
    const auto e = cut_along_hinge(plans, 0, 70, 1e9, 11.0, margin);
    ASSERT_TRUE(e);
    EXPECT_NEAR(e->plans[0].offset(), 70, 1e-12);
    EXPECT_NEAR(e->plans[0].value("width"), 70, 1e-12);
    EXPECT_NEAR(e->plans[1].offset(), margin, 1e-12);
    EXPECT_NEAR(e->plans[1].value("width"), 30 - margin, 1e-12);
    EXPECT_EQ(e->plans[1].value("height"), 20);
    // A cut leaving B1 10 mm long is refused with a smallest part of 11.
    EXPECT_FALSE(cut_along_hinge(plans, 0, 130, 1e9, 11.0, margin));
}

TEST(PlanEdits, MovingKeepsThePlaceAlongTheHinge)
{
    Scaffold card = make_card(CardParams()).value;
    const BasePatchPair fold = central_fold(card);
    const std::vector<MechanismPlan> plans = {box("B1", "central fold", -1, 40, 100, 30, 40),
                                              box("B2", "central fold", -1, 75, 10, 10, 15)};
    const auto b1 = add_mechanism(card, fold, plans[0]);
    ASSERT_TRUE(b1.ok);
    const BasePatchPair& top = b1.value.offered[0];
    ASSERT_EQ(top.name, "B1.top");
    const auto e = move_to_pair(plans, 1, fold, top, 0, 0.001);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->plans[1].host, "B1.top");
    EXPECT_EQ(e->plans[1].parent, 0);
    EXPECT_NEAR(e->plans[1].offset(), 35, 1e-9);
    // Too deep for the top (30 mm each side): not moved.
    std::vector<MechanismPlan> deep = plans;
    deep[1].set_value("depth_ground", 35);
    EXPECT_FALSE(move_to_pair(deep, 1, fold, top, 0, 0.001));
    // A side of the box opens at 90°, the fold at 180°: not moved.
    EXPECT_FALSE(move_to_pair(plans, 1, fold, b1.value.offered[1], 0, 0.001));
}

TEST(PlanEdits, ChangesAreListedByTheirProperty)
{
    MechanismPlan before = box("B1", "central fold", -1, 40, 100, 30, 40);
    MechanismPlan after = before;
    after.set_value("width", 80);
    after.set_value("front", 0);
    EXPECT_EQ(describe_changes(before, after), "Width 100 mm → 80 mm, Front yes → no");
}
