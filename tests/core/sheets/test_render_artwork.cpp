// The artwork rasteriser against constructions with known answers: face areas, texels placed by
// their uvs, the nearest surface, Lambert's formula, and named refusals.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "popup/input/load_model.hpp"
#include "popup/sheets/render_artwork.hpp"

using namespace popup;

namespace {

using Rgb = std::array<int, 3>;

/// Appends the quad a-b-c-d (counter-clockwise seen from outside) as two triangles with their
/// own four vertices, coloured `rgb` (0..1) when given.
void add_quad(ModelMesh& mesh, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
              const Vec3* rgb = nullptr)
{
    const int k = int(mesh.vertices.size());
    for (const Vec3& p : {a, b, c, d}) {
        mesh.vertices.push_back(p);
        if (rgb)
            mesh.colours.push_back(*rgb);
    }
    mesh.triangles.push_back({k, k + 1, k + 2});
    mesh.triangles.push_back({k, k + 2, k + 3});
}

/// The box [lo, hi] with one colour per face, faces counter-clockwise seen from outside.
ModelMesh coloured_box(const Vec3& lo, const Vec3& hi)
{
    ModelMesh m;
    m.source = "box";
    auto at = [&](int i, int j, int k) {
        return Vec3(i ? hi.x() : lo.x(), j ? hi.y() : lo.y(), k ? hi.z() : lo.z());
    };
    const Vec3 red(1, 0, 0), green(0, 1, 0), blue(0, 0, 1), cyan(0, 1, 1), magenta(1, 0, 1),
        yellow(1, 1, 0);
    add_quad(m, at(0, 0, 1), at(1, 0, 1), at(1, 1, 1), at(0, 1, 1), &red);     // +z
    add_quad(m, at(0, 0, 0), at(0, 1, 0), at(1, 1, 0), at(1, 0, 0), &green);   // -z
    add_quad(m, at(1, 0, 0), at(1, 1, 0), at(1, 1, 1), at(1, 0, 1), &blue);    // +x
    add_quad(m, at(0, 0, 0), at(0, 0, 1), at(0, 1, 1), at(0, 1, 0), &cyan);    // -x
    add_quad(m, at(0, 1, 0), at(0, 1, 1), at(1, 1, 1), at(1, 1, 0), &magenta); // +y
    add_quad(m, at(0, 0, 0), at(1, 0, 0), at(1, 0, 1), at(0, 0, 1), &yellow);  // -y
    return m;
}

/// A planar patch with the given outline (counter-clockwise seen from its normal side).
Patch patch_with(std::vector<Vec3> outline, int id = 7)
{
    Patch p;
    p.id = id;
    p.name = "front";
    p.outer = std::move(outline);
    p.derive_frame();
    return p;
}

Rgb pixel_rgb(const PatchArtwork& art, int column, int row)
{
    const std::uint8_t* p = art.image.at(column, row);
    return {p[0], p[1], p[2]};
}

int alpha(const PatchArtwork& art, int column, int row)
{
    return art.image.at(column, row)[3];
}

/// The pixel whose square holds the design-state point x (the layout PatchArtwork documents).
std::pair<int, int> pixel_of(const PatchArtwork& art, const Vec3& x)
{
    const Vec3 d = x - art.frame_origin;
    const double a = d.dot(art.frame_u), b = d.dot(art.frame_v);
    const int column = int(std::floor((a - art.origin.x()) / art.mm_per_pixel));
    const int row = art.image.height - 1 - int(std::floor((b - art.origin.y()) / art.mm_per_pixel));
    return {column, row};
}

Rgb rgb_at(const PatchArtwork& art, const Vec3& x)
{
    const auto [column, row] = pixel_of(art, x);
    return pixel_rgb(art, column, row);
}

long long count_rgb(const PatchArtwork& art, const Rgb& rgb)
{
    long long n = 0;
    for (int row = 0; row < art.image.height; ++row)
        for (int column = 0; column < art.image.width; ++column)
            if (alpha(art, column, row) == 255 && pixel_rgb(art, column, row) == rgb)
                ++n;
    return n;
}

bool has(const Diagnostics& diagnostics, DiagnosticCode code, const std::string& words)
{
    for (const Diagnostic& d : diagnostics)
        if (d.code == code && d.message.find(words) != std::string::npos)
            return true;
    return false;
}

/// Writes an uncompressed 32-bit TGA (top row first) of `width` × `height` RGBA pixels (rows top
/// to bottom), byte by byte: the texture does not depend on the decoder under test.
std::string write_texture(const std::string& name, int width, int height,
                          const std::vector<std::uint8_t>& rgba)
{
    const std::string path =
        (std::filesystem::temp_directory_path() / ("popup_artwork_" + name + ".tga")).string();
    std::string bytes(18, '\0');
    bytes[2] = 2; // true colour, uncompressed
    bytes[12] = char(width & 0xff);
    bytes[13] = char(width >> 8);
    bytes[14] = char(height & 0xff);
    bytes[15] = char(height >> 8);
    bytes[16] = 32;   // bits per pixel
    bytes[17] = 0x28; // 8 alpha bits, rows from the top
    for (size_t i = 0; i < rgba.size(); i += 4)
        bytes += {char(rgba[i + 2]), char(rgba[i + 1]), char(rgba[i]), char(rgba[i + 3])};
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

const Vec3 kRed(1, 0, 0);

} // namespace

TEST(RenderArtwork, CubeFaceCoversExactlyItsAreaInItsColour)
{
    // Cube [10, 30] x [20, 40] x [0, 20]; the patch lies in its top face's plane and is larger.
    const ModelMesh cube = coloured_box({10, 20, 0}, {30, 40, 20});
    const Patch top = patch_with({{0, 0, 20}, {50, 0, 20}, {50, 60, 20}, {0, 60, 20}});
    ArtworkOptions o;
    o.pixels_per_mm = 4.0;
    const Result<PatchArtwork> r = render_artwork(cube, top, o);
    ASSERT_TRUE(r.ok) << r.diagnostics.front().message;
    const PatchArtwork& art = r.value;
    EXPECT_EQ(art.image.width * art.image.height, 200 * 240); // 50 x 60 mm at 4 px/mm
    const double pixel_area = art.mm_per_pixel * art.mm_per_pixel;
    // Only the red top face shows (sides edge-on, bottom 20 mm behind); its 20 x 20 mm within a
    // one-pixel border around its 80 mm perimeter.
    EXPECT_EQ(count_rgb(art, {255, 0, 0}), art.covered_pixels);
    EXPECT_NEAR(art.covered_pixels * pixel_area, 400.0, 80.0 * art.mm_per_pixel);
    EXPECT_EQ(rgb_at(art, {20, 30, 20}), (Rgb{255, 0, 0}));
    EXPECT_EQ(alpha(art, pixel_of(art, {5, 30, 20}).first, pixel_of(art, {5, 30, 20}).second), 0);
    EXPECT_EQ(alpha(art, pixel_of(art, {20, 45, 20}).first, pixel_of(art, {20, 45, 20}).second), 0);
    // The image lies on the patch's own frame (derive_frame's), covering its bounding box.
    EXPECT_LT((art.frame_normal - Vec3::UnitZ()).norm(), 1e-12);
    EXPECT_LT((art.frame_origin - Vec3(25, 30, 20)).norm(), 1e-12);
}

TEST(RenderArtwork, UprightPatchOnACubeSideTakesThatSide)
{
    // A box-fold front: the plane x = 30 facing +x, outline counter-clockwise seen from +x.
    const ModelMesh cube = coloured_box({10, 20, 0}, {30, 40, 20});
    const Patch front = patch_with({{30, 0, 0}, {30, 60, 0}, {30, 60, 30}, {30, 0, 30}});
    ASSERT_LT((front.normal - Vec3::UnitX()).norm(), 1e-12);
    ArtworkOptions o;
    o.pixels_per_mm = 5.0;
    const Result<PatchArtwork> r = render_artwork(cube, front, o);
    ASSERT_TRUE(r.ok);
    EXPECT_EQ(count_rgb(r.value, {0, 0, 255}), r.value.covered_pixels);
    EXPECT_NEAR(r.value.covered_pixels * 0.04, 400.0, 80.0 * 0.2);
    EXPECT_EQ(rgb_at(r.value, {30, 30, 10}), (Rgb{0, 0, 255}));
}

TEST(RenderArtwork, BackSideSeesTheFacesOnTheOtherSide)
{
    // Patch in the cube's top plane, rendered from below: the top face turns its back (culled),
    // the bottom face 20 mm away faces the viewer.
    const ModelMesh cube = coloured_box({10, 20, 0}, {30, 40, 20});
    const Patch top = patch_with({{0, 0, 20}, {50, 0, 20}, {50, 60, 20}, {0, 60, 20}});
    ArtworkOptions o;
    o.pixels_per_mm = 2.0;
    o.back_side = true;
    o.depth = 25.0;
    const Result<PatchArtwork> r = render_artwork(cube, top, o);
    ASSERT_TRUE(r.ok);
    EXPECT_TRUE(r.value.back_side);
    EXPECT_EQ(count_rgb(r.value, {0, 255, 0}), r.value.covered_pixels);
    EXPECT_NEAR(r.value.covered_pixels * 0.25, 400.0, 80.0 * 0.5);
    o.depth = 15.0; // the bottom face is now beyond the window
    EXPECT_EQ(render_artwork(cube, top, o).value.covered_pixels, 0);
}

TEST(RenderArtwork, TexelsLandWhereTheUvsSay)
{
    // 2 x 2 checker, rows top to bottom: red green / blue white. uv (0, 0) is the bottom-left.
    const std::vector<std::uint8_t> checker = {255, 0, 0,   255, 0,   255, 0,   255,
                                               0,   0, 255, 255, 255, 255, 255, 255};
    ModelMesh quad;
    quad.source = "quad";
    quad.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
    quad.vertices = {{0, 0, 0}, {40, 0, 0}, {40, 40, 0}, {0, 0, 0}, {40, 40, 0}, {0, 40, 0}};
    quad.triangles = {{0, 1, 2}, {3, 4, 5}};
    quad.texture = write_texture("checker", 2, 2, checker);
    const Patch patch = patch_with({{0, 0, 0}, {40, 0, 0}, {40, 40, 0}, {0, 40, 0}});
    ArtworkOptions o;
    o.pixels_per_mm = 0.25; // pixel centres at 2, 6, 10, 14, ... mm: on the texel centres
    const Result<PatchArtwork> r = render_artwork(quad, patch, o);
    ASSERT_TRUE(r.ok);
    ASSERT_TRUE(r.diagnostics.empty()) << r.diagnostics.front().message;
    EXPECT_EQ(rgb_at(r.value, {10, 10, 0}), (Rgb{0, 0, 255}));
    EXPECT_EQ(rgb_at(r.value, {30, 10, 0}), (Rgb{255, 255, 255}));
    EXPECT_EQ(rgb_at(r.value, {10, 30, 0}), (Rgb{255, 0, 0}));
    EXPECT_EQ(rgb_at(r.value, {30, 30, 0}), (Rgb{0, 255, 0}));
    // At (6, 10) mm, u = 0.15: texel x = 0.15 * 2 - 0.5 = -0.2, so 0.8 of column 0 and 0.2 of
    // column -1, which repeats as column 1 (bottom row: blue, white).
    const Rgb blend{int(std::lround(0.2 * 255)), int(std::lround(0.2 * 255)), 255};
    EXPECT_EQ(rgb_at(r.value, {6, 10, 0}), blend);
    EXPECT_EQ(r.value.covered_pixels, 100); // the whole 40 x 40 mm at 4 mm per pixel
    std::filesystem::remove(quad.texture);
}

TEST(RenderArtwork, UnreadableTextureWarnsAndShades)
{
    ModelMesh quad;
    quad.source = "quad";
    add_quad(quad, {0, 0, 0}, {40, 0, 0}, {40, 40, 0}, {0, 40, 0});
    quad.uvs.assign(4, Vec2(0.5, 0.5));
    quad.texture = "/nonexistent/popup_texture.png";
    quad.base_colour = Vec3(1, 1, 1);
    const Patch patch = patch_with({{0, 0, 0}, {40, 0, 0}, {40, 40, 0}, {0, 40, 0}});
    ArtworkOptions o;
    o.pixels_per_mm = 0.5;
    o.ambient = 1.0; // all light ambient: exactly the base colour
    const Result<PatchArtwork> r = render_artwork(quad, patch, o);
    ASSERT_TRUE(r.ok);
    EXPECT_TRUE(has(r.diagnostics, DiagnosticCode::unreadable_texture,
                    "quad: texture /nonexistent/popup_texture.png: cannot open the file; the "
                    "shaded base colour is used"));
    EXPECT_EQ(r.diagnostics.front().severity, Severity::warning);
    EXPECT_EQ(rgb_at(r.value, {20, 20, 0}), (Rgb{255, 255, 255}));
}

TEST(RenderArtwork, NearestSurfaceWins)
{
    // Red at 2 mm above the patch over x in [0, 40]; green at 5 mm over x in [20, 60]; both
    // facing the viewer (+z). The green one is nearer the viewer where they overlap.
    ModelMesh m;
    m.source = "two sheets";
    const Vec3 red(1, 0, 0), green(0, 1, 0);
    add_quad(m, {0, 0, 2}, {40, 0, 2}, {40, 40, 2}, {0, 40, 2}, &red);
    add_quad(m, {20, 0, 5}, {60, 0, 5}, {60, 40, 5}, {20, 40, 5}, &green);
    const Patch patch = patch_with({{0, 0, 0}, {60, 0, 0}, {60, 40, 0}, {0, 40, 0}});
    ArtworkOptions o;
    o.pixels_per_mm = 1.0;
    Result<PatchArtwork> r = render_artwork(m, patch, o);
    ASSERT_TRUE(r.ok);
    EXPECT_EQ(rgb_at(r.value, {10, 20, 0}), (Rgb{255, 0, 0}));
    EXPECT_EQ(rgb_at(r.value, {30, 20, 0}), (Rgb{0, 255, 0}));
    EXPECT_EQ(rgb_at(r.value, {50, 20, 0}), (Rgb{0, 255, 0}));
    EXPECT_NEAR(double(count_rgb(r.value, {255, 0, 0})), 20.0 * 40.0, 120.0);
    // With the window 4 mm deep the green sheet is out of reach: red wherever red is.
    o.depth = 4.0;
    r = render_artwork(m, patch, o);
    EXPECT_EQ(rgb_at(r.value, {30, 20, 0}), (Rgb{255, 0, 0}));
    EXPECT_EQ(
        alpha(r.value, pixel_of(r.value, {50, 20, 0}).first, pixel_of(r.value, {50, 20, 0}).second),
        0);
    EXPECT_NEAR(double(r.value.covered_pixels), 40.0 * 40.0, 160.0);
}

TEST(RenderArtwork, SurfaceJustBehindThePatchCountsWithinTolerance)
{
    ModelMesh m;
    m.source = "behind";
    add_quad(m, {0, 0, -0.5}, {40, 0, -0.5}, {40, 40, -0.5}, {0, 40, -0.5}, &kRed);
    const Patch patch = patch_with({{0, 0, 0}, {40, 0, 0}, {40, 40, 0}, {0, 40, 0}});
    ArtworkOptions o;
    o.pixels_per_mm = 1.0;
    o.behind = 1.0;
    EXPECT_EQ(render_artwork(m, patch, o).value.covered_pixels, 1600);
    o.behind = 0.25;
    EXPECT_EQ(render_artwork(m, patch, o).value.covered_pixels, 0);
}

TEST(RenderArtwork, PlainModelIsShadedByLambert)
{
    // Plane z = 20 - 0.3 x - 0.2 y (normal along (0.3, 0.2, 1)) and, beside it, a plane tilted
    // away from the light (normal along (-2, 2, 1)): Lambert clamps it to the ambient term.
    ModelMesh m;
    m.source = "plain";
    m.base_colour = Vec3(0.8, 0.6, 0.4);
    auto lit_z = [](double x, double y) { return 20.0 - 0.3 * x - 0.2 * y; };
    add_quad(m, {0, 0, lit_z(0, 0)}, {40, 0, lit_z(40, 0)}, {40, 40, lit_z(40, 40)},
             {0, 40, lit_z(0, 40)});
    auto dark_z = [](double x, double y) { return 100.0 + 2.0 * (x - 60.0) - 2.0 * y; };
    add_quad(m, {60, 0, dark_z(60, 0)}, {100, 0, dark_z(100, 0)}, {100, 40, dark_z(100, 40)},
             {60, 40, dark_z(60, 40)});
    const Patch patch = patch_with({{0, 0, 0}, {100, 0, 0}, {100, 40, 0}, {0, 40, 0}});
    ArtworkOptions o;
    o.pixels_per_mm = 1.0;
    o.depth = INFINITY;
    const Result<PatchArtwork> r = render_artwork(m, patch, o);
    ASSERT_TRUE(r.ok);
    const Vec3 light = Vec3(1, -1, 2).normalized();
    auto expected = [&](const Vec3& normal) {
        const double lit = 0.3 + 0.7 * std::max(0.0, normal.normalized().dot(light));
        return Rgb{int(std::lround(0.8 * lit * 255)), int(std::lround(0.6 * lit * 255)),
                   int(std::lround(0.4 * lit * 255))};
    };
    EXPECT_GT(Vec3(0.3, 0.2, 1).normalized().dot(light), 0.0);
    EXPECT_LT(Vec3(-2, 2, 1).normalized().dot(light), 0.0);
    EXPECT_EQ(rgb_at(r.value, {20, 20, 0}), expected({0.3, 0.2, 1}));
    EXPECT_EQ(rgb_at(r.value, {80, 20, 0}), expected({-2, 2, 1}));
    EXPECT_EQ(expected({-2, 2, 1}), (Rgb{61, 46, 31})); // 0.3 × base, by hand
}

TEST(RenderArtwork, BadOptionsAreNamed)
{
    const ModelMesh cube = coloured_box({10, 20, 0}, {30, 40, 20});
    const Patch top = patch_with({{0, 0, 20}, {50, 0, 20}, {50, 60, 20}, {0, 60, 20}});
    auto refused = [&](ArtworkOptions o, const std::string& words) {
        const Result<PatchArtwork> r = render_artwork(cube, top, o);
        EXPECT_FALSE(r.ok) << words;
        EXPECT_TRUE(has(r.diagnostics, DiagnosticCode::bad_option, words)) << words;
    };
    ArtworkOptions o;
    o.pixels_per_mm = 0.0;
    refused(o, "pixels_per_mm = 0, must be > 0 and at most 40");
    o.pixels_per_mm = NAN;
    refused(o, "pixels_per_mm = nan");
    o.pixels_per_mm = 41.0;
    refused(o, "pixels_per_mm = 41");
    o = {};
    o.depth = NAN;
    refused(o, "depth = nan, must be > 0 mm");
    o = {};
    o.behind = -1.0;
    refused(o, "behind = -1, must be >= 0 mm");
    o = {};
    o.ambient = 1.5;
    refused(o, "ambient = 1.5, must be in [0, 1]");
    o = {};
    o.light = Vec3::Zero();
    refused(o, "light = (0, 0, 0)");
    o = {};
    o.max_pixels = 0;
    refused(o, "max_pixels = 0, must be in [1, 100000000]");
    // 60 x 50 mm (u along the longest edge) at 40 px/mm is 4.8 M pixels: over a cap of 1 M.
    o = {};
    o.pixels_per_mm = 40.0;
    o.max_pixels = 1'000'000;
    refused(o, "artwork of patch 7 (front): 2400 x 2000 pixels at 40 pixels per mm, at most "
               "max_pixels = 1000000");
    // A 10 m patch at 40 px/mm would be 1.6e11 pixels: refused before anything is allocated.
    const Patch huge = patch_with({{0, 0, 0}, {1e4, 0, 0}, {1e4, 1e4, 0}, {0, 1e4, 0}});
    o.max_pixels = 100'000'000;
    const Result<PatchArtwork> r = render_artwork(cube, huge, o);
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(has(r.diagnostics, DiagnosticCode::bad_option, "400000 x 400000 pixels"));
}

TEST(RenderArtwork, CornersWithoutTextureTakeTheirVertexColour)
{
    // Two materials merged by load_model: the left 40 × 40 mm square is textured (the checker of
    // the test above), the right one is red with no texture, so its corners carry (NaN, NaN)
    // texture coordinates (model_mesh.hpp). The left keeps its texels, the right is red.
    const std::vector<std::uint8_t> checker = {255, 0, 0,   255, 0,   255, 0,   255,
                                               0,   0, 255, 255, 255, 255, 255, 255};
    const double nan = std::numeric_limits<double>::quiet_NaN();
    ModelMesh two;
    two.source = "two materials";
    two.vertices = {{0, 0, 0},  {40, 0, 0}, {40, 40, 0}, {0, 40, 0},
                    {40, 0, 0}, {80, 0, 0}, {80, 40, 0}, {40, 40, 0}};
    two.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
    two.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {nan, nan}, {nan, nan}, {nan, nan}, {nan, nan}};
    const Vec3 white(1, 1, 1);
    two.colours = {white, white, white, white, kRed, kRed, kRed, kRed};
    two.texture = write_texture("checker_two", 2, 2, checker);
    const Patch patch = patch_with({{0, 0, 0}, {80, 0, 0}, {80, 40, 0}, {0, 40, 0}});
    ArtworkOptions o;
    o.pixels_per_mm = 0.25;
    const Result<PatchArtwork> r = render_artwork(two, patch, o);
    ASSERT_TRUE(r.ok) << r.diagnostics.front().message;
    EXPECT_EQ(rgb_at(r.value, {10, 10, 0}), (Rgb{0, 0, 255}));
    EXPECT_EQ(rgb_at(r.value, {30, 30, 0}), (Rgb{0, 255, 0}));
    EXPECT_EQ(rgb_at(r.value, {50, 10, 0}), (Rgb{255, 0, 0}));
    EXPECT_EQ(rgb_at(r.value, {70, 30, 0}), (Rgb{255, 0, 0}));
    EXPECT_EQ(r.value.covered_pixels, 200);
    // Only both coordinates NaN is the mark: one NaN, or an infinity, is a named error.
    two.uvs[5] = Vec2(nan, 0.5);
    EXPECT_TRUE(has(render_artwork(two, patch, o).diagnostics, DiagnosticCode::non_finite_model,
                    "texture coordinate of vertex 5"));
    two.uvs[5] = Vec2(std::numeric_limits<double>::infinity(), 0.5);
    EXPECT_TRUE(has(render_artwork(two, patch, o).diagnostics, DiagnosticCode::non_finite_model,
                    "texture coordinate of vertex 5"));
    std::filesystem::remove(two.texture);
}

