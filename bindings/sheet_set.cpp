// The cutting-sheet layout as bound types: SheetSet and its pieces, lines, tabs, glue areas,
// labels and assembly steps, read-only, loops as (n, 2) arrays in mm; every writer takes it.
// to_json() gives the file format (docs/SHEET_FORMAT.md) for sheets.json and a CuttingSheet's
// stored layout, sheet_set_from_json reads it back.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "binding_support.hpp"
#include "popup/io/sheet_json.hpp"
#include "popup/sheets/sheet_set.hpp"

namespace py = pybind11;
using namespace popup;

namespace {

py::array_t<double> loop2_array(const Loop2& loop)
{
    py::array_t<double> a({py::ssize_t(loop.size()), py::ssize_t(2)});
    auto m = a.mutable_unchecked<2>();
    for (size_t i = 0; i < loop.size(); ++i)
        for (int k = 0; k < 2; ++k)
            m(i, k) = loop[i][k];
    return a;
}

py::list loops_list(const std::vector<Loop2>& loops)
{
    py::list out;
    for (const Loop2& l : loops)
        out.append(loop2_array(l));
    return out;
}

py::tuple point(const Vec2& p)
{
    return py::make_tuple(p.x(), p.y());
}

} // namespace

void bind_sheet_set(py::module_& m)
{
    py::class_<FlatPatch>(m, "FlatPatch", "A patch laid flat on its sheet")
        .def_readonly("id", &FlatPatch::id)
        .def_readonly("name", &FlatPatch::name)
        .def_property_readonly("outer", [](const FlatPatch& p) { return loop2_array(p.outer); })
        .def_property_readonly("holes", [](const FlatPatch& p) { return loops_list(p.holes); })
        .def_property_readonly(
            "to_sheet",
            [](const FlatPatch& p) {
                return p.has_to_sheet() ? py::cast(Eigen::Matrix<double, 2, 3>(p.to_sheet))
                                        : py::none();
            },
            "2 x 3: the patch's own frame (u, v) onto the sheet, sheet = A (u, v) + t; None in a "
            "sheet set written before it existed")
        .def("normal_side_up", &FlatPatch::normal_side_up,
             "The patch's normal side faces up (is printed); else its back side does.");
    py::class_<Region>(m, "Region", "A closed outline with holes")
        .def_property_readonly("outer", [](const Region& r) { return loop2_array(r.outer); })
        .def_property_readonly("holes", [](const Region& r) { return loops_list(r.holes); });
    py::class_<FoldLine>(m, "FoldLine", "A crease; direction seen from the printed side")
        .def_readonly("hinge", &FoldLine::hinge)
        .def_property_readonly("start", [](const FoldLine& f) { return point(f.from); })
        .def_property_readonly("end", [](const FoldLine& f) { return point(f.to); })
        .def_property_readonly(
            "direction", [](const FoldLine& f) { return std::string(to_string(f.direction)); })
        .def_property_readonly("kind",
                               [](const FoldLine& f) { return std::string(to_string(f.kind)); });
    py::class_<GlueTab>(m, "GlueTab", "A glue flap; its polygon's first edge is the crease")
        .def_readonly("code", &GlueTab::code)
        .def_readonly("hinge", &GlueTab::hinge)
        .def_readonly("patch", &GlueTab::patch)
        .def_property_readonly("polygon", [](const GlueTab& t) { return loop2_array(t.polygon); })
        .def_readonly("width", &GlueTab::width)
        .def_readonly("target_piece", &GlueTab::target_piece)
        .def_readonly("target_patch", &GlueTab::target_patch)
        .def_readonly("front", &GlueTab::front);
    py::class_<GlueArea>(m, "GlueArea", "Where another piece's tab is glued")
        .def_readonly("code", &GlueArea::code)
        .def_readonly("hinge", &GlueArea::hinge)
        .def_readonly("patch", &GlueArea::patch)
        .def_property_readonly("polygon", [](const GlueArea& g) { return loop2_array(g.polygon); })
        .def_readonly("tab_piece", &GlueArea::tab_piece)
        .def_readonly("front", &GlueArea::front);
    py::class_<SheetLabel>(m, "SheetLabel")
        .def_readonly("text", &SheetLabel::text)
        .def_readonly("kind", &SheetLabel::kind)
        .def_property_readonly("position", [](const SheetLabel& l) { return point(l.position); })
        .def_readonly("height", &SheetLabel::height)
        .def_readonly("angle", &SheetLabel::angle);
    py::class_<SheetPiece>(m, "SheetPiece", "One piece of paper placed on its sheet")
        .def_readonly("id", &SheetPiece::id)
        .def_property_readonly(
            "printed_side",
            [](const SheetPiece& p) { return std::string(to_string(p.printed_side)); })
        .def_readonly("sheet", &SheetPiece::sheet)
        .def_readonly("rotation", &SheetPiece::rotation)
        .def_readonly("patches", &SheetPiece::patches)
        .def_readonly("cut", &SheetPiece::cut)
        .def_readonly("cut_nominal", &SheetPiece::cut_nominal)
        .def_readonly("folds", &SheetPiece::folds)
        .def_readonly("tabs", &SheetPiece::tabs)
        .def_readonly("glue", &SheetPiece::glue)
        .def_readonly("labels", &SheetPiece::labels);
    py::class_<AssemblyJoin>(m, "AssemblyJoin", "A tab glued onto its area, in a step")
        .def_readonly("code", &AssemblyJoin::code)
        .def_readonly("tab_piece", &AssemblyJoin::tab_piece, "index into SheetSet.pieces")
        .def_readonly("target_piece", &AssemblyJoin::target_piece, "index into SheetSet.pieces")
        .def_readonly("front", &AssemblyJoin::front, "glued to the target's printed side");
    py::class_<AssemblyStep>(m, "AssemblyStep", "One piece glued on, after the steps before")
        .def_readonly("piece", &AssemblyStep::piece, "index into SheetSet.pieces")
        .def_readonly("joins", &AssemblyStep::joins)
        .def_readonly("text", &AssemblyStep::text);
    py::class_<RoundTrip>(m, "RoundTrip")
        .def_readonly("max_error", &RoundTrip::max_error)
        .def_readonly("tolerance", &RoundTrip::tolerance)
        .def_readonly("angles", &RoundTrip::angles)
        .def_readonly("ok", &RoundTrip::ok);
    py::class_<SheetSet>(m, "SheetSet", "The card laid out for cutting (docs/SHEET_FORMAT.md)")
        .def_readonly("options", &SheetSet::options)
        .def_readonly("card_size", &SheetSet::card_size)
        .def_readonly("paper_thickness", &SheetSet::paper_thickness)
        .def_readonly("sheet_count", &SheetSet::sheet_count)
        .def_readonly("shelf_sheet_count", &SheetSet::shelf_sheet_count)
        .def_readonly("pieces", &SheetSet::pieces, "the card first; a list made at each access")
        .def_readonly("assembly", &SheetSet::assembly)
        .def_readonly("cut_length", &SheetSet::cut_length)
        .def_readonly("stack_height", &SheetSet::stack_height)
        .def_readonly("round_trip", &SheetSet::round_trip)
        .def_readonly("diagnostics", &SheetSet::diagnostics)
        .def("to_json", &sheet_set_to_json, py::call_guard<py::gil_scoped_release>(),
             "The sheet set as the JSON text of sheets.json and of a CuttingSheet's stored layout "
             "(docs/SHEET_FORMAT.md).");
    m.def(
        "sheet_set_from_json",
        [](const std::string& text) { return bindings::unwrap(sheet_set_from_json(text)); },
        py::arg("text"), py::call_guard<py::gil_scoped_release>(),
        "The SheetSet a JSON sheet set holds (to_json()'s text, a sheets.json); DesignError (a "
        "ValueError) naming the key path of a missing or malformed field.");
}
