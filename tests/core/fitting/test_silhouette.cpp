// Silhouettes and depth layers of meshes built here, on the card's ground: its profile frame is
// u = 100 - y, v = x (origin mid central fold of a 200 mm card, u along the fold, v across the
// ground), normal +z. Expected areas are closed forms of the meshes (a regular polygon, boxes).
#include <gtest/gtest.h>

#include <cmath>

#include "fitting/silhouette_cache.hpp"
#include "popup/fitting/depth_layers.hpp"
#include "popup/fitting/silhouette.hpp"
#include "popup/mechanisms/step_fold.hpp"
#include "popup/model/apply_profile.hpp"
#include "popup/model/card.hpp"
#include "popup/simulation/simulate_fold.hpp"

using namespace popup;

namespace {

constexpr double kPi = 3.14159265358979323846;

Scaffold card()
{
    CardParams p;
    p.width = 200;
    p.depth = 140;
    return make_card(p).value;
}

// Closed box [lo, hi], triangles counter-clockwise seen from outside.
void add_box(ModelMesh& m, const Vec3& lo, const Vec3& hi)
{
    const int base = int(m.vertices.size());
    for (int k = 0; k < 8; ++k)
        m.vertices.emplace_back(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(),
                                k & 4 ? hi.z() : lo.z());
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        m.triangles.push_back({base + q[0], base + q[1], base + q[2]});
        m.triangles.push_back({base + q[0], base + q[2], base + q[3]});
    }
}

// A closed n-sided prism (a wheel) standing on z from z0 to z1 around (cx, cy).
void add_wheel(ModelMesh& m, double cx, double cy, double r, double z0, double z1, int n)
{
    const int base = int(m.vertices.size());
    for (int k = 0; k < n; ++k) {
        const double a = 2 * kPi * k / n;
        m.vertices.emplace_back(cx + r * std::cos(a), cy + r * std::sin(a), z0);
        m.vertices.emplace_back(cx + r * std::cos(a), cy + r * std::sin(a), z1);
    }
    m.vertices.emplace_back(cx, cy, z0);
    m.vertices.emplace_back(cx, cy, z1);
    const int bottom = base + 2 * n, top = bottom + 1;
    for (int k = 0; k < n; ++k) {
        const int a0 = base + 2 * k, a1 = a0 + 1;
        const int b0 = base + 2 * ((k + 1) % n), b1 = b0 + 1;
        m.triangles.push_back({a0, b0, b1});
        m.triangles.push_back({a0, b1, a1});
        m.triangles.push_back({bottom, b0, a0});
        m.triangles.push_back({top, a1, b1});
    }
}

Scaffold card_with_step()
{
    Scaffold s = card();
    StepFoldParams p;
    p.offset = 60;
    p.width = 60;
    p.run_ground = 30;
    p.run_backdrop = 20;
    add_step_fold(s, central_fold(s), p, "Step");
    return s;
}

double regular_polygon_area(int n, double r)
{
    return 0.5 * n * r * r * std::sin(2 * kPi / n);
}

} // namespace

TEST(Silhouette, AWheelSeenAlongItsAxisIsItsExactPolygon)
{
    const Scaffold s = card();
    ModelMesh wheel;
    wheel.source = "wheel";
    add_wheel(wheel, 50, 100, 10, 5, 15, 256);
    const Result<Silhouette> r = silhouette_profile(wheel, s, s.ground);
    ASSERT_TRUE(r.ok) << r.diagnostics.front().message;
    const double polygon = regular_polygon_area(256, 10);
    EXPECT_NEAR(r.value.area, polygon, 1e-4); // nanometre grid
    // Within the polygon's own tolerance of the circle: πr² − (n/2) r² sin(2π/n).
    EXPECT_LE(std::abs(r.value.area - kPi * 100), kPi * 100 - polygon + 1e-4);
    EXPECT_EQ(r.value.pieces, 1);
    EXPECT_TRUE(r.value.profile.holes.empty());
    EXPECT_EQ(r.value.profile.outer.size(), 256u); // no raster: the wheel keeps its corners
    // Centred at u = 100 - y = 0, v = x = 50.
    double u = 0, v = 0;
    for (const Vec2& q : r.value.profile.outer) {
        u += q.x() / 256;
        v += q.y() / 256;
    }
    EXPECT_NEAR(u, 0, 1e-6);
    EXPECT_NEAR(v, 50, 1e-6);
    EXPECT_NE(r.value.profile.name.find("wheel"), std::string::npos);
}

