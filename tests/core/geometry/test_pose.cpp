#include <gtest/gtest.h>

#include "popup/geometry/pose.hpp"
#include "test_support.hpp"

using namespace popup;

TEST(Pose, ExpAndLogAreInverse)
{
    const Vec3 w(0.3, -1.2, 0.7);
    EXPECT_LT((rotation_log(rotation_exp(w)) - w).norm(), 1e-14);
    const Mat3 r = rotation_exp(w);
    EXPECT_LT((r * r.transpose() - Mat3::Identity()).norm(), 1e-15);
}

TEST(Pose, AxisAngleTurnsAboutTheAxis)
{
    const Mat3 r = axis_angle(Vec3::UnitY(), fixtures::deg(90));
    EXPECT_LT((r * Vec3::UnitX() - Vec3(0, 0, -1)).norm(), 1e-15);
}

TEST(Pose, BasePatchesCloseOntoThePagePlane)
{
    const Scaffold card = fixtures::make_card();
    const Vec3 ground_edge(140, 0, 0), backdrop_edge(-140, 0, 0);
    EXPECT_LT((ground_pose(card, 0).apply(ground_edge) - Vec3(0, 0, 140)).norm(), 1e-12);
    EXPECT_LT((backdrop_pose(card, 0).apply(backdrop_edge) - Vec3(0, 0, 140)).norm(), 1e-12);
    const double h = std::sqrt(0.5) * 140;
    EXPECT_LT((ground_pose(card, fixtures::deg(90)).apply(ground_edge) - Vec3(h, 0, h)).norm(),
              1e-12);
}
