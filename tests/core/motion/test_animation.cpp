// check_animation, forward_kinematics and posed_mesh against hand-derived poses.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "popup/motion/animation.hpp"

using namespace popup;

namespace {

Eigen::Isometry3d rigid(const Vec3& t, double angle_z = 0.0)
{
    Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
    m.linear() = Eigen::AngleAxisd(angle_z, Vec3::UnitZ()).toRotationMatrix();
    m.translation() = t;
    return m;
}

constexpr double shoulder_rate = 0.3; // rad per frame
constexpr double elbow_rate = -0.2;
const Vec3 shoulder_at(1.0, 2.0, 3.0);
constexpr double upper = 4.0, fore = 2.5;

/// A two-bone arm in the xy-plane: the shoulder turns about z at 0.3 rad per frame, the elbow at
/// -0.2 rad per frame relative to it; the hand is an end site fore units along the forearm.
Animation arm(int frames)
{
    Animation a;
    a.source = "arm";
    a.bones = {{"shoulder", -1}, {"elbow", 0}, {"hand", 1}};
    for (int f = 0; f < frames; ++f) {
        a.frame_times_s.push_back(f / 30.0);
        a.local.push_back({rigid(shoulder_at, shoulder_rate * f),
                           rigid(Vec3(upper, 0, 0), elbow_rate * f), rigid(Vec3(fore, 0, 0))});
    }
    return a;
}

/// Where the hand is at (possibly fractional) frame f: shoulder + R(a f)(upper x + R(b f) fore x).
Vec3 analytic_hand(double f)
{
    const double a = shoulder_rate * f, b = (shoulder_rate + elbow_rate) * f;
    return shoulder_at + Vec3(upper * std::cos(a) + fore * std::cos(b),
                              upper * std::sin(a) + fore * std::sin(b), 0.0);
}

DiagnosticCode code_of(const Result<Animation>& r)
{
    EXPECT_FALSE(r.ok);
    return r.diagnostics.empty() ? DiagnosticCode::bad_option : r.diagnostics[0].code;
}

} // namespace

TEST(MotionAnimation, ForwardKinematicsOfATwoBoneArmIsAnalytic)
{
    const Animation a = arm(20);
    ASSERT_TRUE(check_animation(a).ok);
    for (double f : {0.0, 1.0, 2.5, 7.25, 13.9, 19.0}) {
        const auto global = forward_kinematics(a, f);
        EXPECT_LT((global[2].translation() - analytic_hand(f)).norm(), 1e-9) << "frame " << f;
        const double a_f = shoulder_rate * f;
        EXPECT_LT((global[1].translation() -
                   (shoulder_at + upper * Vec3(std::cos(a_f), std::sin(a_f), 0)))
                      .norm(),
                  1e-9);
    }
    // Outside the range the ends hold.
    EXPECT_LT((forward_kinematics(a, 40.0)[2].translation() - analytic_hand(19.0)).norm(), 1e-9);
    EXPECT_LT((forward_kinematics(a, -3.0)[2].translation() - analytic_hand(0.0)).norm(), 1e-9);
}

TEST(MotionAnimation, PosedMeshBlendsItsBonesLinearly)
{
    Animation a = arm(10);
    // Three vertices bound at frame 0's pose: on the upper arm, on the forearm, half and half.
    const auto bind = forward_kinematics(a, 0.0);
    for (size_t b = 0; b < bind.size(); ++b)
        a.bind_inverse.push_back(bind[b].inverse());
    a.mesh.vertices = {shoulder_at + Vec3(2, 0.5, 0), shoulder_at + Vec3(5, -0.5, 1),
                       shoulder_at + Vec3(4, 1, 0)};
    a.mesh.triangles = {{0, 1, 2}};
    a.skin = {{{0, 1.0}}, {{1, 1.0}}, {{0, 0.5}, {1, 0.5}}};
    ASSERT_TRUE(check_animation(a).ok);
    const double f = 6.5;
    const double s = shoulder_rate * f, e = (shoulder_rate + elbow_rate) * f;
    auto rot = [](double t, const Vec3& p) {
        return Vec3(std::cos(t) * p.x() - std::sin(t) * p.y(),
                    std::sin(t) * p.x() + std::cos(t) * p.y(), p.z());
    };
    // Upper arm: rotate about the shoulder by s. Forearm: elbow at R(s) upper x, then R(e)
    // about it of the offset from the bind elbow (upper, 0).
    const Vec3 elbow = shoulder_at + rot(s, Vec3(upper, 0, 0));
    const Vec3 v0 = shoulder_at + rot(s, Vec3(2, 0.5, 0));
    const Vec3 v1 = elbow + rot(e, Vec3(1, -0.5, 1));
    const Vec3 v2 =
        0.5 * (shoulder_at + rot(s, Vec3(4, 1, 0))) + 0.5 * (elbow + rot(e, Vec3(0, 1, 0)));
    const ModelMesh posed = posed_mesh(a, f);
    EXPECT_LT((posed.vertices[0] - v0).norm(), 1e-9);
    EXPECT_LT((posed.vertices[1] - v1).norm(), 1e-9);
    EXPECT_LT((posed.vertices[2] - v2).norm(), 1e-9);
}

