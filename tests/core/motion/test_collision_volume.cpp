// The separating-axis test against a brute-force intersection test that shares nothing with it:
// two convex boxes meet iff a corner of one lies in the other or an edge of one crosses the other
// (Liang–Barsky clipping of the edge against the other box's slabs).
#include <gtest/gtest.h>

#include <random>

#include "motion/collision_volume.hpp"

namespace popup::motion {
namespace {

OrientedBox random_box(std::mt19937_64& rng)
{
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    OrientedBox b;
    b.centre = Vec3(u(rng), u(rng), u(rng)) * 3.0;
    b.half = Vec3(0.2 + std::abs(u(rng)), 0.2 + std::abs(u(rng)), 0.2 + std::abs(u(rng))) * 1.5;
    const Vec3 axis = Vec3(u(rng), u(rng), u(rng)).normalized();
    b.axes = Eigen::AngleAxisd(M_PI * u(rng), axis).toRotationMatrix();
    return b;
}

bool inside(const OrientedBox& b, const Vec3& x)
{
    const Vec3 local = b.axes.transpose() * (x - b.centre);
    return (local.cwiseAbs() - b.half).maxCoeff() <= 0;
}

bool segment_meets(const OrientedBox& b, const Vec3& p, const Vec3& q)
{
    const Vec3 a = b.axes.transpose() * (p - b.centre), d = b.axes.transpose() * (q - p);
    double t0 = 0, t1 = 1;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(d[i]) < 1e-15) {
            if (std::abs(a[i]) > b.half[i])
                return false;
            continue;
        }
        double ta = (-b.half[i] - a[i]) / d[i], tb = (b.half[i] - a[i]) / d[i];
        if (ta > tb)
            std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1)
            return false;
    }
    return true;
}

bool brute_force_meet(const OrientedBox& a, const OrientedBox& b)
{
    const auto ca = a.corners(), cb = b.corners();
    for (const Vec3& x : ca)
        if (inside(b, x))
            return true;
    for (const Vec3& x : cb)
        if (inside(a, x))
            return true;
    // Edges: corners k and k ^ (1 << axis).
    for (int k = 0; k < 8; ++k)
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (k & bit)
                continue;
            if (segment_meets(b, ca[k], ca[k | bit]) || segment_meets(a, cb[k], cb[k | bit]))
                return true;
        }
    return false;
}

TEST(CollisionVolume, SeparatingAxesAgreeWithBruteForceOnRandomBoxPairs)
{
    std::mt19937_64 rng(42);
    int meeting = 0, apart = 0;
    for (int trial = 0; trial < 5000; ++trial) {
        const OrientedBox a = random_box(rng), b = random_box(rng);
        const bool sat = overlap_depth(a, b) > 0;
        const bool brute = brute_force_meet(a, b);
        ASSERT_EQ(sat, brute) << "trial " << trial;
        (brute ? meeting : apart)++;
    }
    EXPECT_GT(meeting, 500); // both verdicts well represented
    EXPECT_GT(apart, 500);
}

TEST(CollisionVolume, DepthOfTwoAxisAlignedBoxesIsTheirSmallestOverlap)
{
    OrientedBox a, b;
    a.half = Vec3(2, 3, 4);
    b.half = Vec3(1, 1, 1);
    b.centre = Vec3(2.5, 0, 0); // x overlap: 2 + 1 − 2.5 = 0.5; y: 4, z: 5
    EXPECT_NEAR(overlap_depth(a, b), 0.5, 1e-12);
    b.centre = Vec3(2.5, 3.8, 0); // y overlap 0.2
    EXPECT_NEAR(overlap_depth(a, b), 0.2, 1e-12);
    b.centre = Vec3(3.5, 0, 0); // touching faces: separate
    EXPECT_EQ(overlap_depth(a, b), 0.0);
}

} // namespace
} // namespace popup::motion
