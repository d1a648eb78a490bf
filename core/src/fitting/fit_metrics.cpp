// CGAL translation unit: distances, coverage and volume difference between a model and a pop-up.
#include "popup/fitting/fit_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <future>
#include <list>
#include <random>
#include <sstream>

#include <CGAL/version_macros.h>
// CGAL 6.0 (Debian 13) renamed the 3D AABB traits and primitive, adding _3; 5.x has only the old.
#if CGAL_VERSION_MAJOR >= 6
#include <CGAL/AABB_traits_3.h>
#include <CGAL/AABB_triangle_primitive_3.h>
#else
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_triangle_primitive.h>
#endif
#include <CGAL/AABB_tree.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/convex_hull_3.h>

#include "popup/simulation/simulate_fold.hpp"

namespace popup {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Triangles = std::vector<Triangle>;
#if CGAL_VERSION_MAJOR >= 6
using Primitive = CGAL::AABB_triangle_primitive_3<Kernel, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits_3<Kernel, Primitive>>;
#else
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
#endif

// A constrained Delaunay triangulation whose faces know how many outlines enclose them: odd
// means inside the patch (the outer loop), even means outside or in a hole.
struct Nesting {
    int level = -1;
};
using Vb = CGAL::Triangulation_vertex_base_2<Kernel>;
using Fb = CGAL::Constrained_triangulation_face_base_2<
    Kernel, CGAL::Triangulation_face_base_with_info_2<Nesting, Kernel>>;
using Cdt =
    CGAL::Constrained_Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<Vb, Fb>,
                                               CGAL::Exact_predicates_tag>;

Point point(const Vec3& v)
{
    return Point(v.x(), v.y(), v.z());
}

/// Flood fill from the infinite face: crossing a constrained edge enters the next level.
void mark_nesting(Cdt& cdt)
{
    std::list<Cdt::Edge> borders;
    auto fill = [&](Cdt::Face_handle start, int level) {
        std::list<Cdt::Face_handle> queue{start};
        while (!queue.empty()) {
            Cdt::Face_handle f = queue.front();
            queue.pop_front();
            if (f->info().level != -1)
                continue;
            f->info().level = level;
            for (int i = 0; i < 3; ++i) {
                Cdt::Face_handle n = f->neighbor(i);
                if (n->info().level != -1)
                    continue;
                if (cdt.is_constrained(Cdt::Edge(f, i)))
                    borders.push_back(Cdt::Edge(f, i));
                else
                    queue.push_back(n);
            }
        }
    };
    fill(cdt.infinite_face(), 0);
    while (!borders.empty()) {
        const Cdt::Edge e = borders.front();
        borders.pop_front();
        Cdt::Face_handle n = e.first->neighbor(e.second);
        if (n->info().level == -1)
            fill(n, e.first->info().level + 1);
    }
}

/// The patch's area (outline minus holes) as triangles, posed.
void triangulate_patch(Patch patch, const Pose& pose, Triangles& out)
{
    if (patch.outer.size() < 3 || !std::isfinite(patch.derive_frame()) || patch.area() <= 0.0)
        return;
    Cdt cdt;
    auto insert_loop = [&](const Loop2& loop) {
        std::vector<Cdt::Point> ring;
        for (const Vec2& p : loop)
            ring.emplace_back(p.x(), p.y());
        cdt.insert_constraint(ring.begin(), ring.end(), true);
    };
    insert_loop(patch.outer_local());
    for (const Loop2& hole : patch.holes_local())
        insert_loop(hole);
    mark_nesting(cdt);
    auto lift = [&](const Cdt::Point& q) {
        return point(pose.apply(patch.origin + q.x() * patch.u + q.y() * patch.v));
    };
    for (Cdt::Face_handle f : cdt.finite_face_handles())
        if (f->info().level % 2 == 1)
            out.emplace_back(lift(f->vertex(0)->point()), lift(f->vertex(1)->point()),
                             lift(f->vertex(2)->point()));
}

/// A triangle mesh of unconnected triangles: what CGAL's Hausdorff distance needs, whatever the
/// triangles' connectivity.
Mesh mesh_of(const Triangles& triangles)
{
    Mesh mesh;
    for (const Triangle& t : triangles)
        mesh.add_face(mesh.add_vertex(t[0]), mesh.add_vertex(t[1]), mesh.add_vertex(t[2]));
    return mesh;
}

/// Uniform points on the triangles (area-weighted triangle choice, uniform barycentrics).
std::vector<Point> sample_surface(const Triangles& triangles, int count, std::mt19937_64& random)
{
    std::vector<double> cumulative;
    double total = 0.0;
    for (const Triangle& t : triangles)
        cumulative.push_back(total += std::sqrt(CGAL::to_double(t.squared_area())));
    // 53 random bits in [0, 1): the same numbers on every standard library.
    auto uniform = [&] { return double(random() >> 11) * 0x1.0p-53; };
    std::vector<Point> samples;
    samples.reserve(count);
    for (int i = 0; i < count; ++i) {
        const double at = uniform() * total;
        const size_t k = std::min<size_t>(
            std::upper_bound(cumulative.begin(), cumulative.end(), at) - cumulative.begin(),
            triangles.size() - 1);
        double a = uniform(), b = uniform();
        if (a + b > 1.0) {
            a = 1.0 - a;
            b = 1.0 - b;
        }
        const Triangle& t = triangles[k];
        samples.push_back(t[0] + a * (t[1] - t[0]) + b * (t[2] - t[0]));
    }
    return samples;
}

/// Mean and RMS of the samples' distances to the tree; `within` counts those <= threshold.
DistanceStats sampled_distances(const std::vector<Point>& samples, const Tree& tree,
                                double threshold, int* within = nullptr)
{
    double sum = 0.0, sum_sq = 0.0;
    int close = 0;
    for (const Point& p : samples) {
        const double d = std::sqrt(CGAL::to_double(tree.squared_distance(p)));
        sum += d;
        sum_sq += d * d;
        close += d <= threshold ? 1 : 0;
    }
    if (within)
        *within = close;
    DistanceStats s;
    s.mean = sum / double(samples.size());
    s.rms = std::sqrt(sum_sq / double(samples.size()));
    return s;
}

/// A convex prism as the outward planes of its corners' hull: inside when below every plane.
struct ConvexCell {
    std::vector<Kernel::Plane_3> planes;
    CGAL::Bbox_3 box;
    bool contains(const Point& p) const
    {
        for (const auto& plane : planes)
            if (plane.has_on_positive_side(p))
                return false;
        return true;
    }
};

DistanceStats relative(const DistanceStats& s, double diagonal)
{
    return {s.mean / diagonal, s.rms / diagonal, s.max / diagonal};
}

/// The fitted prisms as convex cells (their hulls' face planes), for the volume; refused, naming
/// the prism, when a corner is not finite or the corners span no volume.
Result<std::vector<ConvexCell>> prism_cells(const std::vector<std::vector<Vec3>>& prisms,
                                            double diagonal_mm)
{
    Result<std::vector<ConvexCell>> r;
    std::vector<ConvexCell>& cells = r.value;
    for (size_t i = 0; i < prisms.size(); ++i) {
        const std::string name = "prisms[" + std::to_string(i) + "]";
        std::vector<Point> corners;
        for (const Vec3& c : prisms[i]) {
            if (!c.allFinite()) {
                r.fail(DiagnosticCode::bad_option,
                       "fit metrics: " + name + " has a non-finite corner, corners must be finite",
                       about_parameter("prisms"));
                return r;
            }
            corners.push_back(point(c));
        }
        Mesh hull;
        if (corners.size() >= 4)
            CGAL::convex_hull_3(corners.begin(), corners.end(), hull);
        if (corners.size() < 4 || hull.number_of_faces() < 4 ||
            std::abs(PMP::volume(hull)) <= 1e-12 * std::pow(diagonal_mm, 3)) {
            r.fail(DiagnosticCode::bad_option,
                   "fit metrics: " + name + " has " + std::to_string(corners.size()) +
                       " corners spanning no volume, needs at least 4 not in one plane",
                   about_parameter("prisms"));
            return r;
        }
        ConvexCell cell;
        for (Mesh::Face_index f : hull.faces()) {
            const Mesh::Halfedge_index h = hull.halfedge(f);
            cell.planes.emplace_back(hull.point(hull.source(h)), hull.point(hull.target(h)),
                                     hull.point(hull.target(hull.next(h))));
        }
        cell.box = CGAL::bbox_3(corners.begin(), corners.end());
        cells.push_back(std::move(cell));
    }
    return r;
}

/// Volume: only a closed model has an inside. The model (`card_points`, its box [lo, hi]) and
/// the prisms' cells on one grid of `volume_cells` along its longest side; cell centres are
/// tested. Sets m's model_closed, volumes and volume difference; a model thinner than a cell
/// gets a warning instead.
void measure_volume(const ModelMesh& model, const std::vector<Point>& card_points, const Vec3& lo,
                    const Vec3& hi, const std::vector<ConvexCell>& cells, int volume_cells,
                    FitMetrics& m, Diagnostics& warnings)
{
    std::vector<std::vector<std::size_t>> polygons;
    for (const auto& t : model.triangles)
        polygons.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
    Mesh solid;
    if (PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
        PMP::polygon_soup_to_polygon_mesh(card_points, polygons, solid);
        m.model_closed = CGAL::is_closed(solid);
    }
    // The grid spans the model and the prisms; cell centres are tested.
    Vec3 grid_lo = lo, grid_hi = hi;
    for (const ConvexCell& cell : cells) {
        grid_lo = grid_lo.cwiseMin(Vec3(cell.box.xmin(), cell.box.ymin(), cell.box.zmin()));
        grid_hi = grid_hi.cwiseMax(Vec3(cell.box.xmax(), cell.box.ymax(), cell.box.zmax()));
    }
    const double h = (grid_hi - grid_lo).maxCoeff() / volume_cells;
    const Eigen::Vector3i n = ((grid_hi - grid_lo) / h).array().ceil().cast<int>().max(1).matrix();
    auto in_prisms = [&](const Point& p) {
        for (const ConvexCell& cell : cells)
            if (cell.contains(p))
                return true;
        return false;
    };
    std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, Kernel>> inside;
    if (m.model_closed) {
        m.model_volume_mm3 = std::abs(CGAL::to_double(PMP::volume(solid)));
        inside = std::make_unique<CGAL::Side_of_triangle_mesh<Mesh, Kernel>>(solid);
    }
    struct Counts {
        long in_model = 0, in_popup = 0, in_either_only = 0;
    };
    // Slabs of the grid along x; integer counts, so the halves add up to the same numbers.
    auto count_slab = [&](int i_begin, int i_end) {
        Counts c;
        for (int i = i_begin; i < i_end; ++i)
            for (int j = 0; j < n.y(); ++j)
                for (int k = 0; k < n.z(); ++k) {
                    const Point p(grid_lo.x() + (i + 0.5) * h, grid_lo.y() + (j + 0.5) * h,
                                  grid_lo.z() + (k + 0.5) * h);
                    // Outside the model's box no ray needs shooting.
                    const bool in_box = p.x() >= lo.x() && p.x() <= hi.x() && p.y() >= lo.y() &&
                                        p.y() <= hi.y() && p.z() >= lo.z() && p.z() <= hi.z();
                    const bool a = inside && in_box && (*inside)(p) == CGAL::ON_BOUNDED_SIDE;
                    const bool b = in_prisms(p);
                    c.in_model += a;
                    c.in_popup += b;
                    c.in_either_only += a != b;
                }
        return c;
    };
    if (inside) // its tree built once, before the two halves share it
        (*inside)(Point(lo.x(), lo.y(), lo.z()));
    std::future<Counts> first_half = std::async(std::launch::async, count_slab, 0, n.x() / 2);
    const Counts second = count_slab(n.x() / 2, n.x());
    const Counts first = first_half.get();
    const long in_model = first.in_model + second.in_model;
    const long in_popup = first.in_popup + second.in_popup;
    const long in_either_only = first.in_either_only + second.in_either_only;
    m.popup_volume_mm3 = double(in_popup) * h * h * h;
    if (m.model_closed && in_model > 0)
        m.volume_difference = double(in_either_only) / double(in_model);
    else if (m.model_closed)
        warnings.push_back(Diagnostic::warning(
            DiagnosticCode::bad_option,
            "fit metrics: the model is thinner than one grid cell (" + std::to_string(h) +
                " mm); raise volume_cells for a volume difference",
            about_parameter("volume_cells")));
}

} // namespace

