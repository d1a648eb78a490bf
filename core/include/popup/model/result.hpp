#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "popup/model/diagnostic_code.hpp"

namespace popup {

enum class Severity { error, warning, info };
const char* to_string(Severity severity);

/// What a diagnostic is about, as data the caller can act on without reading the message.
struct DiagnosticSubject {
    std::vector<int> patches;             ///< ids of the patches involved (to colour, to select)
    std::optional<std::string> parameter; ///< the parameter, option or file field at fault
    std::optional<double> angle_deg;      ///< the fold angle where it happens
};

inline DiagnosticSubject about_patches(std::vector<int> ids, std::optional<double> angle_deg = {})
{
    return {std::move(ids), std::nullopt, angle_deg};
}
inline DiagnosticSubject about_parameter(std::string name)
{
    return {{}, std::move(name), {}};
}

/// One finding a person can act on: a documented code, how bad it is, a sentence that names the
/// thing (patch, hinge, piece, tab, option), and that thing as data.
struct Diagnostic {
    DiagnosticCode code = DiagnosticCode::bad_option;
    Severity severity = Severity::error;
    std::string message;
    std::vector<int> patches;
    std::optional<std::string> parameter;
    std::optional<double> angle_deg;

    static Diagnostic make(DiagnosticCode code, Severity severity, std::string message,
                           DiagnosticSubject about = {})
    {
        return {code,
                severity,
                std::move(message),
                std::move(about.patches),
                std::move(about.parameter),
                about.angle_deg};
    }
    static Diagnostic error(DiagnosticCode code, std::string message, DiagnosticSubject about = {})
    {
        return make(code, Severity::error, std::move(message), std::move(about));
    }
    static Diagnostic warning(DiagnosticCode code, std::string message,
                              DiagnosticSubject about = {})
    {
        return make(code, Severity::warning, std::move(message), std::move(about));
    }
};

using Diagnostics = std::vector<Diagnostic>;

/// True when any diagnostic has severity error.
bool has_errors(const Diagnostics& diagnostics);

/// Adds the named error "NAME: PARAM = VALUE mm, must be RANGE".
void range_error(Diagnostics& errors, const std::string& mechanism, const std::string& parameter,
                 double value, const std::string& unit, const std::string& range);

/// A value plus the diagnostics gathered while computing it. `ok` is false when the value must
/// not be trusted (the diagnostics then say why).
template <class T> struct Result {
    T value{};
    bool ok = true;
    Diagnostics diagnostics;

    void fail(DiagnosticCode code, std::string message, DiagnosticSubject about = {})
    {
        ok = false;
        diagnostics.push_back(Diagnostic::error(code, std::move(message), std::move(about)));
    }
    /// Fails with the diagnostics of a step that failed.
    void fail_with(const Diagnostics& why)
    {
        ok = false;
        diagnostics = why;
    }
    void warn(DiagnosticCode code, std::string message, DiagnosticSubject about = {})
    {
        diagnostics.push_back(Diagnostic::warning(code, std::move(message), std::move(about)));
    }
};

} // namespace popup
