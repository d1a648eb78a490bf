// Cutting sheets: the flat layout as the JSON sheet set (docs/SHEET_FORMAT.md) and paper sizes.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "binding_support.hpp"
#include "popup/io/sheet_json.hpp"
#include "popup/sheets/sheet_layout.hpp"

namespace py = pybind11;
using namespace popup;
using popup::bindings::unwrap;

void bind_sheets(py::module_& m)
{
    m.def(
        "paper_size",
        [](const std::string& name) {
            const Paper p = unwrap(paper_by_name(name));
            return py::make_tuple(p.name, p.width, p.height);
        },
        py::arg("name"),
        "(name, width, height) in mm of A4, A3, Letter, Tabloid or '<w>x<h>'; raises "
        "DesignError for anything else.");
    // The options as a bound type: its defaults are the core's own (SheetOptions{}), the single
    // source the workbench's option table reads (popupwb/sheets/sheet_options.py).
    py::class_<SheetOptions>(m, "SheetOptions")
        .def(py::init<>())
        .def_property(
            "paper", [](const SheetOptions& o) { return o.nest.paper.name; },
            [](SheetOptions& o, const std::string& name) {
                o.nest.paper = unwrap(paper_by_name(name));
            },
            "A4, A3, Letter, Tabloid or '<w>x<h>' mm (DesignError for anything else)")
        .def_property_readonly("paper_width",
                               [](const SheetOptions& o) { return o.nest.paper.width; })
        .def_property_readonly("paper_height",
                               [](const SheetOptions& o) { return o.nest.paper.height; })
        .def_property(
            "margin", [](const SheetOptions& o) { return o.nest.margin; },
            [](SheetOptions& o, double v) { o.nest.margin = v; })
        .def_property(
            "spacing", [](const SheetOptions& o) { return o.nest.spacing; },
            [](SheetOptions& o, double v) { o.nest.spacing = v; })
        .def_property(
            "rotate", [](const SheetOptions& o) { return o.nest.rotate; },
            [](SheetOptions& o, bool v) { o.nest.rotate = v; })
        .def_readwrite("kerf", &SheetOptions::kerf)
        .def_readwrite("min_gap", &SheetOptions::min_gap)
        .def_readwrite("tab_width", &SheetOptions::tab_width)
        .def_readwrite("tab_angle", &SheetOptions::tab_angle)
        .def_readwrite("min_tab_width", &SheetOptions::min_tab_width)
        .def_readwrite("min_feature", &SheetOptions::min_feature)
        .def_readwrite("min_corner_angle", &SheetOptions::min_corner_angle)
        .def_readwrite("fold_hints", &SheetOptions::fold_hints)
        .def_readwrite("round_trip_angles", &SheetOptions::round_trip_angles)
        .def_property(
            "printed_sides",
            [](const SheetOptions& o) {
                std::map<std::string, std::string> sides;
                for (const auto& [id, side] : o.printed_sides)
                    sides[id] = to_string(side);
                return sides;
            },
            [](SheetOptions& o, const std::map<std::string, std::string>& sides) {
                o.printed_sides = bindings::printed_sides_from(sides);
            },
            "{piece id: 'front' or 'back'}: the side each piece's artwork is printed on")
        .def(
            "check",
            [](const SheetOptions& o) { return bindings::diagnostic_list(check_sheet_options(o)); },
            "The options' range errors as diagnostics (empty when every option is in range).");
    m.def(
        "layout_sheets",
        [](const Scaffold& s, SheetOptions o, std::shared_ptr<CancelFlag> cancel) {
            py::gil_scoped_release release;
            o.cancel = cancel.get();
            return unwrap(layout_sheets(s, o));
        },
        py::arg("scaffold"), py::arg("options") = SheetOptions{}, py::arg("cancel") = nullptr,
        "Unfolds, tabs, labels, orders, nests and re-folds the card; returns the SheetSet "
        "(to_json() gives the file format, docs/SHEET_FORMAT.md). Raises DesignError naming a bad "
        "option (and its "
        "range), a piece too large for the paper, or a piece that cannot lie flat.");
}
