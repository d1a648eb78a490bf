// adaptive_samples and motion_targets against paths whose samples and projection are derived by
// hand (docs/MATH.md, Motion targets).
#include <cmath>

#include <gtest/gtest.h>

#include "popup/motion/adaptive_samples.hpp"
#include "popup/motion/motion_targets.hpp"

using namespace popup;

namespace {

constexpr double radius = 2.0;
constexpr int frames = 21;

Eigen::Isometry3d rigid(const Vec3& t, double angle_z = 0.0)
{
    Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
    m.linear() = Eigen::AngleAxisd(angle_z, Vec3::UnitZ()).toRotationMatrix();
    m.translation() = t;
    return m;
}

/// A hub at the origin turning about z by π over the 21 frames, carrying an arm tip at
/// (radius, 0, 0) and a still post at (0, 0, 5) (on the axis): chains [hub], [tip], [post].
Animation turning_arm()
{
    Animation a;
    a.source = "turning arm";
    a.bones = {{"hub", -1}, {"tip", 0}, {"post", 0}};
    for (int f = 0; f < frames; ++f) {
        a.frame_times_s.push_back(f / 24.0);
        a.local.push_back({rigid(Vec3::Zero(), M_PI * f / (frames - 1)), rigid(Vec3(radius, 0, 0)),
                           rigid(Vec3(0, 0, 5))});
    }
    a.bind_inverse.assign(3, Eigen::Isometry3d::Identity());
    return a;
}

} // namespace

TEST(MotionSampling, AStraightPathKeepsOnlyItsEnds)
{
    const auto uniform = adaptive_samples([](double s) { return Vec2(2 + 3 * s, 1 - s); }, 2.0);
    EXPECT_EQ(uniform, (std::vector<double>{0.0, 1.0}));
    // Speed changes along the line do not matter: only turning does.
    const auto eased =
        adaptive_samples([](double s) { return Vec2(2 + 3 * s * s * s, 1 - s * s * s); }, 2.0);
    EXPECT_EQ(eased, (std::vector<double>{0.0, 1.0}));
    // Started from 8 equal intervals (MotionView's default), the line keeps s = k/8: eq 6.6 then
    // sees a mechanism that keeps the line but not the pace.
    const auto paced = adaptive_samples(
        [](double s) { return Vec2(2 + 3 * s * s * s, 1 - s * s * s); }, 2.0, 1e-9, 16, 8);
    ASSERT_EQ(paced.size(), 9u);
    for (int k = 0; k <= 8; ++k)
        EXPECT_DOUBLE_EQ(paced[k], k / 8.0);
}

TEST(MotionSampling, ACircleIsSampledWithinTheTurningBound)
{
    // A uniform circle: an interval spanning φ turns by φ/2 at its middle (the largest of its
    // tested turns), so it is split while φ > 2τ: the final intervals have τ < φ <= 2τ (their
    // parents had 2φ > 2τ). A full turn with τ = 2°: 360/2^k <= 4 first at k = 7, 128 pieces.
    const double tau = 2.0;
    const auto s = adaptive_samples(
        [](double s) { return Vec2(5 * std::cos(2 * M_PI * s), 5 * std::sin(2 * M_PI * s)); }, tau);
    ASSERT_EQ(s.size(), 129u);
    for (size_t i = 1; i < s.size(); ++i) {
        const double phi = 360.0 * (s[i] - s[i - 1]);
        EXPECT_LE(phi, 2 * tau + 1e-12);
        EXPECT_GT(phi, tau);
    }
    // A circle run at varying speed still ends with every piece turning at most 2τ.
    const auto varying = adaptive_samples(
        [](double s) {
            const double t = 2 * M_PI * s * s;
            return Vec2(std::cos(t), std::sin(t));
        },
        tau);
    for (size_t i = 1; i < varying.size(); ++i) {
        const double phi = 360.0 * (varying[i] * varying[i] - varying[i - 1] * varying[i - 1]);
        EXPECT_LE(phi, 2 * tau + 1e-12)
            << "between s = " << varying[i - 1] << " and " << varying[i];
    }
}

