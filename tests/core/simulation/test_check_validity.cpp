#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <tbb/task_arena.h>

#include "generated_scaffolds.hpp"
#include "popup/simulation/check_validity.hpp"
#include "sheet_designs.hpp"
#include "test_support.hpp"
#include "validity_cases.hpp"

using namespace popup;

namespace {
bool has_code(const ValidityReport& r, const std::string& code)
{
    for (const Diagnostic& d : r.diagnostics)
        if (to_string(d.code) == code)
            return true;
    return false;
}

const Diagnostic* find_code(const ValidityReport& r, const std::string& code)
{
    for (const Diagnostic& d : r.diagnostics)
        if (to_string(d.code) == code)
            return &d;
    return nullptr;
}
} // namespace

TEST(CheckValidity, TentFoldIsValidWithTinyResiduals)
{
    const ValidityReport r = check_validity(fixtures::valid_tent_card());
    EXPECT_TRUE(r.foldable);
    EXPECT_TRUE(r.stable);
    EXPECT_TRUE(r.intersection_free);
    EXPECT_TRUE(r.enclosed);
    EXPECT_TRUE(r.diagnostics.empty()) << r.diagnostics.front().message;
    EXPECT_LE(r.max_hinge_residual, 1e-9 * r.model_size);
    EXPECT_LE(r.max_edge_strain, 1e-12);
    EXPECT_LE(r.flatness_at_zero, 1e-6 * r.model_size);
}

TEST(CheckValidity, MultiMechanismCardIsValid)
{
    const ValidityReport r = check_validity(fixtures::valid_multi_card());
    EXPECT_TRUE(r.valid()) << (r.diagnostics.empty() ? "" : r.diagnostics.front().message);
    EXPECT_TRUE(r.crossings.empty());
}

TEST(CheckValidity, TentWithShortSlopesIsNotFoldable)
{
    const ValidityReport r = check_validity(fixtures::broken_tent_card());
    EXPECT_FALSE(r.foldable);
    // It locks opening, where sin(θ/2) = slope / foot = 25/30.
    EXPECT_NEAR(r.locked_at * 180 / M_PI, 2 * std::asin(25.0 / 30.0) * 180 / M_PI, 0.05);
    const Diagnostic* d = find_code(r, "motion_locked");
    ASSERT_NE(d, nullptr);
    EXPECT_NE(d->message.find("112.9"), std::string::npos) << d->message;
}

TEST(CheckValidity, FiveBarLoopIsNotStable)
{
    const ValidityReport r = check_validity(fixtures::five_bar_card());
    EXPECT_FALSE(r.stable);
    const Diagnostic* d = find_code(r, "unstable");
    ASSERT_NE(d, nullptr);
    EXPECT_NE(d->message.find("1 free motion"), std::string::npos) << d->message;
    for (const char* id : {"patch 2", "patch 3", "patch 4"})
        EXPECT_NE(d->message.find(id), std::string::npos) << d->message;
    std::vector<int> moving = d->patches;
    std::sort(moving.begin(), moving.end());
    EXPECT_EQ(moving, (std::vector<int>{2, 3, 4}));
    ASSERT_TRUE(d->angle_deg.has_value());
    EXPECT_GT(*d->angle_deg, 0.0);
    EXPECT_LT(*d->angle_deg, 180.0);
}

