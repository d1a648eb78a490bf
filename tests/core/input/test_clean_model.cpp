// clean_model: soups with known defects give the known repair counts and the known surface.
#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "popup/input/clean_model.hpp"

using namespace popup;

namespace {

/// The cuboid [0, 20] x [0, 30] x [0, 40] (area 5200, volume 24000): corners and outward
/// triangles, two per face, top face (z = 40) last.
std::vector<Vec3> cuboid_corners()
{
    std::vector<Vec3> c;
    for (int i = 0; i < 8; ++i)
        c.emplace_back(i & 1 ? 20 : 0, i & 2 ? 30 : 0, i & 4 ? 40 : 0);
    return c;
}

std::vector<std::array<int, 3>> cuboid_triangles()
{
    const int quads[6][4] = {{0, 2, 3, 1}, {0, 1, 5, 4}, {2, 6, 7, 3},
                             {0, 4, 6, 2}, {1, 3, 7, 5}, {4, 5, 7, 6}};
    std::vector<std::array<int, 3>> t;
    for (const auto& q : quads) {
        t.push_back({q[0], q[1], q[2]});
        t.push_back({q[0], q[2], q[3]});
    }
    return t;
}

/// A soup: every triangle with its own copies of its corners, as STL stores it.
struct Soup {
    ModelMesh mesh;
    int add_point(const Vec3& p)
    {
        mesh.vertices.push_back(p);
        return int(mesh.vertices.size()) - 1;
    }
    void add_triangle(const Vec3& a, const Vec3& b, const Vec3& c)
    {
        mesh.triangles.push_back({add_point(a), add_point(b), add_point(c)});
    }
};

Soup cuboid_soup(int flipped_faces, int skipped_last = 0)
{
    const auto c = cuboid_corners();
    const auto t = cuboid_triangles();
    Soup soup;
    soup.mesh.source = "defective cuboid";
    for (size_t i = 0; i + skipped_last < t.size(); ++i) {
        if (int(i) < flipped_faces)
            soup.add_triangle(c[t[i][0]], c[t[i][2]], c[t[i][1]]);
        else
            soup.add_triangle(c[t[i][0]], c[t[i][1]], c[t[i][2]]);
    }
    return soup;
}

double signed_volume(const ModelMesh& mesh)
{
    double volume = 0.0;
    for (const auto& t : mesh.triangles)
        volume += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]])) / 6.0;
    return volume;
}

} // namespace

TEST(FitCleanModel, CountsEachRepairOfAClosedSoup)
{
    Soup soup = cuboid_soup(1); // 12 triangles, 36 points, the first one flipped
    const auto c = cuboid_corners();
    const auto t = cuboid_triangles();
    soup.add_triangle(c[t[5][0]], c[t[5][1]], c[t[5][2]]); // a duplicate face (3 more points)
    const int a = soup.add_point(c[0]), b = soup.add_point(c[1]);
    soup.mesh.triangles.push_back({a, a, b}); // a repeated corner (2 more points)
    soup.add_triangle(c[0], c[0], c[1]);      // a corner repeated by position (3 more)
    soup.add_point(Vec3(100, 100, 100));      // used by no face
    ASSERT_EQ(soup.mesh.vertices.size(), 45u);

    const Result<CleanedModel> cleaned = clean_model(soup.mesh);
    ASSERT_TRUE(cleaned.ok) << cleaned.diagnostics.front().message;
    const RepairCounts& r = cleaned.value.repairs;
    EXPECT_EQ(r.duplicate_points_merged, 45 - 9) << "9 distinct positions";
    EXPECT_EQ(r.degenerate_faces_removed, 2);
    EXPECT_EQ(r.duplicate_faces_removed, 1);
    EXPECT_EQ(r.faces_reoriented, 1);
    EXPECT_EQ(r.non_manifold_vertices_split, 0);
    EXPECT_EQ(r.isolated_vertices_removed, 1);
    EXPECT_EQ(r.border_edges, 0);
    EXPECT_EQ(r.holes, 0);
    EXPECT_TRUE(r.closed);
    const ModelMesh& mesh = cleaned.value.mesh;
    EXPECT_EQ(mesh.vertices.size(), 8u);
    EXPECT_EQ(mesh.triangles.size(), 12u);
    EXPECT_NEAR(mesh.area(), 5200.0, 1e-9);
    EXPECT_NEAR(signed_volume(mesh), 24000.0, 1e-9) << "outward";
    EXPECT_EQ(mesh.source, "defective cuboid");
}

TEST(FitCleanModel, AClosedMeshMostlyInsideOutIsTurnedOutward)
{
    const Result<CleanedModel> cleaned = clean_model(cuboid_soup(7).mesh);
    ASSERT_TRUE(cleaned.ok);
    EXPECT_EQ(cleaned.value.repairs.faces_reoriented, 7);
    EXPECT_NEAR(signed_volume(cleaned.value.mesh), 24000.0, 1e-9);
}

