#pragma once
// One option of an options struct as a maker sees it (its name, what it does, its unit, its
// default, the range the core accepts), so that the pipelines' option tables (fit_options.cpp,
// motion_options.cpp) are the one place a range or a default is written: the core checks with
// them and the workbench builds its command-line flags and task panels from them.
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "popup/model/result.hpp"

namespace popup {

/// What an option holds, which decides how a flag or a widget reads it.
enum class OptionKind {
    number,    ///< a real number
    count,     ///< a whole number
    flag,      ///< on or off
    direction, ///< a 3-vector (a direction in the input's axes)
    point,     ///< a 2-vector (card mm)
    names,     ///< a list of names (empty: a rule decides, the doc says which)
};
const char* to_string(OptionKind kind);

struct OptionField {
    std::string name;  ///< as bound and in report.json: "max_mechanisms"
    std::string group; ///< the nested struct it sits in ("view", "chains"), "" at the top
    std::string doc;   ///< one line
    /// "mm" or "°" (written after a number), or what the number is a fraction of ("a fraction of
    /// the model's diagonal", written after the range in brackets); empty for a count
    std::string unit;
    OptionKind kind = OptionKind::number;
    double default_value = std::numeric_limits<double>::quiet_NaN(); ///< NaN: none (optional)
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool min_open = false; ///< min itself is refused
    bool max_open = false; ///< max itself is refused
    bool optional = false; ///< may be left unset: a rule then decides (doc says which)

    /// A finite value within [min, max] (an open end refused). Only for number, count, flag.
    bool accepts(double value) const;
    /// The range as errors and help texts state it: "1 to 32", ">= 20 and <= 2000 mm",
    /// "> 0 and < 1 (a fraction of the model's diagonal)", "any finite number" without bounds;
    /// "on or off" for a flag, and what a vector must be.
    std::string range() const;

    // The table's vocabulary: number("margin", doc, unit).at_least(0).below(0.4).
    static OptionField number(std::string name, std::string doc, std::string unit = "");
    static OptionField count(std::string name, std::string doc);
    static OptionField on_off(std::string name, std::string doc);
    static OptionField vector(OptionKind kind, std::string name, std::string doc);
    OptionField at_least(double low) const;
    OptionField above(double low) const;
    OptionField at_most(double high) const;
    OptionField below(double high) const;
    OptionField in(std::string group_name) const;
    OptionField unset_by_default() const;
};

/// "OWNER.NAME = VALUE, must be RANGE" (bad_option, about the option's name) unless the field
/// accepts `value`.
void check_option(Diagnostics& errors, const std::string& owner, const OptionField& field,
                  double value);

/// One row of an options struct's table: its field and how to read its value (none, or an empty
/// optional, for what has no range to check: a direction, an option left unset).
template <class Options> struct OptionRow {
    OptionField field;
    std::function<std::optional<double>(const Options&)> value = nullptr;
};

/// The rows with each field's default read from a default-made Options, so a default is written
/// once, in the struct.
template <class Options>
std::vector<OptionRow<Options>> with_struct_defaults(std::vector<OptionRow<Options>> rows)
{
    const Options defaults = Options();
    for (OptionRow<Options>& row : rows)
        if (row.value)
            if (const std::optional<double> value = row.value(defaults))
                row.field.default_value = *value;
    return rows;
}

template <class Options>
std::vector<OptionField> fields_of(const std::vector<OptionRow<Options>>& rows)
{
    std::vector<OptionField> fields;
    for (const OptionRow<Options>& row : rows)
        fields.push_back(row.field);
    return fields;
}

/// check_option on every row that has a value; `owner` names a field of the top struct,
/// `group_owner` one of its nested group.
template <class Options>
void check_rows(Diagnostics& errors, const std::vector<OptionRow<Options>>& rows,
                const Options& options, const std::string& owner,
                const std::string& group_owner = "")
{
    for (const OptionRow<Options>& row : rows)
        if (row.value)
            if (const std::optional<double> value = row.value(options))
                check_option(errors, row.field.group.empty() ? owner : group_owner, row.field,
                             *value);
}

/// A number as messages write it (6 significant digits; whole numbers in full up to 1e15).
std::string option_number(double value);

} // namespace popup
