// Binding of ModelMesh, the model every fitting step takes: declarations and conversions only.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "binding_support.hpp"
#include "point_rows.hpp"
#include "popup/input/model_mesh.hpp"

namespace py = pybind11;
using namespace popup;
using namespace popup::bindings;

namespace {

using Rows3i = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;
} // namespace

void bind_model_mesh(py::module_& m)
{
    // dynamic_attr: load_model hangs its warnings on the mesh it returns (.warnings).
    py::class_<ModelMesh>(m, "ModelMesh", py::dynamic_attr(),
                          "A triangle mesh given as the model of a pop-up (model units taken as "
                          "mm); colours and texture coordinates are per vertex")
        .def(py::init([](const Rows3d& vertices, const Rows3i& triangles, std::string source) {
                 ModelMesh mesh;
                 mesh.vertices = points_of(vertices);
                 mesh.triangles.resize(triangles.rows());
                 for (Eigen::Index i = 0; i < triangles.rows(); ++i)
                     mesh.triangles[i] = {triangles(i, 0), triangles(i, 1), triangles(i, 2)};
                 mesh.source = std::move(source);
                 return mesh;
             }),
             py::arg("vertices"), py::arg("triangles"), py::arg("source") = "")
        .def_property(
            "vertices", [](const ModelMesh& mesh) { return rows_of(mesh.vertices); },
            [](ModelMesh& mesh, const Rows3d& v) { mesh.vertices = points_of(v); })
        .def_property(
            "triangles",
            [](const ModelMesh& mesh) {
                Rows3i t(mesh.triangles.size(), 3);
                for (size_t i = 0; i < mesh.triangles.size(); ++i)
                    t.row(i) << mesh.triangles[i][0], mesh.triangles[i][1], mesh.triangles[i][2];
                return t;
            },
            [](ModelMesh& mesh, const Rows3i& t) {
                mesh.triangles.resize(t.rows());
                for (Eigen::Index i = 0; i < t.rows(); ++i)
                    mesh.triangles[i] = {t(i, 0), t(i, 1), t(i, 2)};
            })
        .def_property(
            "colours", [](const ModelMesh& mesh) { return rows_of(mesh.colours); },
            [](ModelMesh& mesh, const Rows3d& c) { mesh.colours = points_of(c); },
            "RGB in [0, 1], one row per vertex, or no rows")
        .def_property(
            "uvs",
            [](const ModelMesh& mesh) {
                Rows2d uv(mesh.uvs.size(), 2);
                for (size_t i = 0; i < mesh.uvs.size(); ++i)
                    uv.row(i) = mesh.uvs[i].transpose();
                return uv;
            },
            [](ModelMesh& mesh, const Rows2d& uv) {
                mesh.uvs.resize(uv.rows());
                for (Eigen::Index i = 0; i < uv.rows(); ++i)
                    mesh.uvs[i] = uv.row(i).transpose();
            },
            "texture coordinates, one row per vertex, or no rows")
        .def_readwrite("texture", &ModelMesh::texture, "path of the base colour image, or ''")
        .def_property(
            "texture_bytes",
            [](const ModelMesh& mesh) {
                return py::bytes(reinterpret_cast<const char*>(mesh.texture_bytes.data()),
                                 mesh.texture_bytes.size());
            },
            [](ModelMesh& mesh, const py::bytes& b) {
                const std::string s = b;
                mesh.texture_bytes.assign(s.begin(), s.end());
            },
            "an embedded texture: the image file's bytes, or raw RGBA8 texels when "
            "texture_width > 0; b'' when the texture is a file")
        .def_readwrite("texture_format", &ModelMesh::texture_format,
                       "extension of the embedded image ('png', 'jpg') or 'rgba8888'")
        .def_readwrite("texture_width", &ModelMesh::texture_width)
        .def_readwrite("texture_height", &ModelMesh::texture_height)
        .def_readwrite("base_colour", &ModelMesh::base_colour)
        .def_readwrite("source", &ModelMesh::source, "file or object name, for messages")
        .def(
            "copy", [](const ModelMesh& mesh) { return ModelMesh(mesh); },
            "An independent copy of the mesh (not of its Python attributes, such as .warnings)")
        .def("area", &ModelMesh::area)
        .def("diagonal", &ModelMesh::diagonal, "bounding-box diagonal (model units)")
        .def("__repr__", [](const ModelMesh& mesh) {
            return "<ModelMesh " + mesh.source + ": " + std::to_string(mesh.vertices.size()) +
                   " vertices, " + std::to_string(mesh.triangles.size()) + " triangles>";
        });
    m.def(
        "check_model",
        [](ModelMesh mesh) { return bindings::unwrap(check_model(std::move(mesh))); },
        py::arg("mesh"),
        "The mesh unchanged, or DesignError naming what makes it unusable (no triangles, a "
        "non-finite coordinate, a bad index, no extent or area, a size outside 1e-6..1e6)");
}