TEST(MotionAnimation, CheckNamesEachBadAnimation)
{
    Animation cycle = arm(5);
    cycle.bones[0].parent = 2; // shoulder <- hand <- elbow <- shoulder
    const auto r = check_animation(cycle);
    EXPECT_EQ(code_of(r), DiagnosticCode::skeleton_cycle);
    EXPECT_NE(r.diagnostics[0].message.find("shoulder"), std::string::npos);
    EXPECT_NE(r.diagnostics[0].message.find("elbow"), std::string::npos);
    EXPECT_NE(r.diagnostics[0].message.find("hand"), std::string::npos);

    EXPECT_EQ(code_of(check_animation(arm(1))), DiagnosticCode::single_frame);
    EXPECT_EQ(code_of(check_animation(arm(0))), DiagnosticCode::no_animation);

    Animation nan = arm(5);
    nan.local[3][1].translation().y() = std::numeric_limits<double>::quiet_NaN();
    const auto rn = check_animation(nan);
    EXPECT_EQ(code_of(rn), DiagnosticCode::non_finite_animation);
    EXPECT_NE(rn.diagnostics[0].message.find("elbow at frame 3"), std::string::npos);

    Animation order = arm(5);
    order.bones[1].parent = 2;
    order.bones[2].parent = 0;
    EXPECT_EQ(code_of(check_animation(order)), DiagnosticCode::bad_animation);

    Animation out_of_range = arm(5);
    out_of_range.bones[2].parent = 7;
    EXPECT_EQ(code_of(check_animation(out_of_range)), DiagnosticCode::bad_animation);

    Animation times = arm(5);
    times.frame_times_s[3] = times.frame_times_s[2];
    EXPECT_EQ(code_of(check_animation(times)), DiagnosticCode::bad_animation);

    Animation scaled = arm(5);
    scaled.local[2][0].linear() *= 2.0;
    EXPECT_EQ(code_of(check_animation(scaled)), DiagnosticCode::bad_animation);

    // A root that jumps 1e30 units in one frame: the joints' extent is absurd (1e-6..1e6).
    Animation jump = arm(5);
    jump.local[2][0].translation().x() = 1e30;
    const auto rj = check_animation(jump);
    EXPECT_EQ(code_of(rj), DiagnosticCode::bad_animation);
    EXPECT_NE(rj.diagnostics[0].message.find("1e+30"), std::string::npos)
        << rj.diagnostics[0].message;
    EXPECT_NE(rj.diagnostics[0].message.find("1e-6..1e6"), std::string::npos);
    Animation tiny = arm(5);
    for (auto& frame : tiny.local)
        for (auto& t : frame)
            t.translation() *= 1e-9;
    EXPECT_EQ(code_of(check_animation(tiny)), DiagnosticCode::bad_animation);

    Animation none;
    none.source = "empty";
    EXPECT_EQ(code_of(check_animation(none)), DiagnosticCode::bad_animation);

    Animation weights = arm(5);
    weights.mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    weights.mesh.triangles = {{0, 1, 2}};
    weights.skin = {{{0, 1.0}}, {{1, 0.7}}, {{2, 1.0}}};
    EXPECT_EQ(code_of(check_animation(weights)), DiagnosticCode::bad_animation);
    weights.skin[1] = {{1, std::numeric_limits<double>::infinity()}};
    EXPECT_EQ(code_of(check_animation(weights)), DiagnosticCode::non_finite_animation);
    weights.skin[1] = {{1, 1.0}};
    EXPECT_TRUE(check_animation(weights).ok);
}
