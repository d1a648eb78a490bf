// MotionView's one table: every option's name, doc, unit, default and range, which
// check_motion_view checks and the workbench reads (popupcore.MotionOptions.fields(), "view").
#include "popup/motion/motion_view.hpp"

#include <optional>
#include <sstream>

namespace popup {
namespace {

using Field = OptionField;

/// No value for a vector (checked on its own below), none either for an optional left unset.
using ViewField = OptionRow<MotionView>;

const std::vector<ViewField>& view_fields()
{
    static const std::vector<ViewField> fields = [] {
        std::vector<ViewField> table = {
            {Field::vector(OptionKind::direction, "view",
                           "direction from the eye toward the character, in the file's axes")},
            {Field::vector(OptionKind::direction, "up",
                           "the file's direction that becomes up on the card")},
            {Field::number("scale",
                           "card mm per file unit; unset: the character's projected box fits "
                           "the card inside the margin",
                           "mm per file unit")
                 .above(0)
                 .unset_by_default(),
             [](const MotionView& v) { return v.scale; }},
            {Field::vector(OptionKind::point, "centre",
                           "card (x, y) mm of the character's projected box's centre; unset: "
                           "(0, half the card's width)")
                 .unset_by_default()},
            {Field::number("margin", "free border kept on every side of the card",
                           "a fraction of each card dimension")
                 .at_least(0)
                 .below(0.5),
             [](const MotionView& v) { return std::optional<double>(v.margin); }},
            {Field::number("card_width", "the card along its central fold", "mm")
                 .above(0)
                 .at_most(2000),
             [](const MotionView& v) { return std::optional<double>(v.card.width); }},
            {Field::number("card_depth", "each page of the card, from the fold to its edge", "mm")
                 .above(0)
                 .at_most(2000),
             [](const MotionView& v) { return std::optional<double>(v.card.depth); }},
            {Field::count("first_frame", "the frame shown when the card is closed (with the "
                                         "whole take's 0 and -1, the frames a card can follow "
                                         "best are chosen: auto_frames)")
                 .at_least(0),
             [](const MotionView& v) { return std::optional<double>(v.first_frame); }},
            {Field::count("last_frame", "the frame shown when the card is open flat; -1: the last")
                 .at_least(-1),
             [](const MotionView& v) { return std::optional<double>(v.last_frame); }},
            {Field::number("angle_tolerance",
                           "a path is sampled more finely where it turns more than this", "°")
                 .above(0)
                 .below(90),
             [](const MotionView& v) { return std::optional<double>(v.angle_tolerance); }},
            {Field::count("min_intervals",
                          "the adaptive sampling starts from this many equal intervals")
                 .at_least(1)
                 .at_most(1000),
             [](const MotionView& v) { return std::optional<double>(v.min_intervals); }},
            {Field::on_off("keep_travel",
                           "keep a character's travel along the ground (a walk) instead of "
                           "keeping it in place"),
             [](const MotionView& v) { return std::optional<double>(v.keep_travel); }},
            {Field::on_off("auto_frames",
                           "with the whole take's frames (first 0, last -1), show the frames a "
                           "card can follow best"),
             [](const MotionView& v) { return std::optional<double>(v.auto_frames); }},
        };
        return with_struct_defaults(table);
    }();
    return fields;
}

std::string text(const Vec3& v)
{
    std::ostringstream s;
    s << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
    return s.str();
}

void refuse(Diagnostics& errors, const std::string& option, const std::string& why)
{
    errors.push_back(Diagnostic::error(
        DiagnosticCode::bad_option, "MotionView." + option + " " + why, about_parameter(option)));
}

// view and up: finite, non-zero, and across each other (the card's axes come from them).
void check_directions(const MotionView& view, Diagnostics& errors)
{
    const bool view_ok = view.view.allFinite() && view.view.norm() >= 1e-12;
    const bool up_ok = view.up.allFinite() && view.up.norm() >= 1e-12;
    if (!view_ok)
        refuse(errors, "view", "= " + text(view.view) + ", must be a finite non-zero direction");
    if (!up_ok)
        refuse(errors, "up", "= " + text(view.up) + ", must be a finite non-zero direction");
    if (view_ok && up_ok && view.up.normalized().cross(view.view.normalized()).norm() < 1e-6)
        refuse(errors, "up",
               "= " + text(view.up) + " is parallel to view " + text(view.view) +
                   ", must be across it");
}

} // namespace

const std::vector<OptionField>& motion_view_fields()
{
    static const std::vector<OptionField> fields = fields_of(view_fields());
    return fields;
}

Diagnostics check_motion_view(const MotionView& view)
{
    Diagnostics errors;
    check_directions(view, errors);
    check_rows(errors, view_fields(), view, "MotionView");
    if (view.centre && !view.centre->allFinite())
        refuse(errors, "centre", "must be finite");
    if (view.last_frame >= 0 && view.first_frame >= 0 && view.last_frame <= view.first_frame)
        refuse(errors, "last_frame",
               "= " + std::to_string(view.last_frame) + ", must be -1 (the last) or after " +
                   "first_frame " + std::to_string(view.first_frame));
    return errors;
}

} // namespace popup
