// Binding of the preview rasteriser (core sheets/render_view): numpy in, an RGBA array out.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "binding_support.hpp"
#include "point_rows.hpp"
#include "popup/sheets/render_view.hpp"

namespace py = pybind11;
using namespace popup;

namespace {

using Rows3i = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;

ViewMesh mesh_of(const py::tuple& t)
{
    if (t.size() != 3)
        throw py::value_error("render_view: a mesh is (vertices Nx3, triangles Mx3, colour RGB)");
    ViewMesh mesh;
    mesh.vertices = bindings::points_of(t[0].cast<bindings::Rows3d>());
    const Rows3i triangles = t[1].cast<Rows3i>();
    mesh.triangles.resize(triangles.rows());
    for (Eigen::Index i = 0; i < triangles.rows(); ++i)
        mesh.triangles[i] = {triangles(i, 0), triangles(i, 1), triangles(i, 2)};
    mesh.colour = t[2].cast<Vec3>();
    return mesh;
}

ViewPolygon polygon_of(const py::tuple& t)
{
    if (t.size() != 3)
        throw py::value_error(
            "render_view: a polygon is (loops: list of Kx3, colour RGB, outlined bool)");
    ViewPolygon polygon;
    for (const py::handle& loop : t[0].cast<py::list>())
        polygon.loops.push_back(bindings::points_of(loop.cast<bindings::Rows3d>()));
    polygon.colour = t[1].cast<Vec3>();
    polygon.outlined = t[2].cast<bool>();
    return polygon;
}

} // namespace

void bind_render_view(py::module_& m)
{
    const ViewCamera d;
    m.def(
        "render_view",
        [](const py::list& meshes, const py::list& polygons, const Vec3& towards_eye,
           const Vec3& up, const Vec3& centre, double mm_per_pixel, int width, int height,
           const Vec3& light, double ambient, const Vec3& background, const Vec3& edge_colour,
           double edge_px, int supersample) {
            std::vector<ViewMesh> scene_meshes;
            for (const py::handle& h : meshes)
                scene_meshes.push_back(mesh_of(h.cast<py::tuple>()));
            std::vector<ViewPolygon> scene_polygons;
            for (const py::handle& h : polygons)
                scene_polygons.push_back(polygon_of(h.cast<py::tuple>()));
            ViewCamera camera{towards_eye, up,      centre,     mm_per_pixel, width,   height,
                              light,       ambient, background, edge_colour,  edge_px, supersample};
            Result<RgbaImage> r;
            {
                py::gil_scoped_release release;
                r = render_view(scene_meshes, scene_polygons, camera);
            }
            if (!r.ok)
                throw bindings::DesignFailure(r.diagnostics);
            py::array_t<std::uint8_t> out(
                {py::ssize_t(r.value.height), py::ssize_t(r.value.width), py::ssize_t(4)});
            std::copy(r.value.pixels.begin(), r.value.pixels.end(), out.mutable_data());
            return out;
        },
        py::arg("meshes"), py::arg("polygons"), py::arg("towards_eye") = d.towards_eye,
        py::arg("up") = d.up, py::arg("centre") = d.centre,
        py::arg("mm_per_pixel") = d.mm_per_pixel, py::arg("width") = d.width,
        py::arg("height") = d.height, py::arg("light") = d.light, py::arg("ambient") = d.ambient,
        py::arg("background") = d.background, py::arg("edge_colour") = d.edge_colour,
        py::arg("edge_px") = d.edge_px, py::arg("supersample") = d.supersample,
        "Orthographic z-buffer picture of triangle meshes (vertices Nx3, triangles Mx3, colour "
        "RGB in [0, 1]) and planar polygons (loops: outline then holes, each Kx3; colour; "
        "outlined), flat-shaded colour x (ambient + (1 - ambient) |n . light|). The image centre "
        "shows `centre`, `up` points up, mm_per_pixel > 0, width and height in 1..8192, edge_px "
        "in [0, 16] (pixels of the result), supersample in 1..4 (drawn that many times finer, "
        "averaged). Returns height x width x 4 uint8, row 0 at the top, alpha 0 on the "
        "background. DesignError names a bad value and its range.");
}
