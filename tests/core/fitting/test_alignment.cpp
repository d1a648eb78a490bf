#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "fitting/synthetic_models.hpp"
#include "popup/fitting/alignment.hpp"
#include "popup/fitting/surface_samples.hpp"

using namespace popup;
using namespace popup::testing;

namespace {

Vec3 up_of(const ModelMesh& model)
{
    const auto a =
        align_model(model, sample_surface(model, 4000, 1), std::nullopt, std::nullopt, CardRoom{});
    EXPECT_TRUE(a.ok);
    return a.value.up;
}

/// A turn that is no multiple of 90° about any axis.
Mat3 some_turn()
{
    return (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()) *
            Eigen::AngleAxisd(-0.4, Vec3(0, 1, 0)))
        .toRotationMatrix();
}

} // namespace

// The house of tools/make_models.py: a body 40 deep and 30 high, a roof 20 high over it, 60 long.
// Its walls and roof face sideways more than its floor faces down, so the first NPCA axis is
// horizontal; it stands on its floor (2400 of flat bottom against 1800 for a wall).
TEST(FitAlignment, HouseStandsOnItsFloorNotOnItsRoofOrAWall)
{
    const ModelMesh house =
        extrude_section({{-20, 0}, {20, 0}, {20, 30}, {0, 50}, {-20, 30}}, 0, 60);
    Vec3 eigen;
    const Mat3 axes = normal_principal_axes(house, &eigen);
    EXPECT_LT(std::abs(axes.col(0).z()), 0.5); // why the largest eigenvalue alone fails
    EXPECT_GT(up_of(house).z(), 0.999);
    const Mat3 turn = some_turn();
    EXPECT_GT(up_of(moved(house, turn, 2.5, Vec3(3, -4, 5))).dot(turn * Vec3::UnitZ()), 0.999);
}

// An upright cylinder 60 high of radius 10: its side faces every horizontal way, so NPCA's
// first axis is horizontal; it stands on a cap (314 of flat bottom against one 2.6-wide facet).
TEST(FitAlignment, UprightCylinderStandsOnItsCap)
{
    const ModelMesh cylinder = cylinder_mesh({0, 0, 0}, {0, 0, 60}, 10, 24);
    EXPECT_GT(std::abs(up_of(cylinder).z()), 0.999);
    const Mat3 turn = some_turn();
    EXPECT_GT(std::abs(up_of(moved(cylinder, turn, 1, Vec3::Zero())).dot(turn * Vec3::UnitZ())),
              0.999);
}

// A box stands on its largest face (ties between its two ends go to the skew, either is right).
TEST(FitAlignment, BoxStandsOnItsLargestFace)
{
    const ModelMesh box = box_mesh({0, 0, 0}, {30, 80, 50}); // largest faces across x
    EXPECT_GT(std::abs(up_of(box).x()), 0.999);
}