TEST(CheckValidity, WallsCollidingAt40DegreesAreFound)
{
    // The walls' tops meet at exactly 40° (tan(θ/2) = h/d). The onset is bisected between the
    // last clear sample and the first crossing one: documented precision = step / 2^refine_depth,
    // and never later than the contact (closing runs towards smaller angles).
    for (int samples : {181, 361, 91}) {
        ValidityOptions options;
        options.samples = samples;
        const ValidityReport r = check_validity(fixtures::colliding_walls_card(), options);
        EXPECT_FALSE(r.intersection_free);
        const Crossing* walls = nullptr;
        for (const Crossing& c : r.crossings)
            if (c.patch_a == 2 && c.patch_b == 3)
                walls = &c;
        ASSERT_NE(walls, nullptr) << samples;
        const double precision = 180.0 / (samples - 1) / double(1 << options.refine_depth);
        const double onset = walls->angle * 180 / M_PI;
        EXPECT_NEAR(onset, 40.0, precision + 1e-9) << samples;
        EXPECT_LE(onset, 40.0 + 1e-9) << samples;
        EXPECT_GT(walls->depth, 1.0);
        // Nothing crosses before the walls meet.
        for (const Crossing& c : r.crossings)
            EXPECT_LE(c.angle * 180 / M_PI, 40.0 + 1e-9);
    }
}

TEST(CheckValidity, TentStickingOutOfTheClosedCardIsNotEnclosed)
{
    const ValidityReport r = check_validity(fixtures::sticking_out_tent_card());
    EXPECT_TRUE(r.foldable);
    EXPECT_TRUE(r.stable);
    EXPECT_FALSE(r.enclosed);
    const Diagnostic* d = find_code(r, "not_enclosed");
    ASSERT_NE(d, nullptr);
    EXPECT_NE(d->message.find("by 10 mm"), std::string::npos) << d->message;
}

TEST(CheckValidity, StackedStepFoldIsNotACrossing)
{
    // Flat at 180° and at 0°, every patch lies on another: touching, never crossing.
    Scaffold card = fixtures::make_card(200, 140);
    fixtures::add_step_fold(card, 50, 40, 30, 20);
    const ValidityReport r = check_validity(card);
    EXPECT_TRUE(r.intersection_free);
    EXPECT_TRUE(r.valid()) << (r.diagnostics.empty() ? "" : r.diagnostics.front().message);
}

TEST(CheckValidity, BadOptionsAreNamed)
{
    ValidityOptions o;
    o.samples = 1;
    const ValidityReport r = check_validity(fixtures::valid_tent_card(), o);
    EXPECT_FALSE(r.valid());
    EXPECT_TRUE(has_code(r, "bad_option"));
}

TEST(FindCrossings, ReportsDepthOfTheWalls)
{
    const Scaffold s = fixtures::colliding_walls_card();
    const Result<FoldSweep> sweep = simulate_fold(s, {fixtures::deg(30)});
    ASSERT_EQ(sweep.value.states.size(), 1u);
    const auto crossings = find_crossings(s, sweep.value.states[0], 1e-6);
    ASSERT_FALSE(crossings.empty());
    // Each wall's top passes the mid-plane by d·sin15° − h·cos15° at 30°.
    const double d = 50, h = d * std::tan(fixtures::deg(20));
    const double past = h * std::cos(fixtures::deg(15)) - d * std::sin(fixtures::deg(15));
    EXPECT_GT(crossings[0].depth, 0.0);
    EXPECT_LT(crossings[0].depth, 2 * past + 1e-9);
}

TEST(CheckValidity, ClearanceIgnoresSharedHingesButCatchesNearMisses)
{
    ValidityOptions o;
    o.clearance = 0.5;
    EXPECT_TRUE(check_validity(fixtures::valid_tent_card(), o).intersection_free);
    // A short wall on the ground runs into the face of a tall wall on the backdrop; with 5 mm
    // clearance the verdict comes earlier in the closing, while the gap is still open.
    Scaffold s = fixtures::make_card(200, 140);
    const int g = fixtures::add_quad(s, {50, 60, 0}, {50, 120, 0}, {50, 120, 15}, {50, 60, 15});
    const int b = fixtures::add_quad(s, {-50, 40, 0}, {-50, 40, 40}, {-50, 140, 40}, {-50, 140, 0});
    s.glue = {{s.ground, g}, {s.backdrop, b}};
    auto onset = [&](double clearance) {
        o.clearance = clearance;
        for (const Crossing& c : check_validity(s, o).crossings)
            if (c.patch_a == g && c.patch_b == b)
                return c.angle * 180 / M_PI;
        return -1.0;
    };
    const double touching = onset(0.0);
    const double near_miss = onset(5.0);
    EXPECT_GT(touching, 0.0);
    EXPECT_GT(near_miss, touching + 1.0);
}

