// Binding of the model input steps (load_model, clean_model, fit_metrics): conversions only.
#include <cmath>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "binding_support.hpp"
#include "point_rows.hpp"
#include "popup/fitting/fit_metrics.hpp"
#include "popup/input/clean_model.hpp"
#include "popup/input/load_model.hpp"

namespace py = pybind11;
using namespace popup;
using namespace popup::bindings;

namespace {

py::dict repairs_dict(const RepairCounts& r)
{
    return py::dict(py::arg("duplicate_points_merged") = r.duplicate_points_merged,
                    py::arg("degenerate_faces_removed") = r.degenerate_faces_removed,
                    py::arg("duplicate_faces_removed") = r.duplicate_faces_removed,
                    py::arg("faces_reoriented") = r.faces_reoriented,
                    py::arg("non_manifold_vertices_split") = r.non_manifold_vertices_split,
                    py::arg("isolated_vertices_removed") = r.isolated_vertices_removed,
                    py::arg("border_edges") = r.border_edges, py::arg("holes") = r.holes,
                    py::arg("closed") = r.closed);
}

py::dict stats_dict(const DistanceStats& s)
{
    return py::dict(py::arg("mean") = s.mean, py::arg("rms") = s.rms, py::arg("max") = s.max);
}

/// NaN (no volume for an open model) as None, so the dict writes as strict JSON.
py::object number_or_none(double x)
{
    return std::isnan(x) ? py::object(py::none()) : py::object(py::float_(x));
}

py::dict metrics_dict(const FitMetrics& m)
{
    py::dict d;
    d["diagonal_mm"] = m.diagonal_mm;
    d["hausdorff"] = py::dict(py::arg("model_to_popup") = stats_dict(m.model_to_popup),
                              py::arg("popup_to_model") = stats_dict(m.popup_to_model));
    d["hausdorff_mm"] = py::dict(py::arg("model_to_popup") = stats_dict(m.model_to_popup_mm),
                                 py::arg("popup_to_model") = stats_dict(m.popup_to_model_mm));
    d["volume_difference"] = number_or_none(m.volume_difference);
    d["model_volume_mm3"] = number_or_none(m.model_volume_mm3);
    d["popup_volume_mm3"] = m.popup_volume_mm3;
    d["coverage"] = m.coverage;
    d["model_closed"] = m.model_closed;
    return d;
}

} // namespace

void bind_model_input(py::module_& m)
{
    m.def(
        "load_model",
        [](const std::string& path) {
            Result<ModelMesh> r;
            {
                py::gil_scoped_release release;
                r = load_model(path);
            }
            const Diagnostics warnings = r.diagnostics;
            py::object mesh = py::cast(bindings::unwrap(std::move(r)));
            mesh.attr("warnings") = bindings::diagnostic_list(warnings);
            return mesh;
        },
        py::arg("path"),
        "Reads a mesh file through assimp (OBJ, STL, PLY, OFF, glTF/GLB, FBX, Collada, 3MF, ...) "
        "into one ModelMesh with node transforms applied, triangulated, identical vertices "
        "joined, with vertex colours, texture coordinates and texture where the file has them. "
        "DesignError (unreadable_model, then check_model's codes) names the file and the reason; "
        "the mesh's .warnings lists a texture that cannot be read (unreadable_texture), the mesh "
        "loading all the same.");
    m.def(
        "clean_model",
        [](const ModelMesh& mesh) {
            CleanedModel cleaned;
            {
                py::gil_scoped_release release;
                cleaned = bindings::unwrap(clean_model(mesh));
            }
            return py::make_tuple(cleaned.mesh, repairs_dict(cleaned.repairs));
        },
        py::arg("mesh"),
        "(cleaned ModelMesh, repair counts dict): CGAL PMP soup repair, orientation (outward when "
        "closed), degenerate faces and non-manifold vertices. The cleaned mesh has no colours, "
        "uvs or texture; keys: duplicate_points_merged, degenerate_faces_removed, "
        "duplicate_faces_removed, faces_reoriented, non_manifold_vertices_split, "
        "isolated_vertices_removed, border_edges, holes, closed.");
    m.def(
        "fit_metrics",
        [](const ModelMesh& model, const Eigen::Matrix4d& model_to_card, const Scaffold& scaffold,
           const std::vector<Rows3d>& prisms, double threshold_mm, int samples,
           std::uint64_t seed) {
            std::vector<std::vector<Vec3>> corners;
            for (const Rows3d& p : prisms)
                corners.push_back(points_of(p));
            FitMetricsOptions options;
            options.threshold_mm = threshold_mm;
            options.samples = samples;
            options.seed = seed;
            FitMetrics metrics;
            {
                py::gil_scoped_release release;
                metrics =
                    bindings::unwrap(fit_metrics(model, model_to_card, scaffold, corners, options));
            }
            return metrics_dict(metrics);
        },
        py::arg("model"), py::arg("model_to_card"), py::arg("scaffold"), py::arg("prisms"),
        py::arg("threshold_mm"), py::arg("samples") = 20000, py::arg("seed") = 1,
        "Model (model units, taken to card mm by the 4x4 model_to_card) against the scaffold at "
        "180° and the union of the prisms (Nx3 corner arrays, card mm): Hausdorff max/mean/rms "
        "both ways, relative to the diagonal ('hausdorff') and in mm ('hausdorff_mm'), volume "
        "difference (None for an open model), coverage within threshold_mm (docs/MATH.md).");
}