TEST(FitCleanModel, AHoleIsCountedAndAnOpenSurfaceKeepsItsMajorityWinding)
{
    Soup soup = cuboid_soup(1, 2); // no top face: a hole of four edges
    // A triangle without area (collinear corners), apart from the rest.
    soup.add_triangle(Vec3(50, 0, 0), Vec3(60, 0, 0), Vec3(70, 0, 0));
    const Result<CleanedModel> cleaned = clean_model(soup.mesh);
    ASSERT_TRUE(cleaned.ok) << cleaned.diagnostics.front().message;
    const RepairCounts& r = cleaned.value.repairs;
    EXPECT_FALSE(r.closed);
    EXPECT_EQ(r.border_edges, 4);
    EXPECT_EQ(r.holes, 1);
    EXPECT_EQ(r.degenerate_faces_removed, 1);
    EXPECT_EQ(r.faces_reoriented, 1);
    EXPECT_EQ(r.duplicate_points_merged, 30 - 8);
    const ModelMesh& mesh = cleaned.value.mesh;
    EXPECT_EQ(mesh.vertices.size(), 8u);
    EXPECT_EQ(mesh.triangles.size(), 10u);
    EXPECT_NEAR(mesh.area(), 5200.0 - 20.0 * 30.0, 1e-9);
    // Open at the top, outward winding: the divergence theorem misses only the top's
    // contribution z * area = 40 * 600.
    EXPECT_NEAR(signed_volume(mesh), 24000.0 - 40.0 * 600.0 / 3.0, 1e-9);
}

TEST(FitCleanModel, ANonManifoldVertexIsSplit)
{
    // Two tetrahedra touching at the origin only (a bow tie).
    Soup soup;
    for (double s : {1.0, -1.0}) {
        const Vec3 o(0, 0, 0), x(10 * s, 0, 0), y(0, 10 * s, 0), z(0, 0, 10 * s);
        // Outward for s = 1; for s = -1 the point reflection reverses orientation, so swap.
        if (s > 0) {
            soup.add_triangle(o, y, x);
            soup.add_triangle(o, x, z);
            soup.add_triangle(o, z, y);
            soup.add_triangle(x, y, z);
        } else {
            soup.add_triangle(o, x, y);
            soup.add_triangle(o, z, x);
            soup.add_triangle(o, y, z);
            soup.add_triangle(x, z, y);
        }
    }
    const Result<CleanedModel> cleaned = clean_model(soup.mesh);
    ASSERT_TRUE(cleaned.ok);
    const RepairCounts& r = cleaned.value.repairs;
    EXPECT_EQ(r.non_manifold_vertices_split, 1);
    EXPECT_EQ(r.faces_reoriented, 0);
    EXPECT_TRUE(r.closed);
    EXPECT_EQ(cleaned.value.mesh.vertices.size(), 8u);
    EXPECT_EQ(cleaned.value.mesh.triangles.size(), 8u);
    EXPECT_NEAR(signed_volume(cleaned.value.mesh), 2 * 1000.0 / 6.0, 1e-9);
}

TEST(FitCleanModel, RefusesWhatCheckModelRefuses)
{
    ModelMesh mesh;
    mesh.source = "bad.obj";
    mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, std::nan(""), 0)};
    mesh.triangles = {{0, 1, 2}};
    const Result<CleanedModel> cleaned = clean_model(mesh);
    ASSERT_FALSE(cleaned.ok);
    EXPECT_EQ(cleaned.diagnostics.front().code, DiagnosticCode::non_finite_model);
    EXPECT_NE(cleaned.diagnostics.front().message.find("bad.obj"), std::string::npos);
}

TEST(FitCleanModel, DropsAppearanceThatMergingLeavesWithoutAValue)
{
    Soup soup = cuboid_soup(0);
    soup.mesh.colours.assign(soup.mesh.vertices.size(), Vec3(1, 0, 0));
    soup.mesh.uvs.assign(soup.mesh.vertices.size(), Vec2(0.5, 0.5));
    soup.mesh.texture = "paint.png";
    soup.mesh.base_colour = Vec3(0.1, 0.2, 0.3);
    const Result<CleanedModel> cleaned = clean_model(soup.mesh);
    ASSERT_TRUE(cleaned.ok);
    EXPECT_TRUE(cleaned.value.mesh.colours.empty());
    EXPECT_TRUE(cleaned.value.mesh.uvs.empty());
    EXPECT_TRUE(cleaned.value.mesh.texture.empty());
    EXPECT_EQ(cleaned.value.mesh.base_colour, Vec3(0.1, 0.2, 0.3));
}