TEST(MotionTargets, ProjectsAndPlacesTheDefaultFit)
{
    const Animation a = turning_arm();
    MotionView view; // looking down -z, y up: card (x, y) = file (x, y) before placement
    const auto r = motion_targets(a, view);
    ASSERT_TRUE(r.ok) << r.diagnostics[0].message;
    const MotionTargets& t = r.value;
    // Extent over the frames: x in [-2, 2], y in [0, 2] (frame 10 is the quarter turn).
    // Room: x 2·148·0.8 = 236.8, y 210·0.8 = 168; scale = min(236.8/4, 168/2) = 59.2.
    const double scale = 59.2;
    const Vec2 box_centre(0.0, 1.0), centre(0.0, 105.0);
    EXPECT_NEAR(t.animation_to_card(0, 0), scale, 1e-9);
    EXPECT_NEAR(t.diagonal_mm, scale * std::sqrt(20.0), 1e-9);
    ASSERT_EQ(t.chains.size(), 3u);
    EXPECT_EQ(t.chains[1].name, "tip");
    const ChainPath& tip = t.paths[1];
    // Half a turn: 180/2^k <= 4 first at k = 6, so 65 samples.
    ASSERT_EQ(tip.s.size(), 65u);
    for (size_t i = 0; i < tip.s.size(); ++i) {
        const double angle = M_PI * tip.s[i];
        const Vec2 expected =
            scale * (radius * Vec2(std::cos(angle), std::sin(angle)) - box_centre) + centre;
        EXPECT_LT((tip.effector[i] - expected).norm(), 1e-9) << "s = " << tip.s[i];
        EXPECT_LT((tip.root[i] - (centre - scale * box_centre)).norm(), 1e-9);
    }
    // The still post: no turn, so only the 8 equal starting intervals (MotionView.min_intervals).
    // Depth: post at z = 5 nearest (1), the others at z = 0 deepest (0).
    EXPECT_EQ(t.paths[2].s.size(), 9u);
    EXPECT_NEAR(t.paths[2].depth, 1.0, 1e-12);
    EXPECT_NEAR(t.paths[1].depth, 0.0, 1e-12);
    EXPECT_NEAR(t.paths[0].depth, 0.0, 1e-12);
}

TEST(MotionTargets, CaptureJitterUnderTheStillFloorAddsNoSamples)
{
    // A hand on a half circle of radius 50 over 8001 frames (0.0196 of arc per frame), shaken
    // along its radius by ±0.1 from frame to frame (like a motion capture's noise; the
    // diagonal is 141.4, the still floor 3e-4 of it = 0.0424). The circle alone needs 65
    // samples; the jitter's kinks turn by more than 2° at every scale down to the frames, but
    // an interval of k frames has quarter pieces of about k·0.0196/4, still under k = 8.65:
    // splitting ends at intervals of 4.3..8.65 frames, 925..1860 samples (about 7500 with a
    // floor of 1e-9: split down to the frames).
    Animation a;
    a.source = "jittery arc";
    a.bones = {{"body", -1}, {"hand", 0}};
    const int n = 8001;
    for (int f = 0; f < n; ++f) {
        const double angle = M_PI * f / (n - 1), r = 50.0 + (f % 2 == 0 ? 0.1 : -0.1);
        a.frame_times_s.push_back(f / 120.0);
        a.local.push_back(
            {rigid(Vec3::Zero()), rigid(Vec3(r * std::cos(angle), r * std::sin(angle), 0))});
    }
    a.bind_inverse.assign(2, Eigen::Isometry3d::Identity());
    MotionView view;
    view.scale = 1.0;
    view.centre = Vec2(0, 100);
    const auto r = motion_targets(a, view);
    ASSERT_TRUE(r.ok) << r.diagnostics[0].message;
    ASSERT_EQ(r.value.paths.size(), 1u);
    const std::size_t samples = r.value.paths[0].s.size();
    EXPECT_LE(samples, 1860u);
    EXPECT_GE(samples, 925u);
}

TEST(MotionTargets, ViewScaleCentreAndFrameRange)
{
    const Animation a = turning_arm();
    MotionView view;
    view.view = Vec3(0, 0, 1); // from behind: the file's +x becomes the card's -x
    view.scale = 10.0;
    view.centre = Vec2(20.0, 50.0);
    view.first_frame = 5;
    view.last_frame = 15;
    const auto r = motion_targets(a, view);
    ASSERT_TRUE(r.ok) << r.diagnostics[0].message;
    const MotionTargets& t = r.value;
    EXPECT_EQ(t.first_frame, 5);
    EXPECT_EQ(t.last_frame, 15);
    // Frames 5..15 turn π/4..3π/4: tip x in [-√2, √2], y in [√2, 2], hub at the origin: box
    // x [-√2, √2], y [0, 2], centre (0, 1); card x = -file x.
    const ChainPath& tip = t.paths[1];
    for (size_t i = 0; i < tip.s.size(); ++i) {
        const double angle = M_PI * (5 + 10 * tip.s[i]) / 20.0;
        const Vec2 file(radius * std::cos(angle), radius * std::sin(angle));
        const Vec2 expected = 10.0 * (Vec2(-file.x(), file.y()) - Vec2(0, 1)) + Vec2(20, 50);
        EXPECT_LT((tip.effector[i] - expected).norm(), 1e-9);
    }
    // A quarter turn: 90/2^k <= 4 first at k = 5: 33 samples.
    EXPECT_EQ(tip.s.size(), 33u);
    // Viewed from behind, the post (file z = 5) is the deepest.
    EXPECT_NEAR(t.paths[2].depth, 0.0, 1e-12);
}