TEST(Silhouette, TheDepthWindowCutsTrianglesAtItsPlanes)
{
    const Scaffold s = card();
    ModelMesh m;
    add_wheel(m, 50, 100, 10, 5, 15, 64);
    add_box(m, {80, 40, 20}, {100, 70, 25}); // 20 x 30 footprint, above the wheel
    const double wheel = regular_polygon_area(64, 10);
    SilhouetteOptions all;
    const Result<Silhouette> both = silhouette_profile(m, s, s.ground, all);
    ASSERT_TRUE(both.ok);
    EXPECT_EQ(both.value.pieces, 2);
    EXPECT_NEAR(both.value.area, 600, 1e-4); // the largest piece: the box's 20 x 30
    EXPECT_NEAR(both.value.left_out, wheel, 1e-4);
    SilhouetteOptions low;
    low.depth_near = 0;
    low.depth_far = 10; // the wheel's lower half: same disc
    const Result<Silhouette> lower = silhouette_profile(m, s, s.ground, low);
    ASSERT_TRUE(lower.ok);
    EXPECT_EQ(lower.value.pieces, 1);
    EXPECT_NEAR(lower.value.area, wheel, 1e-4);
    SilhouetteOptions gap;
    gap.depth_near = 16;
    gap.depth_far = 19;
    const Result<Silhouette> none = silhouette_profile(m, s, s.ground, gap);
    EXPECT_FALSE(none.ok);
    EXPECT_EQ(none.diagnostics.front().code, DiagnosticCode::bad_option);
    SilhouetteOptions upside_down;
    upside_down.depth_near = 10;
    upside_down.depth_far = 5;
    const Result<Silhouette> empty = silhouette_profile(m, s, s.ground, upside_down);
    EXPECT_FALSE(empty.ok);
    EXPECT_NE(empty.diagnostics.front().message.find("[10, 5]"), std::string::npos);
}

TEST(Silhouette, IsAProfileApplyProfileTakes)
{
    // A silhouette on the ground cuts the ground to it only where it holds the central fold:
    // a box straddling the fold (x -5..60, y 70..130) leaves the ground x 0..60, y 70..130.
    Scaffold s = card();
    ModelMesh m;
    add_box(m, {-5, 70, 0}, {60, 130, 10});
    const Result<Silhouette> r = silhouette_profile(m, s, s.ground);
    ASSERT_TRUE(r.ok);
    const Result<ProfileApplied> applied = apply_profile(s, s.ground, r.value.profile);
    ASSERT_TRUE(applied.ok) << applied.diagnostics.front().message;
    EXPECT_NEAR(applied.value.area_after, 60 * 60, 1e-4);
    EXPECT_NEAR((s.hinges.front().to - s.hinges.front().from).norm(), 60, 1e-5);
}

TEST(Silhouette, ABadModelOrPatchIsNamed)
{
    const Scaffold s = card();
    ModelMesh m;
    add_box(m, {0, 0, 0}, {1, 1, 1});
    EXPECT_EQ(silhouette_profile(m, s, 99).diagnostics.front().code, DiagnosticCode::unknown_patch);
    m.vertices[0].x() = std::nan("");
    EXPECT_EQ(silhouette_profile(m, s, s.ground).diagnostics.front().code,
              DiagnosticCode::non_finite_model);
}