TEST(RenderArtwork, BadMeshesAndPatchesAreNamed)
{
    const Patch top = patch_with({{0, 0, 20}, {50, 0, 20}, {50, 60, 20}, {0, 60, 20}});
    ModelMesh empty;
    empty.source = "nothing.obj";
    EXPECT_TRUE(has(render_artwork(empty, top).diagnostics, DiagnosticCode::empty_model,
                    "nothing.obj: has no triangles"));
    ModelMesh cube = coloured_box({10, 20, 0}, {30, 40, 20});
    cube.colours.pop_back();
    EXPECT_TRUE(has(render_artwork(cube, top).diagnostics, DiagnosticCode::degenerate_model,
                    "box: 23 colours for 24 vertices, must be one per vertex or none"));
    cube = coloured_box({10, 20, 0}, {30, 40, 20});
    cube.colours[3].y() = NAN;
    EXPECT_TRUE(has(render_artwork(cube, top).diagnostics, DiagnosticCode::non_finite_model,
                    "colour of vertex 3"));
    cube = coloured_box({10, 20, 0}, {30, 40, 20});
    const Patch line = patch_with({{0, 0, 0}, {10, 0, 0}, {20, 0, 0}}, 3);
    const Result<PatchArtwork> r = render_artwork(cube, line);
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(has(r.diagnostics, DiagnosticCode::degenerate_patch, "patch 3 (front)"));
    Patch bent = top;
    bent.outer[2].z() = 25.0;
    EXPECT_TRUE(has(render_artwork(cube, bent).diagnostics, DiagnosticCode::non_planar_patch,
                    "not planar"));
}