TEST(MotionTargets, BadOptionsAreNamed)
{
    const Animation a = turning_arm();
    auto option_of = [&](const MotionView& v) {
        const auto r = motion_targets(a, v);
        EXPECT_FALSE(r.ok);
        return r.ok ? std::string() : *r.diagnostics[0].parameter;
    };
    MotionView v;
    v.view = Vec3::Zero();
    EXPECT_EQ(option_of(v), "view");
    v = MotionView();
    v.up = Vec3(0, 0, 2);
    EXPECT_EQ(option_of(v), "up");
    v = MotionView();
    v.last_frame = 21;
    EXPECT_EQ(option_of(v), "last_frame");
    v = MotionView();
    v.first_frame = 20;
    EXPECT_EQ(option_of(v), "last_frame");
    v = MotionView();
    v.first_frame = -1;
    EXPECT_EQ(option_of(v), "first_frame");
    v = MotionView();
    v.margin = 0.5;
    EXPECT_EQ(option_of(v), "margin");
    v = MotionView();
    v.scale = 0.0;
    EXPECT_EQ(option_of(v), "scale");
    v = MotionView();
    v.angle_tolerance = 0.0;
    EXPECT_EQ(option_of(v), "angle_tolerance");
}

namespace {

/// A walker: hips travelling 10 along x (the ground, up = y) over the 21 frames, an arm tip at
/// (1, 1, 0) and a foot at (0, -1, 0) from them, neither moving against the hips.
Animation walker(bool lone = false)
{
    Animation a;
    a.source = "walker";
    a.bones = {{"hips", -1}};
    if (!lone)
        a.bones.insert(a.bones.end(), {{"arm", 0}, {"foot", 0}});
    for (int f = 0; f < frames; ++f) {
        a.frame_times_s.push_back(f / 24.0);
        std::vector<Eigen::Isometry3d> pose = {rigid(Vec3(0.5 * f, 0, 0))};
        if (!lone)
            pose.insert(pose.end(), {rigid(Vec3(1, 1, 0)), rigid(Vec3(0, -1, 0))});
        a.local.push_back(pose);
    }
    a.bind_inverse.assign(a.bones.size(), Eigen::Isometry3d::Identity());
    return a;
}

} // namespace

TEST(MotionTargets, AWalkStaysOnTheCardAsItsLastFrame)
{
    // In place, every frame is the last: x in [10, 11], y in [-1, 1]; scale min(236.8 / 1,
    // 168 / 2) = 84; the foot at 84 · ((10, -1) − (10.5, 0)) + (0, 105) = (−42, 21) throughout.
    const auto r = motion_targets(walker(), MotionView{});
    ASSERT_TRUE(r.ok) << r.diagnostics[0].message;
    EXPECT_NEAR(r.value.animation_to_card(0, 0), 84.0, 1e-9);
    EXPECT_NEAR(r.value.travel_removed_mm, 840.0, 1e-9);
    ASSERT_EQ(r.value.chains.size(), 3u);
    for (const Vec2& p : r.value.paths[2].effector)
        EXPECT_LT((p - Vec2(-42.0, 21.0)).norm(), 1e-9);

    // Kept: x in [0, 11], scale 236.8 / 11; the foot crosses 10 of it.
    MotionView keep;
    keep.keep_travel = true;
    const auto kept = motion_targets(walker(), keep);
    ASSERT_TRUE(kept.ok);
    const double scale = 236.8 / 11.0;
    EXPECT_NEAR(kept.value.animation_to_card(0, 0), scale, 1e-9);
    EXPECT_EQ(kept.value.travel_removed_mm, 0.0);
    const auto& foot = kept.value.paths[2].effector;
    EXPECT_NEAR(foot.back().x() - foot.front().x(), 10.0 * scale, 1e-9);

    // A lone chain's travel is its motion: kept.
    const auto lone = motion_targets(walker(true), MotionView{});
    ASSERT_TRUE(lone.ok);
    EXPECT_EQ(lone.value.travel_removed_mm, 0.0);
    EXPECT_GT(lone.value.paths[0].effector.back().x() - lone.value.paths[0].effector.front().x(),
              100.0);
}