TEST(DepthLayers, TwoTopsAtTwoHeightsAreTwoLayers)
{
    const Scaffold s = card();
    ModelMesh m;
    add_box(m, {10, 60, 0}, {40, 140, 20}); // top 30 x 80 at z = 20
    add_box(m, {20, 80, 0}, {30, 100, 28}); // top 10 x 20 at z = 28
    const Result<std::vector<DepthLayer>> r = depth_layers(m, s, s.ground);
    ASSERT_TRUE(r.ok) << r.diagnostics.front().message;
    ASSERT_EQ(r.value.size(), 2u);
    EXPECT_NEAR(r.value[0].depth, 28, 1e-12); // nearest the viewer first
    EXPECT_NEAR(r.value[0].depth_near, 28, 1e-12);
    EXPECT_NEAR(r.value[0].depth_far, 28, 1e-12);
    EXPECT_NEAR(r.value[0].silhouette.area, 200, 1e-4);
    EXPECT_NEAR(r.value[1].depth, 20, 1e-12);
    EXPECT_NEAR(r.value[1].silhouette.area, 2400, 1e-4);
    // The bottoms face away and the sides are edge-on: only the two tops count.
    EXPECT_EQ(r.value[0].silhouette.triangles + r.value[1].silhouette.triangles, 4);

    DepthLayerOptions one;
    one.max_layers = 1;
    const auto merged = depth_layers(m, s, s.ground, one);
    ASSERT_TRUE(merged.ok);
    ASSERT_EQ(merged.value.size(), 1u);
    EXPECT_NEAR(merged.value[0].silhouette.area, 2400, 1e-4); // B's top lies over A's
    EXPECT_NEAR(merged.value[0].depth, (200 * 28 + 2400 * 20) / 2600.0, 1e-9);

    DepthLayerOptions big_gap;
    big_gap.min_gap = 9; // wider than the 8 mm between the tops
    EXPECT_EQ(depth_layers(m, s, s.ground, big_gap).value.size(), 1u);

    DepthLayerOptions no_slivers;
    no_slivers.min_area_fraction = 0.1; // B's 200 of 2600 mm² joins A's layer
    EXPECT_EQ(depth_layers(m, s, s.ground, no_slivers).value.size(), 1u);

    DepthLayerOptions bad;
    bad.max_layers = 0;
    const auto refused = depth_layers(m, s, s.ground, bad);
    EXPECT_FALSE(refused.ok);
    EXPECT_EQ(refused.diagnostics.front().parameter.value_or(""), "max_layers");
}

TEST(Silhouette, OverlappingAndFlippedFacesOfASoupUniteExactly)
{
    // Two open squares, unshared vertices: [0, 10]² at z = 5 facing up, [5, 15] × [0, 10] at
    // z = 8 facing down, and a triangle folded over the first (it lies inside it). Union: 150 mm²
    // in one piece, seen from above (u = 100 - y, v = x) or below alike.
    ModelMesh m;
    auto square = [&](double x0, double x1, double z, bool up) {
        const int b = int(m.vertices.size());
        m.vertices.insert(m.vertices.end(), {{x0, 0, z}, {x1, 0, z}, {x1, 10, z}, {x0, 10, z}});
        if (up) {
            m.triangles.push_back({b, b + 1, b + 2});
            m.triangles.push_back({b, b + 2, b + 3});
        } else {
            m.triangles.push_back({b, b + 2, b + 1});
            m.triangles.push_back({b, b + 3, b + 2});
        }
    };
    square(0, 10, 5, true);
    square(5, 15, 8, false);
    const int b = int(m.vertices.size());
    m.vertices.insert(m.vertices.end(), {{1, 1, 6}, {4, 1, 6}, {1, 4, 9}});
    m.triangles.push_back({b, b + 2, b + 1}); // facing down, over the first square
    const Scaffold s = card();
    const Result<Silhouette> r = silhouette_profile(m, s, s.ground);
    ASSERT_TRUE(r.ok);
    EXPECT_EQ(r.value.pieces, 1);
    EXPECT_NEAR(r.value.area, 150, 1e-6);
    EXPECT_TRUE(r.value.profile.holes.empty());
    SilhouetteOptions facing;
    facing.facing_only = true; // only the first square faces up
    EXPECT_NEAR(silhouette_profile(m, s, s.ground, facing).value.area, 100, 1e-6);
}

