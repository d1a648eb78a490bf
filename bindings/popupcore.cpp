// Python bindings: type conversion, names and docstrings only; every computation is in core/.
#include <sstream>
#include <stdexcept>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <CGAL/exceptions.h>
#include <Standard_Failure.hxx>

#include "binding_support.hpp"
#include "popup/io/brep_export.hpp"
#include "popup/io/design_file.hpp"
#include "popup/model/cancel_flag.hpp"
#include "popup/sheets/pieces.hpp"
#include "popup/simulation/check_validity.hpp"
#include "popup/simulation/simulate_fold.hpp"

namespace py = pybind11;
using namespace popup;
using namespace popup::bindings;

namespace {

// Python exception types, created once at import.
PyObject* design_error = nullptr;
PyObject* occt_error = nullptr;
PyObject* cgal_error = nullptr;

py::array_t<double> loop_array(const Loop3& loop)
{
    py::array_t<double> a({py::ssize_t(loop.size()), py::ssize_t(3)});
    auto m = a.mutable_unchecked<2>();
    for (size_t i = 0; i < loop.size(); ++i)
        for (int k = 0; k < 3; ++k)
            m(i, k) = loop[i][k];
    return a;
}

py::dict report_dict(const ValidityReport& r)
{
    py::list crossings;
    for (const Crossing& c : r.crossings)
        crossings.append(py::dict(py::arg("patch_a") = c.patch_a, py::arg("patch_b") = c.patch_b,
                                  py::arg("angle_deg") = c.angle * 180.0 / M_PI,
                                  py::arg("depth") = c.depth));
    py::dict d;
    d["valid"] = r.valid();
    d["foldable"] = r.foldable;
    d["stable"] = r.stable;
    d["intersection_free"] = r.intersection_free;
    d["enclosed"] = r.enclosed;
    d["max_hinge_residual"] = r.max_hinge_residual;
    d["max_edge_strain"] = r.max_edge_strain;
    d["flatness_at_zero"] = r.flatness_at_zero;
    d["locked_at_deg"] = r.locked_at < 0 ? py::object(py::none())
                                         : py::object(py::float_(r.locked_at * 180.0 / M_PI));
    d["model_size"] = r.model_size;
    d["crossings"] = crossings;
    d["diagnostics"] = diagnostic_list(r.diagnostics);
    return d;
}

// Throws one native exception family on demand, so tests can check the translators.
void raise_native(const std::string& kind, const std::string& message)
{
    if (kind == "std")
        throw std::runtime_error(message);
    if (kind == "invalid_argument")
        throw std::invalid_argument(message);
    if (kind == "occt")
        throw Standard_Failure(message.c_str());
    if (kind == "cgal")
        throw CGAL::Failure_exception("popup", "raise_native", __FILE__, __LINE__, message);
    throw std::invalid_argument("kind = '" + kind +
                                "', must be 'std', 'invalid_argument', 'occt' or 'cgal'");
}

// Patches, hinges, scaffolds, diagnostics and design files.
void bind_scaffold(py::module_& m)
{
    py::class_<Diagnostic>(m, "Diagnostic")
        .def_property_readonly("code", [](const Diagnostic& d) { return to_string(d.code); })
        .def_property_readonly("severity",
                               [](const Diagnostic& d) { return to_string(d.severity); })
        .def_readonly("message", &Diagnostic::message)
        .def_readonly("patches", &Diagnostic::patches)
        .def_readonly("parameter", &Diagnostic::parameter)
        .def_readonly("angle_deg", &Diagnostic::angle_deg)
        .def("to_dict", &diagnostic_dict, "The diagnostic as a dict (the --json shape).")
        .def("__repr__", [](const Diagnostic& d) {
            return std::string("<Diagnostic ") + to_string(d.code) + " " + to_string(d.severity) +
                   ": " + d.message + ">";
        });
    m.def(
        "diagnostic_codes",
        [] {
            std::vector<std::string> names;
            for (DiagnosticCode c : all_diagnostic_codes())
                names.push_back(to_string(c));
            return names;
        },
        "Every diagnostic code, in the order of docs/DIAGNOSTICS.md.");

    py::class_<Patch>(m, "Patch")
        .def_readonly("id", &Patch::id)
        .def_readonly("name", &Patch::name)
        .def_property_readonly("role",
                               [](const Patch& p) { return std::string(to_string(p.role)); })
        .def_property_readonly("outer", [](const Patch& p) { return loop_array(p.outer); })
        .def_property_readonly("holes",
                               [](const Patch& p) {
                                   py::list out;
                                   for (const Loop3& h : p.holes)
                                       out.append(loop_array(h));
                                   return out;
                               })
        .def_property_readonly("normal", [](const Patch& p) { return Vec3(p.normal); })
        .def("area", &Patch::area, "Area in mm² (holes removed).");
    m.def(
        "patch_subject",
        [](int id, const std::string& name) {
            Patch p;
            p.id = id;
            p.name = name;
            return patch_subject(p);
        },
        py::arg("id"), py::arg("name") = "",
        "How the core's messages name a patch: \"patch 5 (BoxFold.TG)\".");

    py::class_<Hinge>(m, "Hinge")
        .def_readonly("id", &Hinge::id)
        .def_readonly("patch_a", &Hinge::patch_a)
        .def_readonly("patch_b", &Hinge::patch_b)
        .def_property_readonly("from_point", [](const Hinge& h) { return Vec3(h.from); })
        .def_property_readonly("to_point", [](const Hinge& h) { return Vec3(h.to); })
        .def_property_readonly("direction",
                               [](const Hinge& h) { return std::string(to_string(h.direction)); })
        .def_property_readonly("kind",
                               [](const Hinge& h) { return std::string(to_string(h.kind)); });

    py::class_<Scaffold>(m, "Scaffold")
        .def_readonly("name", &Scaffold::name)
        .def_readonly("patches", &Scaffold::patches)
        .def_readonly("hinges", &Scaffold::hinges)
        .def_property_readonly("glue",
                               [](const Scaffold& s) {
                                   py::list out;
                                   for (const Glue& g : s.glue)
                                       out.append(py::make_tuple(g.patch_a, g.patch_b));
                                   return out;
                               })
        .def_property_readonly("slits",
                               [](const Scaffold& s) {
                                   py::list out;
                                   for (const Slit& sl : s.slits)
                                       out.append(py::make_tuple(sl.patch_cut, sl.patch_through));
                                   return out;
                               })
        .def_readonly("ground", &Scaffold::ground)
        .def_readonly("backdrop", &Scaffold::backdrop)
        .def_readonly("design_angle", &Scaffold::design_angle)
        .def_readonly("paper_thickness", &Scaffold::paper_thickness)
        .def("size", &Scaffold::size, "Diagonal of the design-state bounding box (mm).")
        .def(
            "copy", [](const Scaffold& s) { return Scaffold(s); }, "An independent copy.");

    m.def(
        "scaffold_from_json",
        [](const py::str& text) {
            // A str that is not valid Unicode (a lone surrogate) has no UTF-8 form: say so,
            // rather than let pybind11 report an argument-type mismatch.
            PyObject* utf8 = PyUnicode_AsUTF8String(text.ptr());
            if (!utf8) {
                PyErr_Clear();
                throw DesignFailure({Diagnostic::error(
                    DiagnosticCode::bad_json,
                    "design text is not valid Unicode (a lone surrogate?); it cannot be UTF-8")});
            }
            const std::string t = py::reinterpret_steal<py::bytes>(utf8);
            return unwrap(scaffold_from_json(t));
        },
        py::arg("text"), "Parses a design file's text; raises DesignError naming the field.");
    m.def(
        "load_scaffold", [](const std::string& p) { return unwrap(load_scaffold(p)); },
        py::arg("path"), "Reads a JSON design file; raises DesignError naming the field.");
    m.def("scaffold_to_json", &scaffold_to_json, py::arg("scaffold"));
    m.def("cut_pieces", &cut_pieces, py::arg("scaffold"),
          "Patch ids of each sheet of paper: patches joined by folds, apart at tab joints.");
    m.def("save_scaffold", &save_scaffold, py::arg("scaffold"), py::arg("path"));
}

// Fold states and sweeps, free motion, crossings and the validity check.
void bind_simulation(py::module_& m)
{
    py::class_<FoldState>(m, "FoldState")
        .def_readonly("angle", &FoldState::angle)
        .def_readonly("hinge_residual", &FoldState::hinge_residual)
        .def_readonly("edge_strain", &FoldState::edge_strain)
        .def_property_readonly("rotations",
                               [](const FoldState& s) {
                                   py::array_t<double> a({py::ssize_t(s.poses.size()),
                                                          py::ssize_t(3), py::ssize_t(3)});
                                   auto m = a.mutable_unchecked<3>();
                                   for (size_t i = 0; i < s.poses.size(); ++i)
                                       for (int r = 0; r < 3; ++r)
                                           for (int c = 0; c < 3; ++c)
                                               m(i, r, c) = s.poses[i].rotation(r, c);
                                   return a;
                               })
        .def_property_readonly("translations", [](const FoldState& s) {
            Loop3 t;
            for (const Pose& p : s.poses)
                t.push_back(p.translation);
            return loop_array(t);
        });

    py::class_<Result<FoldSweep>>(m, "FoldSweep")
        .def_property_readonly("states", [](const Result<FoldSweep>& r) { return r.value.states; })
        .def_property_readonly("complete",
                               [](const Result<FoldSweep>& r) { return r.value.complete; })
        .def_property_readonly("locked_at",
                               [](const Result<FoldSweep>& r) { return r.value.locked_at; })
        .def_readonly("ok", &Result<FoldSweep>::ok)
        .def_readonly("diagnostics", &Result<FoldSweep>::diagnostics);

    m.def(
        "simulate_fold",
        [](const Scaffold& s, const std::vector<double>& angles) {
            return simulate_fold(s, angles);
        },
        py::arg("scaffold"), py::arg("angles"), py::call_guard<py::gil_scoped_release>(),
        "Poses of every patch at each fold angle (radians), by continuation from the design "
        "state.");
    m.def(
        "continue_fold",
        [](const Scaffold& s, const FoldState& from, const std::vector<double>& angles) {
            return continue_fold(s, from, angles);
        },
        py::arg("scaffold"), py::arg("from_state"), py::arg("angles"),
        py::call_guard<py::gil_scoped_release>(),
        "Continues the motion from a state on the branch (a cached one) to each angle.");
    m.def(
        "posed_outlines",
        [](const Scaffold& s, const FoldState& st) {
            if (st.poses.size() != s.patches.size())
                throw std::invalid_argument("state has " + std::to_string(st.poses.size()) +
                                            " poses for " + std::to_string(s.patches.size()) +
                                            " patches");
            py::list out;
            for (size_t i = 0; i < s.patches.size(); ++i)
                out.append(loop_array(posed_outline(s.patches[i], st.poses[i])));
            return out;
        },
        py::arg("scaffold"), py::arg("state"));
    m.def(
        "patches_to_brep",
        [](const Scaffold& s, const FoldState& st, double thickness) {
            return patches_to_brep(s, st, BrepOptions{thickness});
        },
        py::arg("scaffold"), py::arg("state"), py::arg("thickness") = 0.0,
        py::call_guard<py::gil_scoped_release>(),
        "BREP text of a compound of planar faces (solids when thickness > 0).");
    m.def(
        "design_to_brep",
        [](const Scaffold& s, double thickness) {
            return design_to_brep(s, BrepOptions{thickness});
        },
        py::arg("scaffold"), py::arg("thickness") = 0.0, py::call_guard<py::gil_scoped_release>());

    py::class_<ValidityReport>(m, "ValidityReport")
        .def_readonly("foldable", &ValidityReport::foldable)
        .def_readonly("stable", &ValidityReport::stable)
        .def_readonly("intersection_free", &ValidityReport::intersection_free)
        .def_readonly("enclosed", &ValidityReport::enclosed)
        .def_property_readonly("valid", &ValidityReport::valid)
        .def_readonly("max_hinge_residual", &ValidityReport::max_hinge_residual)
        .def_readonly("max_edge_strain", &ValidityReport::max_edge_strain)
        .def_readonly("flatness_at_zero", &ValidityReport::flatness_at_zero)
        .def_readonly("locked_at", &ValidityReport::locked_at)
        .def_readonly("model_size", &ValidityReport::model_size)
        .def_readonly("diagnostics", &ValidityReport::diagnostics)
        .def("to_dict", &report_dict, "Plain dict for JSON output.");

    m.def(
        "check_validity",
        [](const Scaffold& s, int samples, double clearance, std::shared_ptr<CancelFlag> cancel) {
            ValidityOptions o;
            o.samples = samples;
            o.clearance = clearance;
            o.cancel = cancel.get();
            return check_validity(s, o);
        },
        py::arg("scaffold"), py::arg("samples") = 181, py::arg("clearance") = 0.0,
        py::arg("cancel") = nullptr, py::call_guard<py::gil_scoped_release>(),
        "Foldable, stable, intersection-free and enclosed verdicts with diagnostics.");
}

} // namespace

