// Cutting sheets: the flat layout as the JSON sheet set (docs/SHEET_FORMAT.md) and paper sizes.
#include <pybind11/pybind11.h>

#include "binding_support.hpp"
#include "popup/sheet_layout.hpp"

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
    m.def(
        "layout_sheets",
        [](const Scaffold& s, const std::string& paper, double margin, double spacing, bool rotate,
           double kerf, double min_gap, double tab_width, double tab_angle, double min_tab_width,
           double min_feature, double min_corner_angle, bool fold_hints, int round_trip_angles) {
            SheetOptions o;
            o.nest.paper = unwrap(paper_by_name(paper));
            o.nest.margin = margin;
            o.nest.spacing = spacing;
            o.nest.rotate = rotate;
            o.kerf = kerf;
            o.min_gap = min_gap;
            o.tab_width = tab_width;
            o.tab_angle = tab_angle;
            o.min_tab_width = min_tab_width;
            o.min_feature = min_feature;
            o.min_corner_angle = min_corner_angle;
            o.fold_hints = fold_hints;
            o.round_trip_angles = round_trip_angles;
            return sheet_set_to_json(unwrap(layout_sheets(s, o)));
        },
        py::arg("scaffold"), py::arg("paper") = "A4", py::arg("margin") = 10.0,
        py::arg("spacing") = 2.0, py::arg("rotate") = true, py::arg("kerf") = 0.1,
        py::arg("min_gap") = 1.0, py::arg("tab_width") = 8.0, py::arg("tab_angle") = 45.0,
        py::arg("min_tab_width") = 3.0, py::arg("min_feature") = 3.0,
        py::arg("min_corner_angle") = 30.0, py::arg("fold_hints") = false,
        py::arg("round_trip_angles") = 13, py::call_guard<py::gil_scoped_release>(),
        "Unfolds, tabs, labels, orders, nests and re-folds the card; returns the sheet set as "
        "JSON text (docs/SHEET_FORMAT.md). Raises DesignError naming a bad option (and its "
        "range), a piece too large for the paper, or a piece that cannot lie flat.");
}
