// The model's volume (occupancy_grid, outer_surface) and the plate under it (supporting_plate):
// assemblies of touching boxes, a hollow house with a window, a reversed part, a terrain slab.
#include <gtest/gtest.h>

#include <algorithm>

#include "fitting/occupancy_grid.hpp"
#include "fitting/outer_surface.hpp"
#include "fitting/synthetic_models.hpp"
#include "popup/fitting/supporting_plate.hpp"

using namespace popup;
using namespace popup::testing;

namespace {

ModelMesh reversed(ModelMesh mesh)
{
    for (auto& t : mesh.triangles)
        std::swap(t[1], t[2]);
    return mesh;
}

/// A hollow box: outer walls from lo to hi, `wall` thick, as six separate slabs (an assembly).
ModelMesh hollow_box(const Vec3& lo, const Vec3& hi, double wall)
{
    return join({box_mesh(lo, {hi.x(), hi.y(), lo.z() + wall}),
                 box_mesh({lo.x(), lo.y(), hi.z() - wall}, hi),
                 box_mesh({lo.x(), lo.y(), lo.z() + wall}, {lo.x() + wall, hi.y(), hi.z() - wall}),
                 box_mesh({hi.x() - wall, lo.y(), lo.z() + wall}, {hi.x(), hi.y(), hi.z() - wall}),
                 box_mesh({lo.x() + wall, lo.y(), lo.z() + wall},
                          {hi.x() - wall, lo.y() + wall, hi.z() - wall}),
                 box_mesh({lo.x() + wall, hi.y() - wall, lo.z() + wall},
                          {hi.x() - wall, hi.y(), hi.z() - wall})});
}

} // namespace

/// Two boxes stacked face to face: the volume is their union, solid across the shared face, and
/// free beyond it; the samples on the shared face (both boxes' faces there) are inner and make
/// up its share of the area, 2·(40·40) of the total 2·(4·40·20 + 2·40·40) mm².
TEST(ModelVolume, TouchingBoxesActAsOneSolid)
{
    const ModelMesh stack =
        join({box_mesh({0, 0, 0}, {40, 40, 20}), box_mesh({0, 0, 20}, {40, 40, 40})});
    const OccupancyGrid volume(stack, 128, 4);
    EXPECT_TRUE(volume.solid_at({20, 20, 20}));
    EXPECT_TRUE(volume.solid_at({2, 2, 38}));
    EXPECT_FALSE(volume.solid_at({20, 20, 41.5}));
    EXPECT_FALSE(volume.solid_at({-1.5, 20, 20}));
    const OuterSurface outer = outer_surface(volume, sample_surface(stack, 20000, 3));
    const double shared = 2 * 40.0 * 40.0, total = 2 * (4 * 40.0 * 20.0 + 2 * 40.0 * 40.0);
    EXPECT_NEAR(outer.inner_count / 20000.0, shared / total, 0.01);
    EXPECT_EQ(outer.turned, 0);
    for (size_t i = 0; i < outer.inner.size(); ++i) {
        if (outer.inner[i]) {
            EXPECT_NEAR(outer.samples.points[i].z(), 20.0, 1e-9);
        }
    }
}

/// A hollow box of six slabs (cells of 80/128 = 0.625 mm) with a slot through its front: a slot
/// 4 mm wide (6.4 cells, under the 8 the closing bridges) is closed and the room inside is
/// solid; one 16 mm wide (25.6 cells) is not, and the room stays free.
TEST(ModelVolume, ClosingBridgesNarrowWindowsOnly)
{
    const Vec3 lo(0, 0, 0), hi(80, 60, 50);
    EXPECT_TRUE(OccupancyGrid(hollow_box(lo, hi, 2.0), 128, 4).solid_at({40, 30, 25}));
    auto with_window = [&](double width) {
        // The front slab (y from 0 to 2) as two slabs with the slot between them.
        std::vector<ModelMesh> parts{
            box_mesh(lo, {hi.x(), hi.y(), lo.z() + 2}),
            box_mesh({lo.x(), lo.y(), hi.z() - 2}, hi),
            box_mesh({lo.x(), lo.y(), 2}, {2, hi.y(), hi.z() - 2}),
            box_mesh({hi.x() - 2, lo.y(), 2}, {hi.x(), hi.y(), hi.z() - 2}),
            box_mesh({2, hi.y() - 2, 2}, {hi.x() - 2, hi.y(), hi.z() - 2}),
            box_mesh({2, 0, 2}, {40 - width / 2, 2, hi.z() - 2}),
            box_mesh({40 + width / 2, 0, 2}, {hi.x() - 2, 2, hi.z() - 2})};
        return join(parts);
    };
    const OccupancyGrid narrow(with_window(4.0), 128, 4);
    EXPECT_TRUE(narrow.solid_at({40, 30, 25}));
    const OccupancyGrid wide(with_window(16.0), 128, 4);
    EXPECT_FALSE(wide.solid_at({40, 30, 25}));
    // The walls themselves are solid either way.
    EXPECT_TRUE(wide.solid_at({1, 30, 25}));
}

