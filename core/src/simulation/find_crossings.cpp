// The CGAL translation unit: constrained triangulation of patches and exact predicates for
// triangle-triangle contact. No OCCT headers here (their Handle macro breaks CGAL).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/intersections.h>

#include "../geometry/polygon_2d.hpp"
#include "body_graph.hpp"
#include "crossing_test.hpp"

namespace popup {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
struct FaceInfo {
    int nesting = -1;
};
using FaceBase0 = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<K, FaceBase0>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

// Flood fill from the outside: faces behind an odd number of constraints are paper.
void mark_nesting(CDT& cdt)
{
    std::vector<std::pair<CDT::Face_handle, int>> stack{{cdt.infinite_face(), 0}};
    while (!stack.empty()) {
        auto [start, level] = stack.back();
        stack.pop_back();
        if (start->info().nesting != -1)
            continue;
        std::vector<CDT::Face_handle> region{start};
        start->info().nesting = level;
        while (!region.empty()) {
            CDT::Face_handle f = region.back();
            region.pop_back();
            for (int e = 0; e < 3; ++e) {
                CDT::Face_handle n = f->neighbor(e);
                if (n->info().nesting != -1)
                    continue;
                if (cdt.is_constrained({f, e}))
                    stack.push_back({n, level + 1});
                else {
                    n->info().nesting = level;
                    region.push_back(n);
                }
            }
        }
    }
}

PatchMesh mesh_patch(const Patch& p)
{
    PatchMesh mesh;
    std::vector<Loop3> loops{p.outer};
    loops.insert(loops.end(), p.holes.begin(), p.holes.end());
    // All vertices at once (spatially sorted by CGAL), then the edges as constraints: inserting
    // long runs of collinear outline points one by one costs O(n²) flips.
    std::vector<std::pair<K::Point_2, int>> points;
    for (const Loop3& loop : loops) {
        const int first = int(mesh.vertices.size());
        for (const Vec3& x : loop) {
            const Vec2 q = p.to_local(x);
            points.push_back({K::Point_2(q.x(), q.y()), int(mesh.vertices.size())});
            mesh.vertices.push_back(x);
        }
        const int n = int(loop.size());
        for (int k = 0; k < n; ++k)
            mesh.edges.push_back({first + k, first + (k + 1) % n});
    }
    CDT cdt;
    cdt.insert(points.begin(), points.end());
    std::vector<CDT::Vertex_handle> handles(mesh.vertices.size());
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
        handles[v->info()] = v;
    for (const CDT::Vertex_handle& v : handles)
        if (v == CDT::Vertex_handle()) // two loop points coincide: validation refuses that
            throw std::invalid_argument("patch " + std::to_string(p.id) +
                                        ": two of its loop points coincide");
    for (const auto& [a, b] : mesh.edges)
        cdt.insert_constraint(handles[a], handles[b]);
    mark_nesting(cdt);
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
        if (f->info().nesting % 2 == 1)
            mesh.triangles.push_back(
                {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
    return mesh;
}

K::Point_3 to_cgal(const Vec3& x)
{
    return {x.x(), x.y(), x.z()};
}

// Positions along the planes' common line where the boundary of a patch crosses the other plane,
// paired into the chords the patch cuts from that line (even-odd).
std::vector<double> chord_ends(const PatchMesh& mesh, const std::vector<Vec3>& posed,
                               const std::vector<double>& side, const Vec3& line)
{
    std::vector<double> ends;
    for (const auto& e : mesh.edges) {
        const double a = side[e[0]], b = side[e[1]];
        if ((a >= 0.0) == (b >= 0.0))
            continue;
        const Vec3 x = posed[e[0]] + (posed[e[1]] - posed[e[0]]) * (a / (a - b));
        ends.push_back(x.dot(line));
    }
    std::sort(ends.begin(), ends.end());
    return ends;
}

double overlap_length(const std::vector<double>& a, const std::vector<double>& b)
{
    double total = 0.0;
    for (size_t i = 0; i + 1 < a.size(); i += 2)
        for (size_t j = 0; j + 1 < b.size(); j += 2)
            total += std::max(0.0, std::min(a[i + 1], b[j + 1]) - std::max(a[i], b[j]));
    return total;
}

bool triangles_meet(const PatchMesh& a, const std::vector<Vec3>& pa, const PatchMesh& b,
                    const std::vector<Vec3>& pb)
{
    for (const auto& s : a.triangles) {
        const K::Triangle_3 ta(to_cgal(pa[s[0]]), to_cgal(pa[s[1]]), to_cgal(pa[s[2]]));
        if (ta.is_degenerate())
            continue;
        for (const auto& t : b.triangles) {
            const K::Triangle_3 tb(to_cgal(pb[t[0]]), to_cgal(pb[t[1]]), to_cgal(pb[t[2]]));
            if (!tb.is_degenerate() && CGAL::do_intersect(ta, tb))
                return true;
        }
    }
    return false;
}

// Distance from x to the segment ab (3D).
double distance_to_segment_3d(const Vec3& x, const Vec3& a, const Vec3& b)
{
    const Vec3 ab = b - a;
    const double t = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (a + t * ab - x).norm();
}

// How far a vertex of patch a comes inside `clearance` of the inside of patch b. Vertices on a
// hinge the two patches share touch by design and are left out.
double proximity_depth(const PatchMesh& mesh_a, const std::vector<Vec3>& va, const Patch& pb,
                       const Pose& pose_b, const std::vector<double>& side, double clearance,
                       const std::vector<const Hinge*>& shared, double tolerance)
{
    double deepest = 0.0;
    const Mat3 back = pose_b.rotation.transpose();
    for (size_t k = 0; k < va.size(); ++k) {
        if (std::abs(side[k]) >= clearance)
            continue;
        const bool on_hinge = std::any_of(shared.begin(), shared.end(), [&](const Hinge* h) {
            return distance_to_segment_3d(mesh_a.vertices[k], h->from, h->to) <= tolerance;
        });
        if (on_hinge)
            continue;
        const Vec2 q = pb.to_local(back * (va[k] - pose_b.translation));
        if (point_in_polygon_or_near(pb.outer_local(), q, -clearance))
            deepest = std::max(deepest, clearance - std::abs(side[k]));
    }
    return deepest;
}

} // namespace

std::vector<PatchMesh> mesh_patches(const Scaffold& scaffold)
{
    std::vector<PatchMesh> meshes;
    for (const Patch& p : scaffold.patches) {
        try {
            meshes.push_back(mesh_patch(p));
        } catch (const CGAL::Failure_exception& e) {
            // Keep CGAL's exception family (the bindings map it) but say which patch failed.
            throw CGAL::Failure_exception(e.library(), e.expression(), e.filename(),
                                          e.line_number(),
                                          "patch " + std::to_string(p.id) +
                                              ": cannot triangulate its outline; are its loops "
                                              "self-intersecting? " +
                                              e.message());
        }
    }
    return meshes;
}

void pose_patches(const std::vector<PatchMesh>& meshes, const FoldState& state, PosedPatches& posed,
                  const std::vector<int>& only)
{
    posed.state = &state;
    posed.vertices.resize(meshes.size());
    for (std::vector<Vec3>& v : posed.vertices)
        v.clear();
    auto pose = [&](size_t i) {
        std::vector<Vec3>& out = posed.vertices[i];
        out.reserve(meshes[i].vertices.size());
        for (const Vec3& x : meshes[i].vertices)
            out.push_back(state.poses[i].apply(x));
    };
    if (only.empty())
        for (size_t i = 0; i < meshes.size(); ++i)
            pose(i);
    else
        for (int i : only)
            pose(size_t(i));
}

std::vector<std::array<int, 2>>
candidate_pairs(const PosedPatches& posed, const std::vector<int>& body_of_patch, double margin)
{
    const int n = int(posed.vertices.size());
    std::vector<Eigen::AlignedBox3d> boxes(n);
    for (int i = 0; i < n; ++i) {
        for (const Vec3& x : posed.vertices[i])
            boxes[i].extend(x);
        boxes[i].min().array() -= margin;
        boxes[i].max().array() += margin;
    }
    // Sweep and prune along the axis the boxes spread most on (mechanisms line the fold).
    Eigen::AlignedBox3d centres;
    for (const auto& box : boxes)
        centres.extend(box.center());
    int axis = 0;
    centres.diagonal().maxCoeff(&axis);
    std::vector<int> order(n);
    for (int i = 0; i < n; ++i)
        order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return boxes[a].min()[axis] < boxes[b].min()[axis]; });
    std::vector<std::array<int, 2>> pairs;
    for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b) {
            const int i = order[a], j = order[b];
            if (boxes[j].min()[axis] > boxes[i].max()[axis])
                break;
            if (body_of_patch[i] != body_of_patch[j] && boxes[i].intersects(boxes[j]))
                pairs.push_back({std::min(i, j), std::max(i, j)});
        }
    return pairs;
}

