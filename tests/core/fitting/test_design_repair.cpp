#include <gtest/gtest.h>

#include "popup/fitting/design_repair.hpp"
#include "popup/fitting/mechanism_mapping.hpp"

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
    q.panel_pairs = 1;
    q.front = true;
    q.back = true;
    return p;
}

MechanismPlan step_on(const std::string& host, int parent, const StepFoldParams& params)
{
    MechanismPlan p;
    static_cast<DesignedMechanism&>(p) =
        DesignedMechanism::of_kind(MechanismKind::step_fold, "S1", host);
    p.parent = parent;
    p.params = params;
    return p;
}

const FitRepair* repair_of(const RepairOutcome& o, const std::string& name)
{
    for (const auto& r : o.repairs)
        if (r.mechanism == name)
            return &r;
    return nullptr;
}

bool warned(const RepairOutcome& o, const std::string& name)
{
    for (const auto& d : o.warnings)
        if (d.code == DiagnosticCode::mechanism_dropped && d.severity == Severity::warning &&
            d.message.rfind(name + " ", 0) == 0 && d.parameter == name)
            return true;
    return false;
}

} // namespace

TEST(FitDesignRepair, OneValidBoxIsKeptUnchanged)
{
    const RepairOutcome o =
        build_until_valid(CardParams(), {box("B1", "central fold", -1, 40, 100, 30, 40)});
    EXPECT_TRUE(o.valid);
    EXPECT_EQ(o.kept, (std::vector<bool>{true}));
    EXPECT_TRUE(o.repairs.empty());
    EXPECT_TRUE(o.report.valid());
}

TEST(FitDesignRepair, OverlappingSweepsDropTheLaterAndWhatStandsOnIt)
{
    // Closed, B1 sweeps [60 − 30, 100 + 30] = [30, 130] along the fold, B2 [110 − 30, 150 + 30]:
    // they overlap.
    MechanismPlan tent;
    static_cast<DesignedMechanism&>(tent) =
        DesignedMechanism::of_kind(MechanismKind::tent_fold, "T1", "B2.top");
    tent.parent = 1;
    TentFoldParams& q = tent.as<TentFoldParams>();
    q.offset = 0;
    q.width = 40;
    q.foot = 20;
    q.foot_backdrop = 20;
    q.slope = 25;
    const RepairOutcome o =
        build_until_valid(CardParams(), {box("B1", "central fold", -1, 60, 40, 30, 40),
                                         box("B2", "central fold", -1, 110, 40, 30, 40), tent});
    EXPECT_TRUE(o.valid);
    EXPECT_EQ(o.kept, (std::vector<bool>{true, false, false}));
    ASSERT_TRUE(repair_of(o, "B2"));
    EXPECT_EQ(repair_of(o, "B2")->action, "dropped");
    EXPECT_NE(repair_of(o, "B2")->reason.find("sweeps into B1"), std::string::npos);
    ASSERT_TRUE(repair_of(o, "T1"));
    EXPECT_NE(repair_of(o, "T1")->reason.find("stood on B2"), std::string::npos);
    EXPECT_TRUE(warned(o, "B2"));
    EXPECT_TRUE(warned(o, "T1"));
    EXPECT_FALSE(repair_of(o, "B1")) << (repair_of(o, "B1") ? repair_of(o, "B1")->reason : "");
}

TEST(FitDesignRepair, RefusedParametersAreDroppedWithTheGeneratorsReason)
{
    // A step on B1's ground side rising 50 up a 40 high wall: its generator refuses it.
    StepFoldParams q;
    q.offset = 10;
    q.width = 40;
    q.run_ground = 20;
    q.run_backdrop = 50;
    const MechanismPlan step = step_on("B1.side_ground", 0, q);
    const RepairOutcome o =
        build_until_valid(CardParams(), {box("B1", "central fold", -1, 40, 100, 30, 40), step});
    EXPECT_TRUE(o.valid);
    EXPECT_EQ(o.kept, (std::vector<bool>{true, false}));
    ASSERT_TRUE(repair_of(o, "S1"));
    EXPECT_NE(repair_of(o, "S1")->reason.find("RunBackdrop"), std::string::npos);
    EXPECT_TRUE(warned(o, "S1"));
}

