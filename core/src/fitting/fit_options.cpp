// FitOptions' one table: every option's name, doc, unit, default and range, which
// check_fit_options checks and the workbench reads (popupcore.FitOptions.fields()).
#include <algorithm>
#include <cmath>

#include "popup/fitting/fit_design.hpp"

namespace popup {
namespace {

using Field = OptionField;
constexpr auto direction = OptionKind::direction;

using FitField = OptionRow<FitOptions>; // no value for a direction: it has no range

const std::vector<FitField>& fit_fields()
{
    static const std::vector<FitField> fields = [] {
        const std::string of_diagonal = "a fraction of the model's diagonal";
        std::vector<FitField> table = {
            {Field::vector(direction, "up",
                           "model direction that becomes up on the card (z); unset: from the "
                           "model's normals (NPCA)")
                 .unset_by_default()},
            {Field::vector(direction, "facing",
                           "model direction that faces the viewer of the open card; unset: the "
                           "normal of the model's mirror plane containing up")
                 .unset_by_default()},
            {Field::number("card_width", "the card along its central fold", "mm")
                 .at_least(20)
                 .at_most(2000),
             [](const FitOptions& o) { return o.card.width; }},
            {Field::number("card_depth", "each page of the card, from the fold to its edge", "mm")
                 .at_least(20)
                 .at_most(2000),
             [](const FitOptions& o) { return o.card.depth; }},
            {Field::number("margin", "free border kept on every side of the card",
                           "a fraction of each card dimension")
                 .at_least(0)
                 .below(0.4),
             [](const FitOptions& o) { return o.margin; }},
            {Field::count("max_mechanisms", "at most this many mechanisms").at_least(1).at_most(32),
             [](const FitOptions& o) { return double(o.max_mechanisms); }},
            {Field::number("min_shape", "smallest primitive worth finding: a cube of this edge",
                           of_diagonal)
                 .above(0)
                 .below(1),
             [](const FitOptions& o) { return o.min_shape; }},
            {Field::number("probability",
                           "the search stops when no better primitive was overlooked with this "
                           "probability")
                 .above(0)
                 .below(1),
             [](const FitOptions& o) { return o.probability; }},
            {Field::number("threshold", "distance within which a point lies on a primitive",
                           of_diagonal)
                 .above(0)
                 .at_most(0.2),
             [](const FitOptions& o) { return o.threshold; }},
            {Field::count("samples", "pseudo-vertices spread over the model's surface")
                 .at_least(500)
                 .at_most(2000000),
             [](const FitOptions& o) { return double(o.samples); }},
            {Field::number("min_part_mm",
                           "shortest glued crease a mechanism may have (default: what the "
                           "cutting sheets' narrowest glue tab needs; 0 allows any), at most a "
                           "quarter of the card's smaller side",
                           "mm")
                 .at_least(0),
             [](const FitOptions& o) { return o.min_part_mm; }},
            {Field::count("seed", "random seed; same seed, same design").at_least(0).at_most(1e18),
             [](const FitOptions& o) { return double(o.seed); }},
            {Field::on_off("outlines", "principal patches take the model's silhouette"),
             [](const FitOptions& o) { return double(o.outlines); }},
            {Field::on_off("depth_layers",
                           "parts of the model standing proud of a box fold's front, back or "
                           "top become nested mechanisms (needs outlines)"),
             [](const FitOptions& o) { return double(o.depth_layers); }},
        };
        return with_struct_defaults(table);
    }();
    return fields;
}

} // namespace

const std::vector<OptionField>& fit_option_fields()
{
    static const std::vector<OptionField> fields = fields_of(fit_fields());
    return fields;
}

Diagnostics check_fit_options(const FitOptions& o)
{
    Diagnostics d;
    check_rows(d, fit_fields(), o, "FitOptions");
    // min_part_mm's upper end depends on the card: a quarter of its smaller side.
    const double quarter = 0.25 * std::min(o.card.width, o.card.depth);
    if (std::isfinite(o.min_part_mm) && o.min_part_mm > quarter)
        d.push_back(Diagnostic::error(
            DiagnosticCode::bad_option,
            "FitOptions.min_part_mm = " + option_number(o.min_part_mm) +
                ", must be >= 0 and <= a quarter of the card's smaller dimension (" +
                option_number(quarter) + " mm)",
            about_parameter("min_part_mm")));
    return d;
}

} // namespace popup
