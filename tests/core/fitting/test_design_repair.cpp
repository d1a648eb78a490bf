#include <gtest/gtest.h>

#include "popup/fitting/design_repair.hpp"

using namespace popup;

namespace {

MechanismPlan box(const std::string& name, const std::string& host, int parent, double offset,
                  double width, double depth, double height)
{
    MechanismPlan p;
    p.type = "box_fold";
    p.name = name;
    p.host = host;
    p.parent = parent;
    p.parameters = {{"offset", offset},
                    {"width", width},
                    {"depth_ground", depth},
                    {"depth_backdrop", depth},
                    {"height", height},
                    {"panel_pairs", 1},
                    {"front", 1},
                    {"back", 1}};
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
    tent.type = "tent_fold";
    tent.name = "T1";
    tent.host = "B2.top";
    tent.parent = 1;
    tent.parameters = {
        {"offset", 0}, {"width", 40}, {"foot", 20}, {"foot_backdrop", 20}, {"slope", 25}};
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
    MechanismPlan step;
    step.type = "step_fold";
    step.name = "S1";
    step.host = "B1.side_ground";
    step.parent = 0;
    step.parameters = {{"offset", 10}, {"width", 40}, {"run_ground", 20}, {"run_backdrop", 50}};
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
