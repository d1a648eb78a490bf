#include "verify_fixtures.hpp"

#include <gtest/gtest.h>

namespace popup::verify_fixtures {

Laid laid_out(const Scaffold& s)
{
    SheetOptions o;
    o.nest.paper = paper_by_name("A3").value;
    Result<SheetSet> r = layout_sheets(s, o);
    EXPECT_TRUE(r.ok);
    return {s, r.value};
}

std::vector<Diagnostic> errors_with(const Result<RoundTrip>& r, DiagnosticCode code)
{
    std::vector<Diagnostic> found;
    for (const Diagnostic& d : r.diagnostics)
        if (d.code == code && d.severity == Severity::error)
            found.push_back(d);
    return found;
}

double first_number_before_mm(const std::string& message)
{
    const size_t mm = message.find(" mm");
    size_t start = message.rfind(' ', mm - 1);
    return std::stod(message.substr(start + 1, mm - start - 1));
}

} // namespace popup::verify_fixtures
