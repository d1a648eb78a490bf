// Binding of fit_design, the automatic design from a model (thesis §5.1): conversions only.
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "binding_support.hpp"
#include "point_rows.hpp"
#include "popup/fitting/fit_design.hpp"
#include "popup/fitting/supporting_plate.hpp"

namespace py = pybind11;
using namespace popup;
using namespace popup::bindings;

namespace {

/// None or a 3-sequence of numbers.
std::optional<Vec3> direction_of(const py::object& value, const char* name)
{
    if (value.is_none())
        return std::nullopt;
    std::vector<double> v;
    try {
        v = value.cast<std::vector<double>>();
    } catch (const py::cast_error&) {
    }
    if (v.size() != 3)
        throw bindings::DesignFailure({Diagnostic::error(
            DiagnosticCode::bad_option,
            std::string("FitOptions.") + name + " must be None or a sequence of 3 numbers",
            about_parameter(name))});
    return Vec3(v[0], v[1], v[2]);
}

py::object direction_to_python(const std::optional<Vec3>& v)
{
    if (!v)
        return py::none();
    return py::make_tuple((*v)[0], (*v)[1], (*v)[2]);
}

} // namespace

void bind_fitting(py::module_& m)
{
    py::class_<FitOptions>(m, "FitOptions",
                           "What the maker chooses for an automatic design from a model: up and "
                           "facing are None or model directions (3-sequences)")
        .def(py::init<>())
        .def_property(
            "up", [](const FitOptions& o) { return direction_to_python(o.up); },
            [](FitOptions& o, const py::object& v) { o.up = direction_of(v, "up"); })
        .def_property(
            "facing", [](const FitOptions& o) { return direction_to_python(o.facing); },
            [](FitOptions& o, const py::object& v) { o.facing = direction_of(v, "facing"); })
        .def_readwrite("card", &FitOptions::card, "the card's width and depth (mm)")
        .def_property(
            "card_width", [](const FitOptions& o) { return o.card.width; },
            [](FitOptions& o, double v) { o.card.width = v; }, "card.width (mm)")
        .def_property(
            "card_depth", [](const FitOptions& o) { return o.card.depth; },
            [](FitOptions& o, double v) { o.card.depth = v; }, "card.depth (mm)")
        .def_readwrite("margin", &FitOptions::margin)
        .def_readwrite("min_part_mm", &FitOptions::min_part_mm)
        .def_readwrite("max_mechanisms", &FitOptions::max_mechanisms)
        .def_readwrite("min_shape", &FitOptions::min_shape)
        .def_readwrite("probability", &FitOptions::probability)
        .def_readwrite("threshold", &FitOptions::threshold)
        .def_readwrite("samples", &FitOptions::samples)
        .def_readwrite("seed", &FitOptions::seed)
        .def_readwrite("outlines", &FitOptions::outlines)
        .def_readwrite("depth_layers", &FitOptions::depth_layers)
        .def_static(
            "fields", [] { return fit_option_fields(); },
            "Every option's OptionField (name, doc, unit, default, range), in declaration order.")
        .def(
            "check",
            [](const FitOptions& o) { return bindings::diagnostic_list(check_fit_options(o)); },
            "The options' range errors as diagnostics (empty when every option is in range).");

    py::class_<FittedPrimitive>(m, "FittedPrimitive")
        .def_readonly("kind", &FittedPrimitive::kind)
        .def_property_readonly("corners",
                               [](const FittedPrimitive& p) { return rows_of(p.corners); })
        .def_readonly("host", &FittedPrimitive::host)
        .def_readonly("inliers", &FittedPrimitive::inliers);

    py::class_<FitRepair>(m, "FitRepair")
        .def_readonly("mechanism", &FitRepair::mechanism)
        .def_readonly("action", &FitRepair::action)
        .def_readonly("reason", &FitRepair::reason);

    py::class_<FittedProfile>(m, "FittedProfile",
                              "A principal part's outline from the model (thesis §5.1.3), in the "
                              "part's profile frame, mm")
        .def_readonly("mechanism", &FittedProfile::mechanism)
        .def_readonly("part", &FittedProfile::part)
        .def_property_readonly("outer", [](const FittedProfile& p) { return rows_of(p.outer); })
        .def_property_readonly("holes",
                               [](const FittedProfile& p) {
                                   std::vector<Rows2d> out;
                                   for (const Loop2& h : p.holes)
                                       out.push_back(rows_of(h));
                                   return out;
                               })
        .def_property_readonly(
            "reference",
            [](const FittedProfile& p) { return std::make_pair(p.reference.x(), p.reference.y()); })
        .def_readonly("area", &FittedProfile::area)
        .def_readonly("area_before", &FittedProfile::area_before);

    py::class_<FittedDepthLayer>(m, "FittedDepthLayer",
                                 "A depth layer of a box fold's front or top (thesis §5.1.3) and "
                                 "whether it was built as a nested mechanism")
        .def_readonly("box", &FittedDepthLayer::box)
        .def_readonly("face", &FittedDepthLayer::face)
        .def_readonly("depth", &FittedDepthLayer::depth)
        .def_readonly("area", &FittedDepthLayer::area)
        .def_readonly("kept", &FittedDepthLayer::kept)
        .def_readonly("mechanism", &FittedDepthLayer::mechanism)
        .def_readonly("reason", &FittedDepthLayer::reason)
        .def_readonly("mean_before_mm", &FittedDepthLayer::mean_before_mm)
        .def_readonly("mean_after_mm", &FittedDepthLayer::mean_after_mm);

    py::class_<SupportingPlate>(m, "SupportingPlate",
                                "The plate a model stands on (a terrain slab, a print bed), which "
                                "becomes the card's page (docs/MATH.md)")
        .def_property_readonly(
            "up",
            [](const SupportingPlate& p) { return std::make_tuple(p.up.x(), p.up.y(), p.up.z()); })
        .def_readonly("top", &SupportingPlate::top)
        .def_readonly("thickness", &SupportingPlate::thickness)
        .def_readonly("top_area", &SupportingPlate::top_area);

    m.def("above_plate", &above_plate, py::arg("mesh"), py::arg("plate"),
          "The model without its plate: the triangles wholly at or below the plate's top removed "
          "(what fit_metrics and the preview measure and draw)");

    py::class_<FitResult>(m, "FitResult")
        .def_readonly("card", &FitResult::card)
        .def_property_readonly("model_to_card",
                               [](const FitResult& r) { return Eigen::Matrix4d(r.model_to_card); })
        .def_readonly("primitives", &FitResult::primitives)
        .def_readonly("mechanisms", &FitResult::mechanisms)
        .def_readonly("repairs", &FitResult::repairs)
        .def_readonly("scaffold", &FitResult::scaffold)
        .def_readonly("profiles", &FitResult::profiles)
        .def_readonly("depth_layers", &FitResult::depth_layers)
        .def_readonly("valid", &FitResult::valid)
        .def_readonly("coverage", &FitResult::coverage)
        .def_readonly("coverage_error", &FitResult::coverage_error)
        .def_readonly("symmetry_error", &FitResult::symmetry_error)
        .def_readonly("ransac_draws", &FitResult::ransac_draws)
        .def_readonly("outer_samples", &FitResult::outer_samples)
        .def_readonly("inner_samples", &FitResult::inner_samples)
        .def_readonly("turned_faces", &FitResult::turned_faces)
        .def_readonly("plate", &FitResult::plate,
                      "the SupportingPlate that became the page, or None")
        .def_readonly("timings", &FitResult::timings)
        .def_property_readonly("pops_up", &FitResult::pops_up,
                               "valid with at least one mechanism: a bare card is no pop-up")
        .def_property_readonly("diagnostics", [](const FitResult& r) {
            return bindings::diagnostic_list(r.diagnostics);
        });

    m.def(
        "fit_design",
        [](const ModelMesh& mesh, const FitOptions& options, std::shared_ptr<CancelFlag> cancel) {
            Result<FitResult> r = fit_design(mesh, options, cancel.get());
            // No valid design is an answer (valid False, the reasons in diagnostics and
            // repairs); bad input and bad options are errors.
            bool only_no_design = !r.ok;
            for (const Diagnostic& d : r.diagnostics)
                if (d.severity == Severity::error && d.code != DiagnosticCode::no_design_found)
                    only_no_design = false;
            if (only_no_design) {
                for (const Diagnostic& d : r.diagnostics)
                    if (d.code == DiagnosticCode::no_design_found)
                        r.value.diagnostics.push_back(d);
                return r.value;
            }
            return bindings::unwrap(std::move(r));
        },
        py::arg("mesh"), py::arg("options") = FitOptions(), py::arg("cancel") = nullptr,
        py::call_guard<py::gil_scoped_release>(),
        "The automatic design of thesis §5.1 (DesignError on bad input or options; valid False "
        "with a no_design_found diagnostic when nothing valid remains; popupcore.Cancelled when "
        "cancel is set).");
}
