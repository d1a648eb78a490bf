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

MechanismPlan tent_on(const std::string& host, int parent, double offset, double width)
{
    MechanismPlan tent;
    static_cast<DesignedMechanism&>(tent) =
        DesignedMechanism::of_kind(MechanismKind::tent_fold, "T1", host);
    tent.parent = parent;
    TentFoldParams& q = tent.as<TentFoldParams>();
    q.offset = offset;
    q.width = width;
    q.foot = 15;
    q.foot_backdrop = 15;
    q.slope = 20;
    return tent;
}

const FitRepair* repair_of(const RepairOutcome& o, const std::string& name)
{
    for (const auto& r : o.repairs)
        if (r.mechanism == name)
            return &r;
    return nullptr;
}

/// The repairs and the last check's findings, for a failed expectation's message.
std::string story(const RepairOutcome& o)
{
    std::string s;
    for (const auto& r : o.repairs)
        s += r.mechanism + " " + r.action + ": " + r.reason + "\n";
    for (const auto& d : o.report.diagnostics)
        s += d.message + "\n";
    return s;
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

// The margin a repair keeps inside a host's ends (1e-6 of the default card's 210 mm).
constexpr double margin = 210e-6;

TEST(FitDesignRepair, OverlappingSweepsTrimTheLaterAndWhatStandsOnIt)
{
    // Closed, B1 sweeps [60 − 30, 100 + 30] = [30, 130] along the fold, B2 [110 − 30, 150 + 30]:
    // they overlap. Shrunk about its middle B2 still reaches B1 (at 70 %: [116 − 21, ...] =
    // [95, ...]), so it is trimmed: its front end panels come off and it starts where B1's sweep
    // ends, 130 (B2 [130, 150]). T1 on its top keeps its place along the fold and loses the same
    // first 20 mm. (Before repairs, B2 and T1 were dropped.)
    const RepairOutcome o =
        build_until_valid(CardParams(), {box("B1", "central fold", -1, 60, 40, 30, 40),
                                         box("B2", "central fold", -1, 110, 40, 30, 40),
                                         tent_on("B2.top", 1, 0, 40)});
    EXPECT_TRUE(o.valid) << story(o);
    EXPECT_EQ(o.kept, (std::vector<bool>{true, true, true}));
    EXPECT_TRUE(o.warnings.empty());
    const auto& b2 = o.plans[1].parameter_values();
    EXPECT_EQ(b2.at("front"), 0.0);
    EXPECT_EQ(b2.at("back"), 1.0);
    EXPECT_NEAR(b2.at("offset"), 130, 1e-3);
    EXPECT_NEAR(b2.at("width"), 20, 1e-3);
    EXPECT_EQ(b2.at("height"), 40); // trimmed, not shrunk
    const auto& t1 = o.plans[2].parameter_values();
    EXPECT_NEAR(t1.at("offset"), 0, 1e-3);
    EXPECT_NEAR(t1.at("width"), 20, 1e-3);
    EXPECT_EQ(o.plans[0].parameter_values(), box("B1", "", -1, 60, 40, 30, 40).parameter_values());
    ASSERT_TRUE(repair_of(o, "B2"));
    EXPECT_EQ(repair_of(o, "B2")->action, "trimmed");
    EXPECT_NE(repair_of(o, "B2")->reason.find("away from B1"), std::string::npos);
    EXPECT_NE(repair_of(o, "B2")->reason.find("Front yes → no"), std::string::npos);
    EXPECT_NE(repair_of(o, "B2")->reason.find("because it sweeps into B1"), std::string::npos);
    ASSERT_TRUE(repair_of(o, "T1"));
    EXPECT_EQ(repair_of(o, "T1")->action, "trimmed");
    EXPECT_NE(repair_of(o, "T1")->reason.find("with B2, which it stands on"), std::string::npos);
    EXPECT_FALSE(repair_of(o, "B1")) << (repair_of(o, "B1") ? repair_of(o, "B1")->reason : "");
}

TEST(FitDesignRepair, EndPanelsRunningIntoANeighbourComeOff)
{
    // B3 stands on B2's top, its front end at B2's front, 2 mm from B1's back end. Closing, its
    // front panels swing out by its half depth (25) over B1: they pass through B1's top. Shrunk
    // it still reaches past B2's front (the middle stays); its front panels come off instead.
    MechanismPlan b1 = box("B1", "central fold", -1, 40, 40, 30, 40);
    b1.as<BoxFoldParams>().back = false;
    MechanismPlan b2 = box("B2", "central fold", -1, 82, 40, 30, 10);
    b2.as<BoxFoldParams>().front = false;
    const RepairOutcome o =
        build_until_valid(CardParams(), {b1, b2, box("B3", "B2.top", 1, 0, 40, 25, 20)});
    EXPECT_TRUE(o.valid) << story(o);
    EXPECT_EQ(o.kept, (std::vector<bool>{true, true, true})) << story(o);
    ASSERT_TRUE(repair_of(o, "B3")) << story(o);
    EXPECT_EQ(repair_of(o, "B3")->action, "trimmed");
    EXPECT_NE(
        repair_of(o, "B3")->reason.find("its end panels facing B1 taken off (Front yes → no)"),
        std::string::npos)
        << story(o);
    EXPECT_NE(repair_of(o, "B3")->reason.find("(B1.TG) passes through"), std::string::npos)
        << story(o);
    EXPECT_EQ(o.plans[2].value("width"), 40);
}

TEST(FitDesignRepair, AChildOverhangingItsHostIsTrimmedToIt)
{
    // B2 on B1's 100 mm top runs [60, 110]: its generator refuses it. Shrunk about its middle
    // (85) it still overhangs (at 70 %: 85 + 17.5 = 102.5); trimmed to the top it keeps
    // [60, 100 − margin] at its full depth and height.
    const RepairOutcome o =
        build_until_valid(CardParams(), {box("B1", "central fold", -1, 40, 100, 30, 40),
                                         box("B2", "B1.top", 0, 60, 50, 20, 20)});
    EXPECT_TRUE(o.valid) << story(o);
    EXPECT_EQ(o.kept, (std::vector<bool>{true, true}));
    const auto& b2 = o.plans[1].parameter_values();
    EXPECT_NEAR(b2.at("offset"), 60, 1e-9);
    EXPECT_NEAR(b2.at("width"), 40 - margin, 1e-9);
    EXPECT_EQ(b2.at("depth_ground"), 20);
    EXPECT_EQ(b2.at("height"), 20);
    ASSERT_TRUE(repair_of(o, "B2"));
    EXPECT_EQ(repair_of(o, "B2")->action, "trimmed");
    EXPECT_NE(repair_of(o, "B2")->reason.find("trimmed to the length of B1.top"),
              std::string::npos);
    EXPECT_NE(repair_of(o, "B2")->reason.find("Width 50 mm → 40 mm"), std::string::npos);
}

TEST(FitDesignRepair, ABoxInsideAnothersSweepMovesOntoItsTop)
{
    // B2 [75, 85] lies inside B1's sweep [30, 130]: no shrink about its middle (80, B1's too) or
    // trim clears it, so it moves onto B1's top at the same place: 75 − 40 = 35 along the top.
    const RepairOutcome o =
        build_until_valid(CardParams(), {box("B1", "central fold", -1, 40, 80, 30, 40),
                                         box("B2", "central fold", -1, 75, 10, 10, 15)});
    EXPECT_TRUE(o.valid) << story(o);
    EXPECT_EQ(o.kept, (std::vector<bool>{true, true}));
    EXPECT_EQ(o.plans[1].host, "B1.top");
    EXPECT_EQ(o.plans[1].parent, 0);
    EXPECT_NEAR(o.plans[1].offset(), 35, 1e-9);
    EXPECT_EQ(o.plans[1].value("width"), 10);
    ASSERT_TRUE(repair_of(o, "B2"));
    EXPECT_EQ(repair_of(o, "B2")->action, "re-hosted");
    EXPECT_NE(repair_of(o, "B2")->reason.find("moved from central fold onto B1.top"),
              std::string::npos);
}

TEST(FitDesignRepair, WhatStoodOnADroppedBoxMovesDownToTheFold)
{
    // B2 is 200 high: closed, even at 70 % (140 + 14 = 154 > 148) it does not fit in the card,
    // and there is no other pair where it stands: dropped. T1 on its top moves down to the
    // central fold at the same place along it: 120 + 5 = 125.
    const RepairOutcome o =
        build_until_valid(CardParams(), {box("B1", "central fold", -1, 20, 60, 30, 40),
                                         box("B2", "central fold", -1, 120, 40, 20, 200),
                                         tent_on("B2.top", 1, 5, 30)});
    EXPECT_TRUE(o.valid) << story(o);
    EXPECT_EQ(o.kept, (std::vector<bool>{true, false, true}));
    ASSERT_TRUE(repair_of(o, "B2"));
    EXPECT_EQ(repair_of(o, "B2")->action, "dropped");
    EXPECT_NE(repair_of(o, "B2")->reason.find("shrunk to 70 %"), std::string::npos);
    EXPECT_TRUE(warned(o, "B2"));
    EXPECT_EQ(o.plans[2].host, "central fold");
    EXPECT_EQ(o.plans[2].parent, -1);
    EXPECT_NEAR(o.plans[2].offset(), 125, 1e-9);
    EXPECT_EQ(o.plans[2].value("width"), 30);
    ASSERT_TRUE(repair_of(o, "T1"));
    EXPECT_EQ(repair_of(o, "T1")->action, "re-hosted");
    EXPECT_NE(repair_of(o, "T1")->reason.find("onto the central fold"), std::string::npos);
    EXPECT_FALSE(warned(o, "T1"));
}

TEST(FitDesignRepair, RefusedParametersAreShrunkUntilTheGeneratorTakesThem)
{
    // A step on B1's ground side rising 50 up a 40 high wall: its generator refuses it. At 80 %
    // it rises 40, still not below the wall's top; at 70 % 35: kept, about the middle of its
    // width (30): width 28 from 16. (Before repairs, it was dropped.)
    StepFoldParams q;
    q.offset = 10;
    q.width = 40;
    q.run_ground = 20;
    q.run_backdrop = 50;
    const MechanismPlan step = step_on("B1.side_ground", 0, q);
    const RepairOutcome o =
        build_until_valid(CardParams(), {box("B1", "central fold", -1, 40, 100, 30, 40), step});
    EXPECT_TRUE(o.valid) << story(o);
    EXPECT_EQ(o.kept, (std::vector<bool>{true, true}));
    const auto& s = o.plans[1].parameter_values();
    EXPECT_NEAR(s.at("run_backdrop"), 35, 1e-9);
    EXPECT_NEAR(s.at("run_ground"), 14, 1e-9);
    EXPECT_NEAR(s.at("width"), 28, 1e-9);
    EXPECT_NEAR(s.at("offset"), 16, 1e-9);
    ASSERT_TRUE(repair_of(o, "S1"));
    EXPECT_EQ(repair_of(o, "S1")->action, "shrunk");
    EXPECT_NE(repair_of(o, "S1")->reason.find("shrunk to 70 % about its middle"),
              std::string::npos);
    EXPECT_NE(repair_of(o, "S1")->reason.find("RunBackdrop"), std::string::npos);
    EXPECT_TRUE(o.warnings.empty());
}

TEST(FitDesignRepair, AFailedValidityCheckShrinksTheMechanismItNames)
{
    // Closed, a box of height c and half depth g reaches c + g = 130 + 30 > 148 along its page:
    // the closed card does not enclose it. At 90 % it reaches 117 + 27 = 144 and fits. Their
    // sweeps [10, 120] and [124, 196] stay apart. (Before repairs, B2 was dropped.)
    const RepairOutcome o =
        build_until_valid(CardParams(), {box("B1", "central fold", -1, 40, 50, 30, 40),
                                         box("B2", "central fold", -1, 150, 20, 30, 130)});
    EXPECT_TRUE(o.valid) << story(o);
    EXPECT_EQ(o.kept, (std::vector<bool>{true, true}));
    const auto& b2 = o.plans[1].parameter_values();
    EXPECT_NEAR(b2.at("height"), 117, 1e-9);
    EXPECT_NEAR(b2.at("depth_ground"), 27, 1e-9);
    EXPECT_NEAR(b2.at("width"), 18, 1e-9);
    EXPECT_NEAR(b2.at("offset"), 151, 1e-9);
    ASSERT_TRUE(repair_of(o, "B2"));
    EXPECT_EQ(repair_of(o, "B2")->action, "shrunk");
    EXPECT_NE(repair_of(o, "B2")->reason.find("validity check failed"), std::string::npos);
    EXPECT_NE(repair_of(o, "B2")->reason.find("B2."), std::string::npos); // names its patch
    EXPECT_NE(repair_of(o, "B2")->reason.find("Height 130 mm → 117 mm"), std::string::npos);
}

TEST(FitDesignRepair, ShrinkingStopsAtTheSmallestPart)
{
    // At 80 % the depth 30 would be 24, below a smallest part of 25: only 90 % is tried (the
    // width 20, below it already, does not count), where the box still reaches 180 + 27 > 148.
    const RepairOutcome o =
        build_until_valid(CardParams(), {box("B1", "central fold", -1, 40, 20, 30, 200)}, 25.0);
    EXPECT_FALSE(o.valid);
    ASSERT_TRUE(repair_of(o, "B1"));
    EXPECT_EQ(repair_of(o, "B1")->action, "dropped");
    EXPECT_NE(repair_of(o, "B1")->reason.find("shrunk to 90 % about its middle did not help"),
              std::string::npos)
        << repair_of(o, "B1")->reason;
}

TEST(FitDesignRepair, NothingLeftIsNotValid)
{
    // 200 high: at 70 % still 140 + 21 > 148. (130 high, as before repairs, now shrinks to fit.)
    const RepairOutcome o =
        build_until_valid(CardParams(), {box("B1", "central fold", -1, 40, 50, 30, 200)});
    EXPECT_FALSE(o.valid);
    EXPECT_EQ(o.kept, (std::vector<bool>{false}));
    EXPECT_TRUE(warned(o, "B1"));
}

TEST(FitDesignRepair, RepairsAreCappedPerDesign)
{
    // Six boxes too high to close even at 70 % (154 + 7 > 148), far apart. The check names
    // them all; the most nested, the last, goes first. Three shrinks each would be 18 tries: the
    // cap of 16 leaves B1 one, the same way on every run.
    std::vector<MechanismPlan> plans;
    for (int k = 0; k < 6; ++k)
        plans.push_back(
            box("B" + std::to_string(k + 1), "central fold", -1, 5 + 34 * k, 10, 10, 220));
    const RepairOutcome o = build_until_valid(CardParams(), plans);
    EXPECT_FALSE(o.valid);
    ASSERT_EQ(o.repairs.size(), 6u);
    EXPECT_NE(o.repairs[0].reason.find("; shrunk to 90 % about its middle did not help"),
              std::string::npos)
        << o.repairs[0].reason;
    for (size_t k = 1; k < 6; ++k)
        EXPECT_NE(o.repairs[k].reason.find("and shrunk to 70 %"), std::string::npos)
            << o.repairs[k].reason;
    const RepairOutcome again = build_until_valid(CardParams(), plans);
    for (size_t k = 0; k < 6; ++k)
        EXPECT_EQ(again.repairs[k].reason, o.repairs[k].reason);
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
