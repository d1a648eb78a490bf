#pragma once
// A design laid out on sheets, and the findings of verify_sheets read back: the verify tests'
// shared fixtures.
#include <string>
#include <vector>

#include "popup/sheets/sheet_layout.hpp"

namespace popup::verify_fixtures {

struct Laid {
    Scaffold design;
    SheetSet sheets;
};

/// The design laid out on A3 with the default options (expected to succeed).
Laid laid_out(const Scaffold& s);

/// The errors of `r` with `code`.
std::vector<Diagnostic> errors_with(const Result<RoundTrip>& r, DiagnosticCode code);

/// The first number in a message ("… drawn 0.5 mm off …").
double first_number_before_mm(const std::string& message);

} // namespace popup::verify_fixtures