TEST(CheckValidity, TheVerdictDoesNotDependOnTheSampleCount)
{
    // π·k/(n-1) does not round to π for every n (61 and 121 among them): the sample next to the
    // flat design state must still be the design state, not an open state a hair below it.
    for (const fixtures::NamedDesign& d : fixtures::single_mechanism_cards()) {
        for (int samples : {19, 37, 61, 91, 121, 181, 361}) {
            ValidityOptions options;
            options.samples = samples;
            const ValidityReport r = check_validity(d.scaffold, options);
            EXPECT_TRUE(r.valid())
                << d.name << " with " << samples
                << " samples: " << (r.diagnostics.empty() ? "" : r.diagnostics.front().message);
        }
    }
}

TEST(CheckValidity, PatchesHeldByNothingAreNamedNotCrashes)
{
    // A tent whose hinges are all gone: no central fold, and the slopes hang from nothing.
    Scaffold loose = fixtures::make_card();
    const std::vector<int> tent = fixtures::add_tent_fold(loose, 40, 60, 30, 40);
    loose.hinges.clear();
    const ValidityReport r = check_validity(loose);
    EXPECT_FALSE(r.valid());
    std::vector<DiagnosticCode> codes;
    for (const Diagnostic& d : r.diagnostics)
        codes.push_back(d.code);
    EXPECT_NE(std::find(codes.begin(), codes.end(), DiagnosticCode::bases_not_hinged), codes.end());
    // Each slope hangs alone: one finding each, naming it.
    std::vector<int> ids;
    for (const Diagnostic& d : r.diagnostics)
        if (d.code == DiagnosticCode::detached_patch)
            ids.insert(ids.end(), d.patches.begin(), d.patches.end());
    std::sort(ids.begin(), ids.end());
    std::vector<int> expected = tent;
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(ids, expected);

    // One patch beside a well-built card, attached to nothing.
    Scaffold stray = fixtures::make_card();
    fixtures::add_tent_fold(stray, 40, 60, 30, 40);
    const int alone =
        fixtures::add_quad(stray, {100, 170, 0}, {110, 170, 0}, {110, 180, 0}, {100, 180, 0});
    const ValidityReport s = check_validity(stray);
    EXPECT_FALSE(s.valid());
    ASSERT_EQ(s.diagnostics.size(), 1u);
    EXPECT_EQ(s.diagnostics.front().code, DiagnosticCode::detached_patch);
    EXPECT_EQ(s.diagnostics.front().patches, std::vector<int>{alone});
    const Result<FoldSweep> sweep = simulate_fold(stray, {M_PI / 2});
    EXPECT_FALSE(sweep.ok);
}

TEST(CheckValidity, ClearanceIsBoundedAndNeverTurnsInvalidIntoValid)
{
    for (const fixtures::NamedDesign& d : fixtures::single_mechanism_cards()) {
        const double largest = 0.05 * d.scaffold.size();
        bool was_valid = true;
        for (double fraction : {0.0, 0.01, 0.05, 0.1, 0.2, 0.4, 0.7, 1.0}) {
            ValidityOptions options;
            options.samples = 37;
            options.clearance = fraction * largest;
            const ValidityReport r = check_validity(d.scaffold, options);
            EXPECT_FALSE(r.valid() && !was_valid)
                << d.name << ": VALID again at clearance " << options.clearance << " mm";
            was_valid = r.valid();
        }
        for (double beyond : {1.001 * largest, 1000.0, std::numeric_limits<double>::infinity(),
                              -0.1, std::numeric_limits<double>::quiet_NaN()}) {
            ValidityOptions options;
            options.clearance = beyond;
            const ValidityReport r = check_validity(d.scaffold, options);
            EXPECT_FALSE(r.valid()) << d.name << " " << beyond;
            ASSERT_EQ(r.diagnostics.size(), 1u);
            EXPECT_EQ(r.diagnostics.front().code, DiagnosticCode::bad_option);
            EXPECT_EQ(r.diagnostics.front().parameter, "clearance");
        }
    }
}