Result<FitMetrics> fit_metrics(const ModelMesh& model, const Eigen::Matrix4d& model_to_card,
                               const Scaffold& design, const std::vector<std::vector<Vec3>>& prisms,
                               const FitMetricsOptions& options)
{
    Result<FitMetrics> result;
    auto refuse = [&](const std::string& parameter, const std::string& what) {
        result.fail(DiagnosticCode::bad_option, what, about_parameter(parameter));
        return result;
    };
    if (!(options.threshold_mm >= 0.0) || !std::isfinite(options.threshold_mm))
        return refuse("threshold_mm",
                      "fit metrics: threshold_mm = " + std::to_string(options.threshold_mm) +
                          ", must be a finite number >= 0");
    if (options.samples < 1 || options.samples > 10000000)
        return refuse("samples", "fit metrics: samples = " + std::to_string(options.samples) +
                                     ", must be in 1..10000000");
    if (!(options.hausdorff_error > 0.0 && options.hausdorff_error <= 0.1))
        return refuse("hausdorff_error",
                      "fit metrics: hausdorff_error = " + std::to_string(options.hausdorff_error) +
                          " of the diagonal, must be in (0, 0.1]");
    if (options.volume_cells < 2 || options.volume_cells > 1000)
        return refuse("volume_cells",
                      "fit metrics: volume_cells = " + std::to_string(options.volume_cells) +
                          ", must be in 2..1000");
    if (!model_to_card.allFinite() ||
        (model_to_card.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).norm() > 1e-12 ||
        std::abs(model_to_card.topLeftCorner<3, 3>().determinant()) < 1e-12) {
        std::ostringstream s;
        s << "fit metrics: model_to_card = ["
          << model_to_card.format(Eigen::IOFormat(6, 0, ", ", "; "))
          << "], must be a finite affine matrix (last row 0 0 0 1) with an invertible 3x3 part";
        return refuse("model_to_card", s.str());
    }
    const Result<ModelMesh> checked = check_model(model);
    if (!checked.ok) {
        result.fail_with(checked.diagnostics);
        return result;
    }

    // The model in card mm.
    const Eigen::Matrix3d linear = model_to_card.topLeftCorner<3, 3>();
    const Vec3 shift = model_to_card.topRightCorner<3, 1>();
    std::vector<Point> card_points;
    Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
    for (const Vec3& v : model.vertices) {
        const Vec3 p = linear * v + shift;
        card_points.push_back(point(p));
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    FitMetrics& m = result.value;
    m.diagonal_mm = (hi - lo).norm();
    Triangles model_triangles;
    for (const auto& t : model.triangles)
        model_triangles.emplace_back(card_points[t[0]], card_points[t[1]], card_points[t[2]]);

    // The pop-up at 180°: the stored state when that is the design angle, else simulated there.
    std::vector<Pose> poses(design.patches.size());
    if (std::abs(design.design_angle - M_PI) > 1e-9) {
        const Result<FoldSweep> sweep = simulate_fold(design, {M_PI});
        if (!sweep.ok || sweep.value.states.empty()) {
            result.fail_with(sweep.diagnostics);
            if (result.diagnostics.empty())
                result.fail(DiagnosticCode::motion_locked,
                            "fit metrics: " + design.name + " does not open to 180°");
            return result;
        }
        poses = sweep.value.states.front().poses;
    }
    Triangles all_patches, shape_patches;
    for (size_t i = 0; i < design.patches.size(); ++i) {
        const Patch& patch = design.patches[i];
        const size_t before = all_patches.size();
        triangulate_patch(patch, poses[i], all_patches);
        if (patch.id != design.ground && patch.id != design.backdrop)
            shape_patches.insert(shape_patches.end(), all_patches.begin() + before,
                                 all_patches.end());
    }
    if (shape_patches.empty()) {
        result.fail(DiagnosticCode::empty_scaffold,
                    "fit metrics: " + design.name +
                        " has no patch with an area besides the base patches");
        return result;
    }

    Result<std::vector<ConvexCell>> cells = prism_cells(prisms, m.diagonal_mm);
    if (!cells.ok) {
        result.fail_with(cells.diagnostics);
        return result;
    }

    // Distances both ways: the maximum by CGAL's bounded-error Hausdorff distance, mean and RMS
    // over uniform samples.
    const double error_bound = options.hausdorff_error * m.diagonal_mm;
    const Mesh model_mesh = mesh_of(model_triangles);
    const Mesh all_mesh = mesh_of(all_patches);
    const Mesh shape_mesh = mesh_of(shape_patches);
    Tree model_tree(model_triangles.begin(), model_triangles.end());
    Tree popup_tree(all_patches.begin(), all_patches.end());
    // Built here, before the lanes below share them (they would build lazily on first use).
    model_tree.build();
    popup_tree.build();
    model_tree.accelerate_distance_queries();
    popup_tree.accelerate_distance_queries();
    std::mt19937_64 random(options.seed);
    const std::vector<Point> model_samples =
        sample_surface(model_triangles, options.samples, random);
    const std::vector<Point> shape_samples = sample_surface(shape_patches, options.samples, random);
    // The four measures are independent: run side by side (two cores), each as it ran alone,
    // so the numbers are the same as one after the other.
    int covered = 0;
    auto model_side = std::async(std::launch::async, [&] {
        return sampled_distances(model_samples, popup_tree, options.threshold_mm, &covered);
    });
    auto model_max = std::async(std::launch::async, [&] {
        return PMP::bounded_error_Hausdorff_distance<CGAL::Sequential_tag>(model_mesh, all_mesh,
                                                                           error_bound);
    });
    auto shape_side = std::async(std::launch::async, [&] {
        return sampled_distances(shape_samples, model_tree, options.threshold_mm);
    });
    m.popup_to_model_mm.max = PMP::bounded_error_Hausdorff_distance<CGAL::Sequential_tag>(
        shape_mesh, model_mesh, error_bound);
    const double popup_max = m.popup_to_model_mm.max;
    m.model_to_popup_mm = model_side.get();
    m.model_to_popup_mm.max = model_max.get();
    m.popup_to_model_mm = shape_side.get();
    m.popup_to_model_mm.max = popup_max;
    m.model_to_popup = relative(m.model_to_popup_mm, m.diagonal_mm);
    m.popup_to_model = relative(m.popup_to_model_mm, m.diagonal_mm);
    m.coverage = double(covered) / double(model_samples.size());

    measure_volume(model, card_points, lo, hi, cells.value, options.volume_cells, m,
                   result.diagnostics);
    return result;
}

} // namespace popup
