// What a cutting file holds (SheetDrawing), and the proof of a drawing against its design
// (verify_sheets). The DXF reader (popupwb/sheets/dxf_reader.py) fills SheetDrawing from ezdxf.
#include <array>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "binding_support.hpp"
#include "popup/sheets/verify_sheets.hpp"

namespace py = pybind11;
using namespace popup;
using popup::bindings::unwrap;

namespace {

using Points = std::vector<std::array<double, 2>>;

Loop2 to_loop(const Points& points)
{
    Loop2 loop;
    for (const auto& p : points)
        loop.emplace_back(p[0], p[1]);
    return loop;
}

Points to_points(const Loop2& loop)
{
    Points points;
    for (const Vec2& p : loop)
        points.push_back({p.x(), p.y()});
    return points;
}

std::vector<Points> to_points(const std::vector<Loop2>& loops)
{
    std::vector<Points> out;
    for (const Loop2& l : loops)
        out.push_back(to_points(l));
    return out;
}

std::vector<Loop2> to_loops(const std::vector<Points>& loops)
{
    std::vector<Loop2> out;
    for (const Points& l : loops)
        out.push_back(to_loop(l));
    return out;
}

FoldDirection fold_direction(const std::string& name)
{
    if (name == "mountain")
        return FoldDirection::mountain;
    if (name == "valley")
        return FoldDirection::valley;
    throw bindings::DesignFailure({Diagnostic::error(
        DiagnosticCode::bad_option, "fold direction '" + name + "', must be mountain or valley",
        about_parameter("direction"))});
}

std::array<double, 2> pair(const Vec2& p)
{
    return {p.x(), p.y()};
}

Vec2 vec(const std::array<double, 2>& p)
{
    return {p[0], p[1]};
}

} // namespace

void bind_sheet_drawing(py::module_& m)
{
    py::class_<DrawnFold>(m, "DrawnFold", "A line on the MOUNTAIN or VALLEY layer")
        .def(py::init([](std::array<double, 2> start, std::array<double, 2> end,
                         const std::string& direction) {
                 return DrawnFold{vec(start), vec(end), fold_direction(direction)};
             }),
             py::arg("start"), py::arg("end"), py::arg("direction"))
        .def_property_readonly("start", [](const DrawnFold& f) { return pair(f.from); })
        .def_property_readonly("end", [](const DrawnFold& f) { return pair(f.to); })
        .def_property_readonly(
            "direction", [](const DrawnFold& f) { return std::string(to_string(f.direction)); });
    py::class_<DrawnText>(m, "DrawnText", "A text on the LABEL layer, by its centre")
        .def(py::init([](const std::string& text, std::array<double, 2> position) {
                 return DrawnText{text, vec(position)};
             }),
             py::arg("text"), py::arg("position"))
        .def_readonly("text", &DrawnText::text)
        .def_property_readonly("position", [](const DrawnText& t) { return pair(t.position); });
    py::class_<SheetDrawing>(m, "SheetDrawing",
                             "What one cutting file holds: CUT loops (kerf-compensated), fold "
                             "lines, glue areas and labels, in mm")
        .def(py::init<>())
        .def_readwrite("name", &SheetDrawing::name)
        .def_readwrite("kerf", &SheetDrawing::kerf)
        .def_property(
            "cut", [](const SheetDrawing& d) { return to_points(d.cut); },
            [](SheetDrawing& d, const std::vector<Points>& loops) { d.cut = to_loops(loops); })
        .def_property(
            "glue", [](const SheetDrawing& d) { return to_points(d.glue); },
            [](SheetDrawing& d, const std::vector<Points>& loops) { d.glue = to_loops(loops); })
        .def_readwrite("folds", &SheetDrawing::folds)
        .def_readwrite("labels", &SheetDrawing::labels);
    m.def("draw_sheets", &draw_sheets, py::arg("sheet_set"),
          "The drawing of each sheet of a SheetSet: the entities the DXF writer puts on its "
          "layers.");
    m.def(
        "verify_sheets",
        [](const Scaffold& design, const std::vector<SheetDrawing>& drawings,
           const std::map<std::string, std::string>& printed_sides, int angles) {
            VerifyOptions options;
            options.angles = angles;
            options.printed_sides = bindings::printed_sides_from(printed_sides);
            Result<RoundTrip> r;
            {
                py::gil_scoped_release release;
                r = verify_sheets(design, drawings, options);
            }
            if (!r.ok)
                throw bindings::DesignFailure(r.diagnostics);
            // Nothing compared (the pieces could not be re-made): no error to report, not 0.
            const py::object max_error =
                r.value.angles > 0 ? py::object(py::float_(r.value.max_error)) : py::none();
            return py::dict(py::arg("ok") = r.value.ok, py::arg("max_error") = max_error,
                            py::arg("tolerance") = r.value.tolerance,
                            py::arg("angles") = r.value.angles,
                            py::arg("diagnostics") = bindings::diagnostic_list(r.diagnostics));
        },
        py::arg("design"), py::arg("drawings"), py::arg("printed_sides") = py::dict(),
        py::arg("angles") = 13,
        "Re-builds the pieces from the drawings, folds them with the simulator and compares them "
        "with the design: {'ok', 'max_error' (None when nothing could be compared), 'tolerance', "
        "'angles', 'diagnostics'}. Raises "
        "DesignError when the design or the options cannot be used at all.");
}
