#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "popup/simulation/simulate_fold.hpp"
#include "test_support.hpp"

using namespace popup;
using fixtures::deg;

namespace {
Vec3 ground_direction(double theta)
{
    return {std::sin(theta / 2), 0, std::cos(theta / 2)};
}
Vec3 backdrop_direction(double theta)
{
    return {-std::sin(theta / 2), 0, std::cos(theta / 2)};
}
} // namespace

// docs/MATH.md, "Symmetric tent fold": apex height z(θ) = a cos(θ/2) + sqrt(s² − a² sin²(θ/2)).
TEST(TentFold, ApexFollowsTheClosedFormOver181Angles)
{
    const double a = 30, s = 40, y0 = 40;
    Scaffold card = fixtures::make_card(200, 140);
    const auto slopes = fixtures::add_tent_fold(card, y0, 60, a, s);
    const Result<FoldSweep> r = simulate_fold(card, fixtures::angle_range(180, 0, 181));
    ASSERT_TRUE(r.ok);
    ASSERT_TRUE(r.value.complete);
    ASSERT_EQ(r.value.states.size(), 181u);
    const double size = card.size();
    const Vec3 apex0(0, y0, std::sqrt(s * s - a * a));
    for (const FoldState& st : r.value.states) {
        const double t = st.angle;
        const double z =
            a * std::cos(t / 2) + std::sqrt(s * s - a * a * std::pow(std::sin(t / 2), 2));
        const Vec3 apex = fixtures::world_point(card, st, slopes[0], apex0);
        EXPECT_NEAR(apex.z(), z, 1e-9 * size) << "at " << t * 180 / M_PI << "°";
        EXPECT_NEAR(apex.x(), 0.0, 1e-9 * size);
        EXPECT_NEAR(apex.y(), y0, 1e-9 * size);
    }
    EXPECT_LE(fixtures::max_residual(r.value), 1e-9 * size);
    EXPECT_LE(fixtures::max_strain(r.value), 1e-12);
}

// docs/MATH.md, "Parallelogram step fold": the nose C(θ) = a·g(θ) + b·b(θ).
TEST(StepFold, FlatAtBothEndsAndErectAt90)
{
    const double a = 30, b = 20, y0 = 50;
    Scaffold card = fixtures::make_card(200, 140);
    const auto step = fixtures::add_step_fold(card, y0, 40, a, b);
    const Result<FoldSweep> r = simulate_fold(card, fixtures::angle_range(180, 0, 181));
    ASSERT_TRUE(r.ok);
    ASSERT_TRUE(r.value.complete);
    const double size = card.size();
    const Vec3 nose0(a - b, y0, 0), hinge0(a, y0, 0);
    for (const FoldState& st : r.value.states) {
        const Vec3 expected =
            a * ground_direction(st.angle) + b * backdrop_direction(st.angle) + Vec3(0, y0, 0);
        EXPECT_LT((fixtures::world_point(card, st, step[0], nose0) - expected).norm(), 1e-9 * size)
            << "at " << st.angle * 180 / M_PI << "°";
        EXPECT_LT((fixtures::world_point(card, st, step[1], nose0) - expected).norm(), 1e-9 * size);
    }
    const FoldState& open = r.value.states.front();
    const FoldState& erect = r.value.states[90];
    const FoldState& closed = r.value.states.back();
    EXPECT_NEAR(fixtures::world_point(card, open, step[0], nose0).z(), 0.0, 1e-12);
    EXPECT_NEAR(fixtures::world_point(card, closed, step[0], nose0).x(), 0.0, 1e-9 * size);
    // At 90° the riser stands at right angles to the ground.
    const Vec3 riser = fixtures::world_point(card, erect, step[0], nose0) -
                       fixtures::world_point(card, erect, step[0], hinge0);
    EXPECT_NEAR(riser.dot(ground_direction(deg(90))), 0.0, 1e-9 * size);
    EXPECT_TRUE(r.diagnostics.empty());
    EXPECT_LE(fixtures::max_residual(r.value), 1e-9 * size);
}

TEST(StepFold, OppositeFoldDirectionsTakeTheOtherBranch)
{
    Scaffold card = fixtures::make_card(200, 140);
    const auto step = fixtures::add_step_fold(card, 50, 40, 30, 20);
    for (Hinge& h : card.hinges)
        if (h.patch_b == step[0] || h.patch_b == step[1])
            h.direction = h.direction == FoldDirection::valley ? FoldDirection::mountain
                                                               : FoldDirection::valley;
    const Result<FoldSweep> r = simulate_fold(card, {deg(170)});
    ASSERT_EQ(r.value.states.size(), 1u);
    // The riser now folds under the ground: its nose leaves the page toward z < 0.
    const Vec3 nose = fixtures::world_point(card, r.value.states[0], step[0], {10, 50, 0});
    const Vec3 parallelogram = 30 * ground_direction(deg(170)) + 20 * backdrop_direction(deg(170));
    EXPECT_GT((nose - parallelogram - Vec3(0, 50, 0)).norm(), 1.0);
}