PYBIND11_MODULE(popupcore, m)
{
    m.doc() = "PopUp core: scaffolds of paper patches, the rigid fold simulator and validity "
              "checks. Lengths in mm, angles in radians.";

    design_error = PyErr_NewException("popupcore.DesignError", PyExc_ValueError, nullptr);
    occt_error = PyErr_NewException("popupcore.OcctError", PyExc_RuntimeError, nullptr);
    cgal_error = PyErr_NewException("popupcore.CgalError", PyExc_RuntimeError, nullptr);
    m.attr("DesignError") = py::handle(design_error);
    m.attr("OcctError") = py::handle(occt_error);
    m.attr("CgalError") = py::handle(cgal_error);
    // A call stopped by its CancelFlag: not an error in the design, so not a DesignError.
    py::register_exception<Cancelled>(m, "Cancelled", PyExc_RuntimeError);
    py::class_<CancelFlag, std::shared_ptr<CancelFlag>>(
        m, "CancelFlag",
        "Pass as cancel= to a long call (check_validity, layout_sheets) running in another "
        "thread; cancel() makes it raise popupcore.Cancelled at its next checkpoint.")
        .def(py::init<>())
        .def("cancel", &CancelFlag::cancel)
        .def_property_readonly("cancelled", &CancelFlag::cancelled);
    // OCCT's Standard_Failure is not a std::exception in 7.6: translate it by itself.
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p)
                std::rethrow_exception(p);
        } catch (const DesignFailure& e) {
            py::object error = py::reinterpret_borrow<py::object>(design_error)(e.what());
            error.attr("diagnostics") = diagnostic_list(e.diagnostics);
            PyErr_SetObject(design_error, error.ptr());
        } catch (const Standard_Failure& e) {
            const char* msg = e.GetMessageString();
            PyErr_SetString(
                occt_error,
                (std::string(e.DynamicType()->Name()) + ": " + (msg ? msg : "")).c_str());
        } catch (const CGAL::Failure_exception& e) {
            PyErr_SetString(cgal_error, e.what());
        }
    });
    bind_mechanisms(m);
    bind_mechanism_catalogue(m);
    bind_options(m);
    bind_sheets(m);
    bind_sheet_set(m);
    bind_sheet_drawing(m);
    bind_model_mesh(m);
    bind_artwork(m);
    bind_render_view(m);
    bind_fitting(m);
    bind_model_input(m);
    bind_profiles(m);
    bind_motion_input(m);
    bind_motion(m);
    m.def("_raise_native", &raise_native, py::arg("kind"), py::arg("message"),
          "Test hook: throws a native exception of family 'std', 'invalid_argument', 'occt' or "
          "'cgal' so the translators can be checked.");

    bind_scaffold(m);
    bind_simulation(m);
}