void side_of_plane(const PosedPatches& posed, const Scaffold& scaffold, int i, int j,
                   std::vector<double>& side)
{
    const Pose& pj = posed.state->poses[j];
    const Vec3 normal = pj.rotation * scaffold.patches[j].normal;
    const Vec3 origin = pj.apply(scaffold.patches[j].origin);
    side.clear();
    for (const Vec3& x : posed.vertices[i])
        side.push_back((x - origin).dot(normal));
}

double crossing_depth(const std::vector<PatchMesh>& meshes, const PosedPatches& posed,
                      const Scaffold& scaffold, int i, int j, double tolerance, double clearance)
{
    const FoldState& state = *posed.state;
    auto straddle = [](const std::vector<double>& d) {
        const auto [lo, hi] = std::minmax_element(d.begin(), d.end());
        return std::min(*hi, -*lo);
    };
    // Per thread, reused: the validity check calls this for every candidate pair and sample.
    thread_local std::vector<double> di, dj;
    side_of_plane(posed, scaffold, i, j, di);
    // Most pairs do not even reach each other's plane: stop before any further work.
    if (clearance <= 0.0 && straddle(di) <= tolerance)
        return 0.0;
    side_of_plane(posed, scaffold, j, i, dj);
    const std::vector<Vec3>& vi = posed.vertices[i];
    const std::vector<Vec3>& vj = posed.vertices[j];
    double near = 0.0;
    if (clearance > 0.0) {
        const Vec3 ni = state.poses[i].rotation * scaffold.patches[i].normal;
        const Vec3 nj = state.poses[j].rotation * scaffold.patches[j].normal;
        std::vector<const Hinge*> shared;
        for (const Hinge& h : scaffold.hinges)
            if ((h.patch_a == scaffold.patches[i].id && h.patch_b == scaffold.patches[j].id) ||
                (h.patch_a == scaffold.patches[j].id && h.patch_b == scaffold.patches[i].id))
                shared.push_back(&h);
        if (ni.cross(nj).norm() > 0.02) // transversal approach only: stacking is allowed
            near = std::max(proximity_depth(meshes[i], vi, scaffold.patches[j], state.poses[j], di,
                                            clearance, shared, tolerance),
                            proximity_depth(meshes[j], vj, scaffold.patches[i], state.poses[i], dj,
                                            clearance, shared, tolerance));
    }
    const double depth = std::min(straddle(di), straddle(dj));
    if (depth <= tolerance)
        return near;
    const Vec3 line = (state.poses[i].rotation * scaffold.patches[i].normal)
                          .cross(state.poses[j].rotation * scaffold.patches[j].normal);
    if (line.norm() < 1e-12)
        return near;
    const Vec3 dir = line.normalized();
    const double overlap =
        overlap_length(chord_ends(meshes[i], vi, di, dir), chord_ends(meshes[j], vj, dj, dir));
    if (overlap <= tolerance)
        return near;
    // The exact predicate has the last word on whether the two patches meet at all.
    return triangles_meet(meshes[i], vi, meshes[j], vj) ? std::max(depth, near) : near;
}

} // namespace popup