// docs/MATH.md, "V-fold": the tip P is where three spheres meet (centres O, A(θ), B(θ)).
TEST(VFold, TipMatchesTheSphereIntersection)
{
    const double r = 50, alpha = deg(45), L = 60, gamma = deg(60);
    Scaffold card = fixtures::make_card(200, 140);
    const auto v = fixtures::add_v_fold(card, 0, r, alpha, L, gamma);
    const Result<FoldSweep> sweep = simulate_fold(card, fixtures::angle_range(180, 0, 181));
    ASSERT_TRUE(sweep.ok);
    ASSERT_TRUE(sweep.value.complete);
    const double X = r * std::sin(alpha), Y = r * std::cos(alpha);
    const Vec3 P0(0, L * std::cos(gamma), L * std::sin(gamma));
    const double dA2 = (P0 - Vec3(X, Y, 0)).squaredNorm();
    const double K = 0.5 * (X * X + Y * Y + L * L - dA2);
    for (const FoldState& st : sweep.value.states) {
        // p_y·Y + p_z·X·cos(θ/2) = K and p_y² + p_z² = L²: the root continuous with P0.
        const double c = X * std::cos(st.angle / 2);
        const double n2 = Y * Y + c * c;
        const double disc = std::sqrt(n2 * L * L - K * K);
        const double py = (K * Y - c * disc) / n2, pz = (K * c + Y * disc) / n2;
        const Vec3 tip = fixtures::world_point(card, st, v[0], P0);
        EXPECT_LT((tip - Vec3(0, py, pz)).norm(), 1e-9 * card.size())
            << "at " << st.angle * 180 / M_PI << "°";
        EXPECT_LT((fixtures::world_point(card, st, v[1], P0) - tip).norm(), 1e-9 * card.size());
    }
}

TEST(SimulateFold, AnglesOutsideTheRangeAreRejected)
{
    const Result<FoldSweep> r = simulate_fold(fixtures::make_card(), {deg(190)});
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.diagnostics.front().code, DiagnosticCode::angle_out_of_range);
}

TEST(SimulateFold, InvalidScaffoldIsReportedNotSimulated)
{
    Scaffold s = fixtures::make_card();
    s.patches[0].outer[1].z() = std::nan("");
    const Result<FoldSweep> r = simulate_fold(s, {deg(90)});
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.diagnostics.front().code, DiagnosticCode::non_finite_coordinate);
    EXPECT_TRUE(r.value.states.empty());
}

TEST(SimulateFold, StatesComeBackInTheRequestedOrder)
{
    Scaffold card = fixtures::make_card();
    fixtures::add_tent_fold(card, 40, 60, 30, 40);
    const std::vector<double> angles{deg(30), deg(150), deg(0), deg(90)};
    const Result<FoldSweep> r = simulate_fold(card, angles);
    ASSERT_EQ(r.value.states.size(), 4u);
    for (size_t i = 0; i < angles.size(); ++i)
        EXPECT_EQ(r.value.states[i].angle, angles[i]);
}

TEST(ContinueFold, FromACachedStateMatchesASweepFromTheDesign)
{
    Scaffold card = fixtures::make_card(200, 140);
    fixtures::add_step_fold(card, 20, 40, 30, 20);
    fixtures::add_tent_fold(card, 80, 50, 30, 40);
    fixtures::add_v_fold(card, 150, 40, deg(45), 45, deg(60));
    const Result<FoldSweep> cached = simulate_fold(card, {deg(120)});
    ASSERT_EQ(cached.value.states.size(), 1u);
    const std::vector<double> targets{deg(100), deg(150), deg(0), deg(180)};
    const Result<FoldSweep> direct = simulate_fold(card, targets);
    const Result<FoldSweep> resumed = continue_fold(card, cached.value.states[0], targets);
    ASSERT_TRUE(resumed.ok);
    ASSERT_EQ(resumed.value.states.size(), targets.size());
    for (size_t i = 0; i < targets.size(); ++i)
        for (size_t p = 0; p < card.patches.size(); ++p) {
            const Pose& a = direct.value.states[i].poses[p];
            const Pose& b = resumed.value.states[i].poses[p];
            EXPECT_LT((a.rotation - b.rotation).norm(), 1e-9);
            EXPECT_LT((a.translation - b.translation).norm(), 1e-9 * card.size());
        }
}
