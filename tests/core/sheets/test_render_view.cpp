// The preview rasteriser against constructions with known answers: a polygon's area in pixel
// centres across many bands, the nearer surface winning, holes left open, the shade formula,
// supersampling, and named refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "popup/sheets/render_view.hpp"

using namespace popup;

namespace {

/// A camera looking straight down (-z) at `centre`, x right and y up, one pixel per mm.
ViewCamera top_view(int width, int height, const Vec3& centre)
{
    ViewCamera c;
    c.towards_eye = Vec3(0, 0, 1);
    c.up = Vec3(0, 1, 0);
    c.centre = centre;
    c.mm_per_pixel = 1.0;
    c.width = width;
    c.height = height;
    c.light = Vec3(0, 0, 1);
    c.ambient = 0.0;
    c.edge_px = 0.0;
    return c;
}

std::vector<Vec3> rectangle(double x0, double y0, double x1, double y1, double z)
{
    return {Vec3(x0, y0, z), Vec3(x1, y0, z), Vec3(x1, y1, z), Vec3(x0, y1, z)};
}

long count(const RgbaImage& image, int r, int g, int b)
{
    long n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.at(x, y);
            n += p[0] == r && p[1] == g && p[2] == b && p[3] == 255;
        }
    return n;
}

} // namespace

TEST(RenderView, APolygonCoversItsAreaInPixelCentresAcrossBands)
{
    // 300 rows: many bands of 32; the rectangle's 150 x 250 mm are as many pixel centres.
    ViewPolygon red{{rectangle(0, 0, 150, 250, 0)}, Vec3(1, 0, 0), false};
    const Result<RgbaImage> r = render_view({}, {red}, top_view(200, 300, Vec3(75, 125, 0)));
    ASSERT_TRUE(r.ok);
    EXPECT_EQ(count(r.value, 255, 0, 0), 150L * 250L);
    EXPECT_EQ(r.value.at(0, 0)[3], 0); // the background is transparent
}

TEST(RenderView, TheNearerSurfaceWinsAndHolesStayOpen)
{
    ViewMesh blue;
    blue.vertices = rectangle(0, 0, 50, 50, 10);
    blue.triangles = {{0, 1, 2}, {0, 2, 3}};
    blue.colour = Vec3(0, 0, 1);
    ViewPolygon red{
        {rectangle(0, 0, 100, 50, 0), rectangle(60, 10, 90, 40, 0)}, Vec3(1, 0, 0), false};
    const Result<RgbaImage> r = render_view({blue}, {red}, top_view(100, 50, Vec3(50, 25, 0)));
    ASSERT_TRUE(r.ok);
    EXPECT_EQ(count(r.value, 0, 0, 255), 50L * 50L);
    EXPECT_EQ(count(r.value, 255, 0, 0), 50L * 50L - 30L * 30L);
}

TEST(RenderView, FacesAreShadedByTheirNormalOnBothSides)
{
    // ambient 0.2, light at 60 degrees from the normal: 0.2 + 0.8 * 0.5 = 0.6 of the colour.
    ViewCamera camera = top_view(10, 10, Vec3(5, 5, 0));
    camera.ambient = 0.2;
    camera.light = Vec3(std::sqrt(3.0), 0, 1);
    ViewPolygon white{{rectangle(0, 0, 10, 10, 0)}, Vec3(1, 1, 1), false};
    const Result<RgbaImage> up = render_view({}, {white}, camera);
    std::reverse(white.loops[0].begin(), white.loops[0].end()); // the other face
    const Result<RgbaImage> down = render_view({}, {white}, camera);
    ASSERT_TRUE(up.ok && down.ok);
    EXPECT_EQ(count(up.value, 153, 153, 153), 100);
    EXPECT_EQ(count(down.value, 153, 153, 153), 100);
}

TEST(RenderView, SupersamplingAveragesTheBorderPixels)
{
    // Half a pixel of the rectangle's edge falls in column 10: 2 x 2 samples, 2 of them inside.
    ViewCamera camera = top_view(20, 4, Vec3(10, 2, 0));
    camera.supersample = 2;
    ViewPolygon red{{rectangle(0, 0, 10.5, 4, 0)}, Vec3(1, 0, 0), false};
    const Result<RgbaImage> r = render_view({}, {red}, camera);
    ASSERT_TRUE(r.ok);
    EXPECT_EQ(count(r.value, 255, 0, 0), 10L * 4L);
    const std::uint8_t* border = r.value.at(10, 1);
    EXPECT_EQ(border[0], 255);
    EXPECT_EQ(border[1], 128); // two white and two red samples: (255 + 255 + 0 + 0 + 2) / 4
    EXPECT_EQ(border[3], 128);
}

TEST(RenderView, BadValuesAreNamedWithTheirRange)
{
    ViewCamera camera = top_view(0, 10, Vec3::Zero());
    camera.mm_per_pixel = -1.0;
    camera.supersample = 9;
    ViewMesh broken;
    broken.vertices = {Vec3::Zero()};
    broken.triangles = {{0, 0, 3}};
    const Result<RgbaImage> r = render_view({broken}, {}, camera);
    ASSERT_FALSE(r.ok);
    std::string all;
    for (const Diagnostic& d : r.diagnostics)
        all += d.message + "\n";
    EXPECT_NE(all.find("mm_per_pixel"), std::string::npos) << all;
    EXPECT_NE(all.find("1..8192"), std::string::npos) << all;
    EXPECT_NE(all.find("supersample = 9, must be in 1..4"), std::string::npos) << all;
    EXPECT_NE(all.find("meshes[0] has a triangle index outside 0..0"), std::string::npos) << all;
}