TEST(Silhouette, AStandingRiserSeesTheModelWhereItStands)
{
    // A step is flat at the design state and stands at 90°: the silhouette is taken with the
    // riser's pose there (from the simulator). The model: a block 20 (along u) × 40 (along v)
    // × 10 (along the normal) built in the posed riser's frame, so its silhouette is 20 × 40;
    // the riser (60 × 20) keeps 20 × 20 of it.
    Scaffold s = card();
    StepFoldParams p;
    p.offset = 60;
    p.width = 60;
    p.run_ground = 30;
    p.run_backdrop = 20;
    const Result<MechanismParts> step = add_step_fold(s, central_fold(s), p, "Step");
    ASSERT_TRUE(step.ok);
    const int riser = step.value.patches[0];
    const Result<FoldSweep> sweep = simulate_fold(s, {kPi / 2});
    ASSERT_TRUE(sweep.ok && sweep.value.complete);
    const Pose pose = sweep.value.states[0].poses[s.patch_index(riser)];
    const ProfileFrame f = profile_frame(s, riser).value;
    const Vec3 o = pose.apply(f.origin), u = pose.rotation * f.u, v = pose.rotation * f.v,
               n = pose.rotation * f.normal;
    ModelMesh block;
    const int base = 0;
    for (int k = 0; k < 8; ++k)
        block.vertices.push_back(o + (k & 1 ? 10.0 : -10.0) * u + (k & 2 ? 40.0 : 0.0) * v +
                                 (k & 4 ? 5.0 : -5.0) * n);
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        block.triangles.push_back({base + q[0], base + q[1], base + q[2]});
        block.triangles.push_back({base + q[0], base + q[2], base + q[3]});
    }
    SilhouetteOptions standing;
    standing.pose = pose;
    const Result<Silhouette> r = silhouette_profile(block, s, riser, standing);
    ASSERT_TRUE(r.ok);
    EXPECT_NEAR(r.value.area, 20 * 40, 1e-4);
    const Result<ProfileApplied> applied = apply_profile(s, riser, r.value.profile);
    ASSERT_TRUE(applied.ok) << applied.diagnostics.front().message;
    EXPECT_NEAR(applied.value.area_after, 20 * 20, 1e-4);
    // At the design state the riser lies flat: the same block seen along z is another shape.
    const Result<Silhouette> flat = silhouette_profile(block, card_with_step(), riser);
    EXPECT_GT(std::abs(flat.value.area - 20 * 40), 1.0);
}

TEST(SilhouetteCache, AParallelPartGetsTheSilhouetteItWouldProject)
{
    // The open card's ground and backdrop lie in one plane with different frames (each u along
    // the fold, v onto its own page): the silhouette projected once on the ground and carried
    // into the backdrop's frame is the backdrop's own, point for point to a nanometre, and the
    // ground's is silhouette_profile's exactly.
    ModelMesh m;
    add_wheel(m, 20, 90, 15, 0, 10, 24);
    add_box(m, {-30, 60, 0}, {10, 130, 25});
    const Scaffold s = card();
    SilhouetteCache cache(m);
    for (int patch : {0, 1}) {
        const Result<Silhouette> direct = silhouette_profile(m, s, patch);
        const Result<Silhouette> cached = cache.seen_in(profile_frame(s, patch).value, "page");
        ASSERT_TRUE(direct.ok);
        ASSERT_TRUE(cached.ok);
        EXPECT_NEAR(cached.value.area, direct.value.area, 1e-9);
        const Loop2 &a = cached.value.profile.outer, &b = direct.value.profile.outer;
        ASSERT_EQ(a.size(), b.size()) << patch;
        for (const Vec2& q : a) {
            double nearest = 1e9;
            for (const Vec2& r : b)
                nearest = std::min(nearest, (q - r).norm());
            EXPECT_LT(nearest, 2e-6) << patch;
        }
    }
}
