#pragma once
// Shared by the binding files: how core results with diagnostics become Python errors.
#include <sstream>
#include <stdexcept>

#include <pybind11/pybind11.h>

#include "popup/result.hpp"

namespace popup::bindings {

/// Raised for invalid designs and parameters; popupcore.DesignError on the Python side.
struct DesignFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

inline std::string join(const Diagnostics& diagnostics)
{
    std::ostringstream s;
    for (size_t i = 0; i < diagnostics.size(); ++i)
        s << (i ? "; " : "") << diagnostics[i].subject << ": " << diagnostics[i].message;
    return s.str();
}

/// The value, or DesignFailure with every diagnostic.
template <class T> T unwrap(Result<T> r)
{
    if (!r.ok)
        throw DesignFailure(join(r.diagnostics));
    return std::move(r.value);
}

} // namespace popup::bindings

void bind_mechanisms(pybind11::module_& m);
void bind_sheets(pybind11::module_& m);