/// A part written inside out (its winding reversed, as a file or a cleaning may leave it) is
/// turned to face out: all twelve of its triangles, none of the other part's; afterwards the
/// signed volume of the whole is the two boxes' sum.
TEST(ModelVolume, ReversedPartFacesOutAgain)
{
    const ModelMesh model =
        join({box_mesh({0, 0, 0}, {30, 30, 10}), reversed(box_mesh({5, 5, 10}, {25, 25, 30}))});
    const OccupancyGrid volume(model, 128, 4);
    int turned = 0;
    const ModelMesh fixed = faces_turned_out(model, volume, turned);
    EXPECT_EQ(turned, 12);
    double signed_volume = 0;
    for (const auto& t : fixed.triangles)
        signed_volume +=
            fixed.vertices[t[0]].dot(fixed.vertices[t[1]].cross(fixed.vertices[t[2]])) / 6;
    EXPECT_NEAR(signed_volume, 30 * 30 * 10 + 20 * 20 * 20, 1e-6);
}

/// A single-sided sheet (an open roof panel) over a closed box, its normal pointing down into the
/// box: the grid turns it up.
TEST(ModelVolume, OpenSheetTurnsToFaceOut)
{
    ModelMesh sheet;
    sheet.vertices = {{-5, -5, 21}, {45, -5, 21}, {45, 45, 21}, {-5, 45, 21}};
    sheet.triangles = {{0, 2, 1}, {0, 3, 2}}; // clockwise from above: facing down
    const ModelMesh model = join({box_mesh({0, 0, 0}, {40, 40, 20}), sheet});
    const OccupancyGrid volume(model, 128, 4);
    int turned = 0;
    const ModelMesh fixed = faces_turned_out(model, volume, turned);
    EXPECT_EQ(turned, 2);
    const auto& t = fixed.triangles.back();
    const Vec3 n = (fixed.vertices[t[1]] - fixed.vertices[t[0]])
                       .cross(fixed.vertices[t[2]] - fixed.vertices[t[0]]);
    EXPECT_GT(n.z(), 0);
}

/// A house (box) on a terrain slab four times its footprint: the slab's top is the plate, at its
/// thickness above the bottom; without the plate the model is the house alone, less its bottom
/// face, which lies on the page (12 - 2 triangles, all 8 corners still used).
TEST(SupportingPlate, TerrainSlabUnderAHouse)
{
    const ModelMesh model =
        join({box_mesh({-40, -30, -2}, {40, 30, 0}), box_mesh({-20, -15, 0}, {20, 15, 25})});
    const auto plate = supporting_plate(model, {0, 0, 1});
    ASSERT_TRUE(plate.has_value());
    EXPECT_NEAR(plate->top, 0.0, 1e-12);
    EXPECT_NEAR(plate->thickness, 2.0, 1e-12);
    EXPECT_NEAR(plate->top_area, 80.0 * 60.0, 1e-6); // the slab's whole top face
    const ModelMesh house = above_plate(model, *plate);
    EXPECT_EQ(house.triangles.size(), 10u);
    EXPECT_EQ(house.vertices.size(), 8u);
}

/// What is not a plate: a plate alone (nothing stands on it), a box on a box nearly as wide
/// (the top covers more than 70 % of the footprint), a model upside down (the slab on top),
/// and a slab thicker than a quarter of the height.
TEST(SupportingPlate, OnlyAThinWidePlateUnderSomething)
{
    EXPECT_FALSE(supporting_plate(box_mesh({0, 0, 0}, {80, 60, 0.4}), {0, 0, 1}));
    EXPECT_FALSE(supporting_plate(
        join({box_mesh({0, 0, 0}, {80, 60, 2}), box_mesh({2, 2, 2}, {78, 58, 30})}), {0, 0, 1}));
    const ModelMesh house =
        join({box_mesh({-40, -30, -2}, {40, 30, 0}), box_mesh({-20, -15, 0}, {20, 15, 25})});
    EXPECT_FALSE(supporting_plate(house, {0, 0, -1}));
    EXPECT_FALSE(supporting_plate(
        join({box_mesh({-40, -30, 0}, {40, 30, 10}), box_mesh({-20, -15, 10}, {20, 15, 30})}),
        {0, 0, 1}));
}