namespace {

/// The walker under a still armature node far from it (30 back along x, as glTF and FBX exports
/// put one above the hips): the node's bone 0, the walker's bones below it, skinned (as such
/// exports are) by one vertex at each of the walker's joints, inside the joints' own box.
Animation walker_under_a_node()
{
    Animation a = walker();
    a.source = "walker under a node";
    a.bones.insert(a.bones.begin(), {"Armature", -1});
    for (std::size_t b = 1; b < a.bones.size(); ++b)
        a.bones[b].parent += 1;
    for (std::vector<Eigen::Isometry3d>& pose : a.local)
        pose.insert(pose.begin(), rigid(Vec3(-30, 0, 0)));
    for (std::vector<Eigen::Isometry3d>& pose : a.local)
        pose[1].translation() += Vec3(30, 0, 0); // the hips where the walker's are
    a.bind_inverse.assign(a.bones.size(), Eigen::Isometry3d::Identity());
    for (int bone = 1; bone <= 3; ++bone) {
        a.mesh.vertices.push_back(Vec3::Zero()); // at the bone's origin in every pose
        a.skin.push_back({{bone, 1.0}});
    }
    a.mesh.triangles.push_back({0, 1, 2});
    return a;
}

} // namespace

TEST(MotionTargets, TheHipsTravelNotTheStillNodeAboveThem)
{
    // The same figures as the walker alone (AWalkStaysOnTheCardAsItsLastFrame): the node neither
    // travels nor counts in the character's extent.
    const Animation a = walker_under_a_node();
    const auto r = motion_targets(a, MotionView{});
    ASSERT_TRUE(r.ok) << r.diagnostics[0].message;
    EXPECT_NEAR(r.value.animation_to_card(0, 0), 84.0, 1e-9);
    EXPECT_NEAR(r.value.travel_removed_mm, 840.0, 1e-9);
    for (const Vec2& p : r.value.paths[2].effector)
        EXPECT_LT((p - Vec2(-42.0, 21.0)).norm(), 1e-9);
    // From the last frame (20) back to the first, the hips went back 10 along the ground.
    EXPECT_LT((ground_travel(a, Vec3::UnitY(), 20, 0.0) - Vec3(-10, 0, 0)).norm(), 1e-12);
}

namespace {

/// A hub with two arms of length 1 (on x and on y), swinging together ±60° about z as
/// 60° · sin(2π t / 40) over 81 frames: two full swings back and forth.
Animation swinging()
{
    Animation a;
    a.source = "swinging";
    a.bones = {{"hub", -1}, {"shoulder", 0}, {"arm", 1}, {"other", 1}};
    for (int f = 0; f < 81; ++f) {
        a.frame_times_s.push_back(f / 40.0);
        const double angle = M_PI / 3.0 * std::sin(2.0 * M_PI * f / 40.0);
        a.local.push_back({rigid(Vec3::Zero()), rigid(Vec3::Zero(), angle), rigid(Vec3(1, 0, 0)),
                           rigid(Vec3(0, 1, 0))});
    }
    a.bind_inverse.assign(4, Eigen::Isometry3d::Identity());
    return a;
}

} // namespace

TEST(MotionTargets, TheFrameWindowIsOneStrokeOfASwing)
{
    // The stroke from −60° (frame 30) to +60° (frame 50) is the longest chord with no retreat:
    // each arm's chord is 2 sin 60° = √3; the whole take's chord is 0 with a retreat of √3.
    const Animation a = swinging();
    MotionView view;
    const auto r = motion_targets(a, view);
    ASSERT_TRUE(r.ok) << r.diagnostics[0].message;
    const MotionTargets& t = r.value;
    EXPECT_TRUE(t.window.chosen);
    EXPECT_NEAR(std::abs(t.last_frame - t.first_frame), 20, 1);
    EXPECT_NEAR(std::fmod(double(t.first_frame), 20.0), 10.0, 1.0); // starts at an extreme
    EXPECT_NEAR(t.window.score, std::sqrt(3.0), 0.02); // the two arms' weights sum to 1
    EXPECT_LT(t.window.whole_score, 0.0);
    // Named frames are shown as named.
    view.auto_frames = false;
    const auto whole = motion_targets(a, view);
    ASSERT_TRUE(whole.ok);
    EXPECT_FALSE(whole.value.window.chosen);
    EXPECT_EQ(whole.value.first_frame, 0);
    EXPECT_EQ(whole.value.last_frame, 80);
}
