// Binding of the artwork rasteriser (core sheets/render_artwork): declarations and conversions.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "binding_support.hpp"
#include "popup/sheets/render_artwork.hpp"

namespace py = pybind11;
using namespace popup;

namespace {

ArtworkOptions options_of(double pixels_per_mm, double depth, double behind, bool back_side,
                          const Vec3& light, double ambient, long long max_pixels)
{
    ArtworkOptions o;
    o.pixels_per_mm = pixels_per_mm;
    o.depth = depth;
    o.behind = behind;
    o.back_side = back_side;
    o.light = light;
    o.ambient = ambient;
    o.max_pixels = max_pixels;
    return o;
}

/// The artwork as a Python object carrying the model's warnings (an unreadable texture).
py::object with_warnings(PatchArtwork art, const Diagnostics& diagnostics)
{
    py::object out = py::cast(std::move(art));
    out.attr("warnings") = bindings::diagnostic_list(diagnostics);
    return out;
}

const char* const kOptionsDoc =
    "pixels_per_mm in (0, 40] (default 300 dpi); depth (mm, > 0, may be inf): how far in front "
    "of the patch a surface counts; behind (mm, >= 0): how far behind it; back_side: render the "
    "side opposite the normal (the printed side where FlatPatch.normal_side_up is False); light "
    "(card frame) and ambient in [0, 1] shade a model without texture or colours; max_pixels "
    "caps width x height. DesignError names a bad value and its range.";

} // namespace

void bind_artwork(py::module_& m)
{
    py::class_<PatchArtwork>(m, "PatchArtwork", py::dynamic_attr(),
                             "A model's appearance rendered onto one patch, laid on the patch's "
                             "own frame (docs/DESIGN.md, Artwork)")
        .def_readonly("patch", &PatchArtwork::patch, "the patch's id")
        .def_property_readonly(
            "rgba",
            [](const PatchArtwork& a) {
                py::array_t<std::uint8_t> out(
                    {py::ssize_t(a.image.height), py::ssize_t(a.image.width), py::ssize_t(4)});
                std::copy(a.image.pixels.begin(), a.image.pixels.end(), out.mutable_data());
                return out;
            },
            "height x width x 4 uint8, row 0 at the top (largest v), straight alpha; 0 alpha "
            "where no surface counts")
        .def_property_readonly(
            "origin_uv",
            [](const PatchArtwork& a) { return py::make_tuple(a.origin.x(), a.origin.y()); },
            "(u, v) in the patch frame of the image's lower-left corner, mm")
        .def_readonly("mm_per_pixel", &PatchArtwork::mm_per_pixel)
        .def_readonly("back_side", &PatchArtwork::back_side,
                      "rendered from the side opposite the patch's normal")
        .def_property_readonly(
            "frame",
            [](const PatchArtwork& a) {
                return py::dict(py::arg("origin") = a.frame_origin, py::arg("u") = a.frame_u,
                                py::arg("v") = a.frame_v, py::arg("normal") = a.frame_normal);
            },
            "the patch frame at the design state: origin, u, v, normal")
        .def_readonly("covered_pixels", &PatchArtwork::covered_pixels,
                      "pixels showing a model surface")
        .def("__repr__", [](const PatchArtwork& a) {
            return "<PatchArtwork patch " + std::to_string(a.patch) + ": " +
                   std::to_string(a.image.width) + " x " + std::to_string(a.image.height) +
                   " pixels, " + std::to_string(a.covered_pixels) + " covered>";
        });
    m.def(
        "render_artwork",
        [](const ModelMesh& mesh, const Patch& patch, double pixels_per_mm, double depth,
           double behind, bool back_side, const Vec3& light, double ambient, long long max_pixels) {
            Result<PatchArtwork> r;
            {
                py::gil_scoped_release release;
                r = render_artwork(mesh, patch,
                                   options_of(pixels_per_mm, depth, behind, back_side, light,
                                              ambient, max_pixels));
            }
            if (!r.ok)
                throw bindings::DesignFailure(r.diagnostics);
            return with_warnings(std::move(r.value), r.diagnostics);
        },
        py::arg("mesh"), py::arg("patch"),
        py::arg("pixels_per_mm") = ArtworkOptions{}.pixels_per_mm,
        py::arg("depth") = ArtworkOptions{}.depth, py::arg("behind") = ArtworkOptions{}.behind,
        py::arg("back_side") = false, py::arg("light") = ArtworkOptions{}.light,
        py::arg("ambient") = ArtworkOptions{}.ambient,
        py::arg("max_pixels") = ArtworkOptions{}.max_pixels,
        (std::string("The model (card mm) seen orthographically along the patch's normal, as a "
                     "PatchArtwork; .warnings lists an unreadable texture. ") +
         kOptionsDoc)
            .c_str());
    m.def(
        "render_artworks",
        [](const ModelMesh& mesh, const std::vector<Patch>& patches, double pixels_per_mm,
           double depth, double behind, bool back_side, const Vec3& light, double ambient,
           long long max_pixels) {
            Result<std::vector<PatchArtwork>> r;
            {
                py::gil_scoped_release release;
                r = render_artworks(mesh, patches,
                                    options_of(pixels_per_mm, depth, behind, back_side, light,
                                               ambient, max_pixels));
            }
            if (!r.ok)
                throw bindings::DesignFailure(r.diagnostics);
            py::list out;
            for (PatchArtwork& art : r.value)
                out.append(with_warnings(std::move(art), r.diagnostics));
            return out;
        },
        py::arg("mesh"), py::arg("patches"),
        py::arg("pixels_per_mm") = ArtworkOptions{}.pixels_per_mm,
        py::arg("depth") = ArtworkOptions{}.depth, py::arg("behind") = ArtworkOptions{}.behind,
        py::arg("back_side") = false, py::arg("light") = ArtworkOptions{}.light,
        py::arg("ambient") = ArtworkOptions{}.ambient,
        py::arg("max_pixels") = ArtworkOptions{}.max_pixels,
        (std::string("render_artwork for each patch of a list, reading the texture once. ") +
         kOptionsDoc)
            .c_str());
}
