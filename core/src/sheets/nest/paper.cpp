#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>

#include "popup/sheets/nest.hpp"

namespace popup {

namespace {

constexpr double kLargestCustomSide = 1000.0; // mm; Clipper's fast integer range ends near 1 m

const std::array<Paper, 4> kPresets{{
    {"A4", 210.0, 297.0},
    {"A3", 297.0, 420.0},
    {"Letter", 215.9, 279.4},
    {"Tabloid", 279.4, 431.8},
}};

std::string lower_case(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

std::string trimmed(const std::string& text)
{
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string::npos)
        return {};
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

/// A whole-string decimal number; std::from_chars ignores the locale (FreeCAD may set one with
/// decimal commas).
bool parse_side(const std::string& text, double& side)
{
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, side);
    return error == std::errc() && stop == end;
}

} // namespace

Result<Paper> paper_by_name(const std::string& name)
{
    Result<Paper> result;
    const std::string key = lower_case(trimmed(name));
    for (const Paper& preset : kPresets) {
        if (lower_case(preset.name) == key) {
            result.value = preset;
            return result;
        }
    }

    const auto cross = key.find('x');
    double width = 0.0;
    double height = 0.0;
    if (cross != std::string::npos && parse_side(trimmed(key.substr(0, cross)), width) &&
        parse_side(trimmed(key.substr(cross + 1)), height) && width > 0.0 && height > 0.0 &&
        width <= kLargestCustomSide && height <= kLargestCustomSide) {
        result.value = {key, width, height};
        return result;
    }
    result.fail(DiagnosticCode::bad_paper,
                "unknown paper \"" + name +
                    "\": use A4, A3, Letter, Tabloid or \"<width>x<height>\" in mm (e.g. "
                    "\"300x200\") with each side greater than 0 and at most 1000 mm",
                about_parameter("paper"));
    return result;
}

} // namespace popup
