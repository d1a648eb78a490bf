// Where a fold may stand (model_walls): a model's inner walls, and the middles of its blocks
// off the model's own middle (an L of a tall tower and a low wing).
#include <gtest/gtest.h>

#include "fitting/model_walls.hpp"
#include "fitting/outer_surface.hpp"
#include "fitting/synthetic_models.hpp"

using namespace popup;
using namespace popup::testing;

namespace {

/// A row of a long low block (x 0..20, two boxes along y 0..40) and a tower (x 20..30) behind it,
/// and a wing behind the tower (x 30..60, y 28..40), each a closed box; touching, as an export of
/// separate solids is, so the faces between them are in the mesh too.
ModelMesh blocks()
{
    return join({box_mesh({0, 0, 0}, {20, 28, 8}), box_mesh({0, 28, 0}, {20, 40, 8}),
                 box_mesh({20, 0, 0}, {30, 40, 14}), box_mesh({30, 28, 0}, {60, 40, 5})});
}

} // namespace

TEST(ModelWalls, BlockCentresAreMidwayBetweenAFrontAndABackWall)
{
    const ModelMesh model = blocks();
    const Vec3 x = Vec3::UnitX(), y = Vec3::UnitY();
    // Walls facing -x: x = 0 (the row: 40 x 8 = 320), x = 20 (the tower: 40 x 14 = 560) and
    // x = 30 (the wing: 12 x 5 = 60); facing +x: x = 20 (the row's back, 320), x = 30 (the
    // tower's back, 560), x = 60 (the wing's end, 60). Every pair overlaps along y over half
    // the shorter; (0, 60) → 30 is the model's middle, left out. The rest by the smaller wall:
    // (20, 30) → 25 (560), (0, 20) → 10 and (0, 30) → 15 (320), (20, 60) → 40 and (30, 60) → 45.
    const std::vector<double> centres = block_centres(model, x, y, 1.0, 5);
    const std::vector<double> expected{25, 10, 15, 40, 45};
    ASSERT_EQ(centres.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i)
        EXPECT_NEAR(centres[i], expected[i], 1e-9) << i;
    // A floor of 100 leaves the wing's walls out, and count caps the list.
    EXPECT_EQ(block_centres(model, x, y, 100.0, 5).size(), 3u);
    EXPECT_EQ(block_centres(model, x, y, 1.0, 2).size(), 2u);
}

TEST(ModelWalls, AMirrorSymmetricBoxHasNoBlockOffItsMiddle)
{
    const ModelMesh model = box_mesh({-10, 0, 0}, {10, 30, 12});
    EXPECT_TRUE(block_centres(model, Vec3::UnitX(), Vec3::UnitY(), 1.0, 2).empty());
}

TEST(ModelWalls, InnerWallsLieInsideTheExtent)
{
    const ModelMesh model = blocks();
    // Inside x's extent (0..60), either facing: x = 20 (the row's back and the tower's front,
    // 320 + 560) and x = 30 (the tower's back and the wing's front, 560 + 60). Largest first.
    const std::vector<double> walls = inner_walls(model, Vec3::UnitX(), 1.0, 2);
    ASSERT_EQ(walls.size(), 2u);
    EXPECT_NEAR(walls[0], 20.0, 1e-9);
    EXPECT_NEAR(walls[1], 30.0, 1e-9);
}