// The sparse solver's rank test (inertia of JᵀJ - τI) against the dense one (pivoted LDLᵀ, then
// eigenvalues): the same verdicts and diagnostics on rigid mechanisms of many bodies, and the same
// free motions on a chain of 7 links between the bases (whose path is arbitrary: 5 free motions).
TEST(CheckValidity, SparseAndDenseSolversGiveTheSameReport)
{
    auto both = [](const Scaffold& card) {
        ValidityOptions dense;
        dense.dense_linear_algebra = true;
        dense.samples = 37;
        ValidityOptions sparse;
        sparse.samples = 37;
        return std::make_pair(check_validity(card, dense), check_validity(card, sparse));
    };
    for (const Scaffold& card : {fixtures::nested_boxes(2), fixtures::box_with_panel_pairs(2)}) {
        const auto [a, b] = both(card);
        EXPECT_TRUE(a.valid());
        EXPECT_TRUE(b.valid());
        EXPECT_TRUE(b.diagnostics.empty()) << b.diagnostics.front().message;
        EXPECT_NEAR(a.max_hinge_residual, b.max_hinge_residual, 1e-10 * card.size());
        EXPECT_NEAR(a.flatness_at_zero, b.flatness_at_zero, 1e-8 * card.size());
    }
    const auto [a, b] = both(fixtures::chain_card(7));
    EXPECT_EQ(a.foldable, b.foldable);
    EXPECT_FALSE(b.stable);
    EXPECT_FALSE(a.stable);
    const Diagnostic* da = find_code(a, "unstable");
    const Diagnostic* db = find_code(b, "unstable");
    ASSERT_NE(da, nullptr);
    ASSERT_NE(db, nullptr);
    EXPECT_EQ(da->message, db->message);
    EXPECT_NE(db->message.find("5 free motion"), std::string::npos) << db->message;
    EXPECT_EQ(db->patches.size(), 7u);
}

// Components are followed on all cores: the report must be the one a single thread writes, to
// the bit, whatever the scheduling (an unstable chain and a crossing design included).
TEST(CheckValidity, AllCoresGiveTheOneThreadReport)
{
    const std::vector<Scaffold> cards = {
        fixtures::generated_scaffold(60), fixtures::chain_card(7), fixtures::nested_boxes(2),
        fixtures::colliding_walls_card(), fixtures::broken_tent_card()};
    for (const Scaffold& card : cards) {
        ValidityReport serial;
        tbb::task_arena(1).execute([&] { serial = check_validity(card); });
        for (int run = 0; run < 3; ++run) {
            const ValidityReport parallel = check_validity(card);
            EXPECT_EQ(parallel.valid(), serial.valid());
            EXPECT_EQ(parallel.stable, serial.stable);
            EXPECT_EQ(parallel.max_hinge_residual, serial.max_hinge_residual);
            EXPECT_EQ(parallel.flatness_at_zero, serial.flatness_at_zero);
            ASSERT_EQ(parallel.diagnostics.size(), serial.diagnostics.size());
            for (size_t k = 0; k < serial.diagnostics.size(); ++k) {
                EXPECT_EQ(parallel.diagnostics[k].message, serial.diagnostics[k].message);
                EXPECT_EQ(parallel.diagnostics[k].patches, serial.diagnostics[k].patches);
            }
        }
    }
}
