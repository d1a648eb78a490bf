#include "popup/model/diagnostic_code.hpp"
#include "popup/model/result.hpp"

#include <sstream>

namespace popup {

const char* to_string(DiagnosticCode code)
{
    switch (code) {
#define POPUP_DIAGNOSTIC_NAME(name)                                                                \
    case DiagnosticCode::name:                                                                     \
        return #name;
        POPUP_DIAGNOSTIC_CODES(POPUP_DIAGNOSTIC_NAME)
#undef POPUP_DIAGNOSTIC_NAME
    }
    return "unknown";
}

const std::vector<DiagnosticCode>& all_diagnostic_codes()
{
    static const std::vector<DiagnosticCode> codes = {
#define POPUP_DIAGNOSTIC_VALUE(name) DiagnosticCode::name,
        POPUP_DIAGNOSTIC_CODES(POPUP_DIAGNOSTIC_VALUE)
#undef POPUP_DIAGNOSTIC_VALUE
    };
    return codes;
}

std::optional<DiagnosticCode> diagnostic_code_named(const std::string& name)
{
    for (DiagnosticCode code : all_diagnostic_codes())
        if (name == to_string(code))
            return code;
    return std::nullopt;
}

const char* to_string(Severity severity)
{
    switch (severity) {
    case Severity::error:
        return "error";
    case Severity::warning:
        return "warning";
    case Severity::info:
        return "info";
    }
    return "error";
}

bool has_errors(const Diagnostics& diagnostics)
{
    for (const Diagnostic& d : diagnostics)
        if (d.severity == Severity::error)
            return true;
    return false;
}

void range_error(Diagnostics& errors, const std::string& mechanism, const std::string& parameter,
                 double value, const std::string& unit, const std::string& range)
{
    std::ostringstream m;
    m << mechanism << ": " << parameter << " = " << value << (unit.empty() ? "" : " ") << unit
      << ", must be " << range;
    errors.push_back(
        Diagnostic::error(DiagnosticCode::bad_parameter, m.str(), about_parameter(parameter)));
}

} // namespace popup