TEST(FitDesignRepair, AFailedValidityCheckDropsTheMechanismItNames)
{
    // Closed, a box of height c and half depth g reaches c + g = 130 + 30 > 148 along its page:
    // the closed card does not enclose it. Their sweeps [10, 120] and [120, 200] only touch.
    const RepairOutcome o =
        build_until_valid(CardParams(), {box("B1", "central fold", -1, 40, 50, 30, 40),
                                         box("B2", "central fold", -1, 150, 20, 30, 130)});
    EXPECT_TRUE(o.valid);
    EXPECT_EQ(o.kept, (std::vector<bool>{true, false}));
    ASSERT_TRUE(repair_of(o, "B2"));
    EXPECT_NE(repair_of(o, "B2")->reason.find("validity check failed"), std::string::npos);
    EXPECT_NE(repair_of(o, "B2")->reason.find("B2."), std::string::npos); // names its patch
    EXPECT_TRUE(warned(o, "B2"));
}

TEST(FitDesignRepair, NothingLeftIsNotValid)
{
    const RepairOutcome o =
        build_until_valid(CardParams(), {box("B1", "central fold", -1, 40, 50, 30, 130)});
    EXPECT_FALSE(o.valid);
    EXPECT_EQ(o.kept, (std::vector<bool>{false}));
    EXPECT_TRUE(warned(o, "B1"));
}

TEST(FitDesignRepair, ParametersOnTheirBoundsMoveInsideByTheMargin)
{
    // A step on B1's backdrop side exactly as long as B1 (offset + width = 100), rising the whole
    // wall (40); a box on B1's top as deep
    // as B1. Each lands on a generator bound; keep_inside_ranges moves it `margin` inside.
    const CardParams card;
    const double margin = 0.01;
    StepFoldParams q;
    q.offset = 0.1;
    q.width = 99.9;
    q.run_ground = 40;
    q.run_backdrop = 20;
    const MechanismPlan step = step_on("B1.side_backdrop", 0, q);
    std::vector<MechanismPlan> plans = {box("B1", "central fold", -1, 40, 100, 30, 40), step,
                                        box("B2", "B1.top", 0, 0, 100, 30, 20)};
    keep_inside_ranges(plans, card.width, card.depth, margin);
    const auto& s = plans[1].parameter_values();
    // Its width fits (99.9 <= 100 - 2 margin): it keeps it and moves back to end margin short.
    EXPECT_NEAR(s.at("width"), 99.9, 1e-12);
    EXPECT_NEAR(s.at("offset"), 100 - margin - 99.9, 1e-9);
    EXPECT_NEAR(s.at("run_ground"), 40 - margin, 1e-12); // the wall: B1's height
    EXPECT_EQ(s.at("run_backdrop"), 20);                 // well inside the page beyond the wall
    const auto& t = plans[2].parameter_values();
    EXPECT_NEAR(t.at("offset"), margin, 1e-12);
    EXPECT_NEAR(t.at("width"), 100 - 2 * margin, 1e-12);
    EXPECT_NEAR(t.at("depth_ground"), 30 - margin, 1e-12);
    EXPECT_NEAR(t.at("depth_backdrop"), 30 - margin, 1e-12);
    // B1 itself is well inside the card: unchanged.
    EXPECT_EQ(plans[0].value("width"), 100);
    EXPECT_EQ(plans[0].value("offset"), 40);
    // Each builds on B1 (the step and B2 would meet at B1's top edge: built apart).
    for (size_t k : {1, 2}) {
        const RepairOutcome o = build_until_valid(card, {plans[0], plans[k]});
        EXPECT_EQ(o.kept, (std::vector<bool>{true, true}))
            << plans[k].name << ": " << (o.repairs.empty() ? "" : o.repairs[0].reason);
    }
}
