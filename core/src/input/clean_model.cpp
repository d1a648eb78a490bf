// CGAL translation unit: polygon-soup repair and orientation of a model (CGAL PMP).
#include "popup/input/clean_model.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
// GCC 14 (Debian 13) reports a memmove out of bounds (-Warray-bounds, -Wstringop-overflow) where
// CGAL's duplicate-polygon search (collect_duplicate_polygons) copies a polygon's std::vector:
// a false positive of the inliner's range analysis. Only the polygon-soup repair's headers are
// exempt: GCC honours the pragma at the inlined call sites inside them.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 14
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Warray-bounds"
#pragma GCC diagnostic ignored "-Wstringop-overflow"
#endif
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 14
#pragma GCC diagnostic pop
#endif
#include <CGAL/version_macros.h>
// CGAL 6.2 (Debian sid) moved the border functions from PMP to CGAL/boost/graph.
#if CGAL_VERSION_MAJOR > 6 || (CGAL_VERSION_MAJOR == 6 && CGAL_VERSION_MINOR >= 2)
#define POPUP_CGAL_GRAPH_BORDER 1
#include <CGAL/boost/graph/border.h>
#else
#include <CGAL/Polygon_mesh_processing/border.h>
#endif
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

namespace popup {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Polygon = std::vector<std::size_t>;

/// A triangle by its corner positions, independent of point numbering: the sorted corners, and
/// whether the winding visits them in sorted cyclic order.
struct Winding {
    std::array<Point, 3> corners;
    bool sorted_order;
};

Winding winding_of(std::array<Point, 3> c)
{
    // Rotate the smallest corner first; the winding is then fixed by the order of the other two.
    const auto first = std::min_element(c.begin(), c.end()) - c.begin();
    std::rotate(c.begin(), c.begin() + first, c.end());
    const bool ascending = c[1] < c[2];
    if (!ascending)
        std::swap(c[1], c[2]);
    return {c, ascending};
}

std::array<Point, 3> corners_of(const Mesh& mesh, Mesh::Face_index f)
{
    std::array<Point, 3> c;
    int k = 0;
    for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
        c[k++] = mesh.point(v);
    return c;
}

double area_of(const std::array<Point, 3>& c)
{
    return std::sqrt(CGAL::to_double(CGAL::squared_area(c[0], c[1], c[2])));
}

/// Faces of the mesh whose winding differs from the input's same triangle (by corner
/// positions), and their total area; faces changed by degenerate-face removal have no match.
std::pair<int, double> reversed_faces(const Mesh& mesh,
                                      const std::map<std::array<Point, 3>, bool>& input)
{
    int count = 0;
    double area = 0.0;
    for (Mesh::Face_index f : mesh.faces()) {
        const std::array<Point, 3> c = corners_of(mesh, f);
        const Winding w = winding_of(c);
        const auto found = input.find(w.corners);
        if (found != input.end() && found->second != w.sorted_order) {
            ++count;
            area += area_of(c);
        }
    }
    return {count, area};
}

// The soup steps of PMP::repair_polygon_soup, one at a time so that each repair is counted.
void repair_soup(std::vector<Point>& points, std::vector<Polygon>& polygons, RepairCounts& counts)
{
    counts.duplicate_points_merged =
        int(PMP::merge_duplicate_points_in_polygon_soup(points, polygons));
    PMP::internal::simplify_polygons_in_polygon_soup(points, polygons, Kernel());
    counts.degenerate_faces_removed =
        int(PMP::internal::remove_invalid_polygons_in_polygon_soup(points, polygons));
    counts.duplicate_faces_removed =
        int(PMP::merge_duplicate_polygons_in_polygon_soup(points, polygons));
    counts.isolated_vertices_removed =
        int(PMP::remove_isolated_points_in_polygon_soup(points, polygons));
}

int boundary_cycles(const Mesh& mesh)
{
    std::vector<Mesh::Halfedge_index> cycles;
#ifdef POPUP_CGAL_GRAPH_BORDER
    CGAL::extract_boundary_cycles(mesh, std::back_inserter(cycles));
#else
    PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
#endif
    return int(cycles.size());
}

} // namespace

Result<CleanedModel> clean_model(const ModelMesh& model)
{
    Result<CleanedModel> result;
    const Result<ModelMesh> checked = check_model(model);
    if (!checked.ok) {
        result.fail_with(checked.diagnostics);
        return result;
    }
    RepairCounts& counts = result.value.repairs;

    std::vector<Point> points;
    points.reserve(model.vertices.size());
    for (const Vec3& v : model.vertices)
        points.emplace_back(v.x(), v.y(), v.z());
    std::vector<Polygon> polygons;
    polygons.reserve(model.triangles.size());
    for (const auto& t : model.triangles)
        polygons.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});

    repair_soup(points, polygons, counts);

    // The input winding of every surviving triangle, to count what orientation reverses.
    std::map<std::array<Point, 3>, bool> input_winding;
    double total_area = 0.0;
    for (const Polygon& p : polygons) {
        const std::array<Point, 3> c = {points[p[0]], points[p[1]], points[p[2]]};
        const Winding w = winding_of(c);
        input_winding.emplace(w.corners, w.sorted_order);
        total_area += area_of(c);
    }

    const std::size_t before_orient = points.size();
    PMP::orient_polygon_soup(points, polygons);
    counts.non_manifold_vertices_split = int(points.size() - before_orient);
    Mesh mesh;
    PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);

    const std::size_t faces_before = mesh.number_of_faces();
    PMP::remove_degenerate_faces(mesh);
    mesh.collect_garbage();
    counts.degenerate_faces_removed += int(faces_before - mesh.number_of_faces());
    counts.non_manifold_vertices_split += int(PMP::duplicate_non_manifold_vertices(mesh));
    counts.isolated_vertices_removed += int(PMP::remove_isolated_vertices(mesh));
    mesh.collect_garbage();
    if (mesh.number_of_faces() == 0) {
        result.fail(DiagnosticCode::degenerate_model,
                    (model.source.empty() ? std::string("model") : model.source) +
                        ": no face with an area is left after cleaning (" +
                        std::to_string(model.triangles.size()) + " triangles given)");
        return result;
    }

    counts.closed = CGAL::is_closed(mesh);
    if (counts.closed) {
        PMP::orient_to_bound_a_volume(mesh);
    } else if (reversed_faces(mesh, input_winding).second > 0.5 * total_area) {
        // An open surface has no inside: keep the winding most of its input area had.
        PMP::reverse_face_orientations(mesh);
    }
    counts.faces_reoriented = reversed_faces(mesh, input_winding).first;
    for (Mesh::Halfedge_index h : mesh.halfedges())
        counts.border_edges += mesh.is_border(h) ? 1 : 0;
    counts.holes = boundary_cycles(mesh);

    ModelMesh& out = result.value.mesh;
    out.source = model.source;
    out.base_colour = model.base_colour;
    for (Mesh::Vertex_index v : mesh.vertices()) {
        const Point& p = mesh.point(v);
        out.vertices.emplace_back(p.x(), p.y(), p.z());
    }
    for (Mesh::Face_index f : mesh.faces()) {
        std::array<int, 3> t;
        int k = 0;
        for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
            t[k++] = int(v);
        out.triangles.push_back(t);
    }
    return result;
}

} // namespace popup
