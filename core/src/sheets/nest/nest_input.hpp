#pragma once
// What the true-shape nester and the shelf packer share: checking the options and the shapes,
// and each shape's outline in Clipper units. Header-only: popup_core lists one source per packer.
#include <algorithm>
#include <cmath>
#include <limits>
#include <locale>
#include <sstream>
#include <string>
#include <vector>

#include "../../geometry/clipper_paths.hpp"
#include "bounds.hpp"
#include "popup/sheets/nest.hpp"

namespace popup::nest_detail {

/// A shape's outer loop, counter-clockwise, in Clipper units, shifted so that its bounding box
/// starts at the origin: shape point p lies at (p - shift) · clipper_scale.
struct Outline {
    ClipperLib::Path path;
    Vec2 shift = Vec2::Zero();
    ClipperLib::cInt width = 0;
    ClipperLib::cInt height = 0;
    double area = 0.0; ///< mm²
};

constexpr double kLargestPaperSide = 1e6; // mm; keeps Clipper units far from overflow

inline ClipperLib::cInt to_units(double mm)
{
    return static_cast<ClipperLib::cInt>(std::llround(mm * clipper_scale));
}

/// `value` in mm with `decimals` digits, or as short as possible when decimals < 0; never a
/// decimal comma, whatever the locale.
inline std::string format_mm(double value, int decimals = -1)
{
    std::ostringstream out;
    out.imbue(std::locale::classic());
    if (decimals >= 0)
        out << std::fixed;
    out.precision(decimals >= 0 ? decimals : 6);
    out << value;
    return out.str();
}

inline std::string shape_label(const NestShape& shape, std::size_t index)
{
    return shape.name.empty() ? "shape " + std::to_string(index) : shape.name;
}

/// Where the uninflated outlines may lie on a sheet.
inline Bounds printable_area(const NestOptions& options)
{
    return {to_units(options.margin), to_units(options.margin),
            to_units(options.paper.width - options.margin),
            to_units(options.paper.height - options.margin)};
}

/// Checks paper, margin and spacing; an error names the option and the allowed range.
inline void check_options(const NestOptions& options, Result<std::vector<Outline>>& result)
{
    const Paper& paper = options.paper;
    const std::string paper_size =
        format_mm(paper.width, 1) + " x " + format_mm(paper.height, 1) + " mm";
    if (!(paper.width > 0.0 && paper.height > 0.0 && paper.width <= kLargestPaperSide &&
          paper.height <= kLargestPaperSide)) {
        result.fail(DiagnosticCode::bad_paper,
                    "paper " + paper.name + " is " + paper_size +
                        "; width and height must be greater than 0 and at most " +
                        format_mm(kLargestPaperSide) + " mm",
                    about_parameter("paper"));
        return;
    }
    const double largest_margin = 0.5 * std::min(paper.width, paper.height);
    const std::string allowed_margin = "; allowed: at least 0 mm and less than " +
                                       format_mm(largest_margin) + " mm (half the paper's " +
                                       "shorter side)";
    if (!(options.margin >= 0.0))
        result.fail(DiagnosticCode::bad_margin,
                    "margin " + format_mm(options.margin) + " mm" + allowed_margin,
                    about_parameter("margin"));
    else if (options.margin >= largest_margin)
        result.fail(DiagnosticCode::bad_margin,
                    "margin " + format_mm(options.margin) + " mm leaves no printable area on " +
                        paper.name + " (" + paper_size + ")" + allowed_margin,
                    about_parameter("margin"));
    if (!(options.spacing >= 0.0 && options.spacing < largest_margin * 2.0))
        result.fail(DiagnosticCode::bad_spacing,
                    "spacing " + format_mm(options.spacing) +
                        " mm; allowed: at least 0 mm and less than " +
                        format_mm(2.0 * largest_margin) + " mm",
                    about_parameter("spacing"));
}

/// The outline of one shape, or an error naming it.
inline void add_outline(const NestShape& shape, std::size_t index, const NestOptions& options,
                        Result<std::vector<Outline>>& result)
{
    const std::string label = shape_label(shape, index);
    Outline outline;
    if (shape.outer.size() < 3) {
        result.fail(DiagnosticCode::bad_shape, label + " has " +
                                                   std::to_string(shape.outer.size()) +
                                                   " outline points; it needs at least 3");
        result.value.push_back(outline);
        return;
    }
    Vec2 low = Vec2::Constant(std::numeric_limits<double>::infinity());
    Vec2 high = -low;
    for (const Vec2& p : shape.outer) {
        low = low.cwiseMin(p);
        high = high.cwiseMax(p);
    }
    const Vec2 size = high - low;
    if (!size.allFinite() || size.maxCoeff() > kLargestPaperSide) {
        result.fail(DiagnosticCode::bad_shape,
                    label + " has a coordinate that is not finite or too large");
        result.value.push_back(outline);
        return;
    }

    outline.shift = low;
    for (const Vec2& p : shape.outer)
        outline.path.push_back(to_int_point(p - low));
    ClipperLib::CleanPolygon(outline.path);
    if (outline.path.size() >= 3 && !ClipperLib::Orientation(outline.path))
        ClipperLib::ReversePath(outline.path);
    outline.area = outline.path.size() < 3 ? 0.0 : path_area(outline.path);
    if (outline.area < 1e-6) { // a square micrometre: nothing a cutter could make
        result.fail(DiagnosticCode::bad_shape, label + " has zero area");
        result.value.push_back(outline);
        return;
    }
    outline.width = to_units(size.x());
    outline.height = to_units(size.y());

    const Bounds printable = printable_area(options);
    const bool fits_upright =
        outline.width <= printable.width() && outline.height <= printable.height();
    const bool fits_turned = options.rotate && outline.height <= printable.width() &&
                             outline.width <= printable.height();
    if (!fits_upright && !fits_turned) {
        const Paper& paper = options.paper;
        const std::string paper_label = paper.name.empty()
                                            ? "the " + format_mm(paper.width, 1) + " x " +
                                                  format_mm(paper.height, 1) + " mm paper"
                                            : paper.name;
        result.fail(DiagnosticCode::piece_does_not_fit,
                    label + " (" + format_mm(size.x(), 1) + " x " + format_mm(size.y(), 1) +
                        " mm) does not fit the printable area " +
                        format_mm(paper.width - 2.0 * options.margin, 1) + " x " +
                        format_mm(paper.height - 2.0 * options.margin, 1) + " mm of " +
                        paper_label + " with " + format_mm(options.margin) + " mm margins" +
                        (options.rotate ? "" : " (turning not allowed)"),
                    about_parameter("paper"));
    }
    result.value.push_back(outline);
}

/// Every shape's outline (one per shape, same order), or the errors in the options or shapes.
inline Result<std::vector<Outline>> prepare_outlines(const std::vector<NestShape>& shapes,
                                                     const NestOptions& options)
{
    Result<std::vector<Outline>> result;
    check_options(options, result);
    if (!result.ok)
        return result;
    for (std::size_t i = 0; i < shapes.size(); ++i)
        add_outline(shapes[i], i, options, result);
    return result;
}

/// Copies the errors of the preparation into the packer's result.
template <class T> Result<Nesting> failed_nesting(const Result<T>& cause)
{
    Result<Nesting> result;
    result.ok = false;
    result.diagnostics = cause.diagnostics;
    return result;
}

} // namespace popup::nest_detail
