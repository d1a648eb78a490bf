// The rules a candidate prism meets before the RANSAC may accept it (prism_acceptance): here, a
// prism grown along its hinge stops at the accepted boxes it reached.
#include <gtest/gtest.h>

#include "fitting/prism_acceptance.hpp"

using namespace popup;
using namespace popup::prism_search;

namespace {

PrismHost central_fold()
{
    PrismHost h;
    h.name = "central fold";
    h.length = 200;
    h.across_min = -100;
    h.across_max = 100;
    return h; // origin 0, axis +y, across +x, up +z
}

Prism box(double a0, double a1, double d, double height)
{
    Prism m;
    m.a0 = a0;
    m.a1 = a1;
    m.s0 = -d;
    m.s1 = d;
    m.height = height;
    return m;
}

} // namespace

TEST(PrismAcceptance, GrowthStopsAtAnAcceptedBoxOnEitherSide)
{
    const PrismHost h = central_fold();
    // Accepted: a tall box at y 40..60 and another at y 120..150.
    const std::vector<Eigen::AlignedBox3d> taken{
        Eigen::AlignedBox3d(Vec3(-20, 40, 0), Vec3(20, 60, 30)),
        Eigen::AlignedBox3d(Vec3(-20, 120, 0), Vec3(20, 150, 30))};
    // Drawn on y 70..100, grown to 10..190 over the same top and sides.
    Prism m = box(10, 190, 30, 10);
    stop_at_taken(m, h, taken, 70, 100, 0.5);
    EXPECT_DOUBLE_EQ(m.a0, 60);
    EXPECT_DOUBLE_EQ(m.a1, 120);
    EXPECT_FALSE(overlaps(m, h, taken, 0.5));
}

TEST(PrismAcceptance, AnOverlapAcrossTheDrawnStretchIsLeftToTheOverlapTest)
{
    const PrismHost h = central_fold();
    const std::vector<Eigen::AlignedBox3d> taken{
        Eigen::AlignedBox3d(Vec3(-20, 40, 0), Vec3(20, 80, 30))};
    // Drawn on 60..100: the accepted box lies across the drawn samples, not beyond them.
    Prism m = box(50, 110, 30, 10);
    stop_at_taken(m, h, taken, 60, 100, 0.5);
    EXPECT_DOUBLE_EQ(m.a0, 50);
    EXPECT_DOUBLE_EQ(m.a1, 110);
    EXPECT_TRUE(overlaps(m, h, taken, 0.5));
    // Boxes it only touches (within ε) leave it as it is.
    Prism touching = box(80, 110, 30, 10);
    stop_at_taken(touching, h, taken, 90, 100, 0.5);
    EXPECT_DOUBLE_EQ(touching.a0, 80);
}
