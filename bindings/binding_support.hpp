#pragma once
// Shared by the binding files: how core results with diagnostics become Python errors.
#include <map>
#include <sstream>
#include <stdexcept>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "popup/model/result.hpp"
#include "popup/sheets/sheet_layout.hpp"

namespace popup::bindings {

inline std::string join(const Diagnostics& diagnostics)
{
    std::ostringstream s;
    for (size_t i = 0; i < diagnostics.size(); ++i)
        s << (i ? "; " : "") << diagnostics[i].message;
    return s.str();
}

/// Raised for invalid designs and parameters; popupcore.DesignError on the Python side, which
/// carries the diagnostics as `.diagnostics` (a list of dicts).
struct DesignFailure : std::runtime_error {
    explicit DesignFailure(Diagnostics why)
        : std::runtime_error(join(why)), diagnostics(std::move(why))
    {
    }
    Diagnostics diagnostics;
};

/// A diagnostic as the dict every Python caller and --json output uses (docs/SHEET_FORMAT.md).
inline pybind11::dict diagnostic_dict(const Diagnostic& d)
{
    namespace py = pybind11;
    return py::dict(py::arg("code") = to_string(d.code),
                    py::arg("severity") = to_string(d.severity), py::arg("message") = d.message,
                    py::arg("patches") = d.patches, py::arg("parameter") = d.parameter,
                    py::arg("angle_deg") = d.angle_deg);
}

inline pybind11::list diagnostic_list(const Diagnostics& diagnostics)
{
    pybind11::list out;
    for (const Diagnostic& d : diagnostics)
        out.append(diagnostic_dict(d));
    return out;
}

/// The value, or DesignFailure with every diagnostic.
template <class T> T unwrap(Result<T> r)
{
    if (!r.ok)
        throw DesignFailure(std::move(r.diagnostics));
    return std::move(r.value);
}

/// {piece id: "front" or "back"} as the core's printed sides; anything else is a named error.
inline std::map<std::string, PrintedSide>
printed_sides_from(const std::map<std::string, std::string>& sides)
{
    std::map<std::string, PrintedSide> chosen;
    for (const auto& [id, side] : sides) {
        if (side != "front" && side != "back")
            throw DesignFailure({Diagnostic::error(DiagnosticCode::bad_option,
                                                   "printed side of " + id + " = '" + side +
                                                       "', must be front or back",
                                                   about_parameter("printed_sides"))});
        chosen[id] = side == "back" ? PrintedSide::back : PrintedSide::front;
    }
    return chosen;
}

} // namespace popup::bindings

void bind_mechanisms(pybind11::module_& m);
void bind_mechanism_catalogue(pybind11::module_& m);
void bind_options(pybind11::module_& m);
void bind_sheets(pybind11::module_& m);
void bind_sheet_drawing(pybind11::module_& m);
void bind_sheet_set(pybind11::module_& m);
void bind_model_mesh(pybind11::module_& m);
void bind_artwork(pybind11::module_& m);
void bind_render_view(pybind11::module_& m);
void bind_fitting(pybind11::module_& m);
void bind_model_input(pybind11::module_& m);
void bind_profiles(pybind11::module_& m);
void bind_motion_input(pybind11::module_& m);
void bind_motion(pybind11::module_& m);