TEST(RenderArtwork, ModelFarBesideThePatchLeavesItTransparent)
{
    // 1e9 mm away in the patch plane: no pixel index may overflow, nothing shows.
    const ModelMesh cube = coloured_box({1e9, 0, -10}, {1e9 + 20, 20, 10});
    const Patch patch = patch_with({{0, 0, 0}, {40, 0, 0}, {40, 40, 0}, {0, 40, 0}});
    const Result<PatchArtwork> r = render_artwork(cube, patch);
    ASSERT_TRUE(r.ok);
    EXPECT_EQ(r.value.covered_pixels, 0);
}

TEST(RenderArtwork, TexturedModelsPrintTheirTextureOrWarnAndShade)
{
    // tools/make_textured_models.py's cuboid [0, 60] x [0, 40] x [0, 30], every face showing the
    // 32 x 16 texture of four blocks upright: its top, seen from above, red top-left, green
    // top-right, blue bottom-left, yellow bottom-right, each over a 30 x 20 mm quarter.
    const std::string folder = "tests/data/textures/";
    std::ifstream file(folder + "expected.json");
    const auto blocks = nlohmann::json::parse(file)["blocks"];
    auto block = [&](const char* name) { return blocks[name].get<Rgb>(); };
    const Patch top = patch_with({{0, 0, 30}, {60, 0, 30}, {60, 40, 30}, {0, 40, 30}});
    ArtworkOptions o;
    o.pixels_per_mm = 1.0;
    for (const char* name : {"cube_tga.obj", "cube_bmp.obj", "cube_png.glb"}) {
        const Result<ModelMesh> model = load_model(folder + name);
        ASSERT_TRUE(model.ok) << name;
        const Result<PatchArtwork> r = render_artwork(model.value, top, o);
        ASSERT_TRUE(r.ok) << name;
        EXPECT_TRUE(r.diagnostics.empty()) << name << ": " << r.diagnostics.front().message;
        EXPECT_EQ(r.value.covered_pixels, 60 * 40) << name;
        EXPECT_EQ(rgb_at(r.value, {15, 30, 30}), block("top_left")) << name;
        EXPECT_EQ(rgb_at(r.value, {45, 30, 30}), block("top_right")) << name;
        EXPECT_EQ(rgb_at(r.value, {15, 10, 30}), block("bottom_left")) << name;
        EXPECT_EQ(rgb_at(r.value, {45, 10, 30}), block("bottom_right")) << name;
        // Only the texels next to a block edge blend (bilinear): most of each quarter is exact.
        for (const char* quarter : {"top_left", "top_right", "bottom_left", "bottom_right"})
            EXPECT_GE(count_rgb(r.value, block(quarter)), 500) << name << " " << quarter;
    }
    for (const auto& [name, texture] : std::vector<std::pair<std::string, std::string>>{
             {"cube_missing.obj", "missing.tga"}, {"cube_corrupt.obj", "corrupt.png"}}) {
        const Result<ModelMesh> model = load_model(folder + name);
        ASSERT_TRUE(model.ok) << name;
        const Result<PatchArtwork> r = render_artwork(model.value, top, o);
        ASSERT_TRUE(r.ok) << name;
        ASSERT_EQ(r.diagnostics.size(), 1u) << name;
        EXPECT_EQ(r.diagnostics.front().severity, Severity::warning);
        EXPECT_TRUE(has(r.diagnostics, DiagnosticCode::unreadable_texture,
                        folder + name + ": texture " + folder + texture + ": "))
            << r.diagnostics.front().message;
        EXPECT_TRUE(has(r.diagnostics, DiagnosticCode::unreadable_texture,
                        "; the shaded base colour is used"));
        // Grey: the material's 0.8 grey shaded by the light, the same on the whole flat top.
        const Rgb grey = rgb_at(r.value, {30, 20, 30});
        EXPECT_TRUE(grey[0] == grey[1] && grey[1] == grey[2]) << name;
        EXPECT_EQ(count_rgb(r.value, grey), 60 * 40) << name;
    }
}
