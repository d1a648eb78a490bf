#include "popup/model/option_field.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace popup {

const char* to_string(OptionKind kind)
{
    switch (kind) {
    case OptionKind::number:
        return "number";
    case OptionKind::count:
        return "count";
    case OptionKind::flag:
        return "flag";
    case OptionKind::direction:
        return "direction";
    case OptionKind::point:
        return "point";
    case OptionKind::names:
        return "names";
    }
    return "number";
}

std::string option_number(double value)
{
    std::ostringstream s;
    if (std::isfinite(value) && value == std::floor(value) && std::abs(value) < 1e15)
        s << std::fixed << std::setprecision(0) << value;
    else
        s << value;
    return s.str();
}

bool OptionField::accepts(double value) const
{
    if (!std::isfinite(value))
        return false;
    const bool low_ok = min_open ? value > min : value >= min;
    const bool high_ok = max_open ? value < max : value <= max;
    return low_ok && high_ok;
}

std::string OptionField::range() const
{
    if (kind == OptionKind::flag)
        return "on or off";
    if (kind == OptionKind::direction)
        return "a finite non-zero direction (3 numbers)";
    if (kind == OptionKind::point)
        return "a finite point (2 numbers)";
    if (kind == OptionKind::names)
        return "a list of names";
    const bool low = std::isfinite(min), high = std::isfinite(max);
    std::string text;
    if (kind == OptionKind::count && low && high && !min_open && !max_open)
        text = option_number(min) + " to " + option_number(max);
    else if (low || high) {
        if (low)
            text = (min_open ? "> " : ">= ") + option_number(min);
        if (high)
            text +=
                (low ? " and " : "") + std::string(max_open ? "< " : "<= ") + option_number(max);
    } else
        return "any finite number";
    if (unit == "°")
        return text + unit;
    if (unit == "mm")
        return text + " " + unit;
    return unit.empty() ? text : text + " (" + unit + ")";
}

OptionField OptionField::number(std::string name, std::string doc, std::string unit)
{
    OptionField f;
    f.name = std::move(name);
    f.doc = std::move(doc);
    f.unit = std::move(unit);
    return f;
}

OptionField OptionField::count(std::string name, std::string doc)
{
    OptionField f = number(std::move(name), std::move(doc));
    f.kind = OptionKind::count;
    return f;
}

OptionField OptionField::on_off(std::string name, std::string doc)
{
    OptionField f = number(std::move(name), std::move(doc));
    f.kind = OptionKind::flag;
    f.min = 0;
    f.max = 1;
    return f;
}

OptionField OptionField::vector(OptionKind kind, std::string name, std::string doc)
{
    OptionField f = number(std::move(name), std::move(doc));
    f.kind = kind;
    return f;
}

OptionField OptionField::at_least(double low) const
{
    OptionField f = *this;
    f.min = low;
    f.min_open = false;
    return f;
}

OptionField OptionField::above(double low) const
{
    OptionField f = at_least(low);
    f.min_open = true;
    return f;
}

OptionField OptionField::at_most(double high) const
{
    OptionField f = *this;
    f.max = high;
    f.max_open = false;
    return f;
}

OptionField OptionField::below(double high) const
{
    OptionField f = at_most(high);
    f.max_open = true;
    return f;
}

OptionField OptionField::in(std::string group_name) const
{
    OptionField f = *this;
    f.group = std::move(group_name);
    return f;
}

OptionField OptionField::unset_by_default() const
{
    OptionField f = *this;
    f.optional = true;
    return f;
}

void check_option(Diagnostics& errors, const std::string& owner, const OptionField& field,
                  double value)
{
    if (field.accepts(value))
        return;
    errors.push_back(Diagnostic::error(DiagnosticCode::bad_option,
                                       owner + "." + field.name + " = " + option_number(value) +
                                           ", must be " + field.range(),
                                       about_parameter(field.name)));
}

} // namespace popup
