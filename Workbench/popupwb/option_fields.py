"""The core's option tables as the workbench reads them. popupcore.FitOptions.fields() and
MotionOptions.fields() (core/src/fitting/fit_options.cpp, core/src/motion/motion_options.cpp and
motion_view.cpp) give each option's name, doc, unit, default and range: `popup fit` and `popup
animate` take their flags' help and checks from them, the From-model and From-animation panels
their boxes, fit_run and motion_run their options, and the reports the options used. Nothing here
restates a range or a default.

A field is a popupcore.OptionField: .name, .group ("" or the nested options it sits in: "view",
"chains"), .doc, .unit, .kind (number, count, flag, direction, point, names), .default (None when unset
by default), .min, .max, .range (the text errors use) and .accepts(value).
"""

import math


def fields(options_type):
    """{name: OptionField} of popupcore.<options_type> ("FitOptions", "MotionOptions"), in the
    core's order; {} when popupcore does not import (the CLI's --help still works, and a run
    says what is missing)."""
    try:
        from popupwb.core import popupcore
    except ImportError:
        return {}
    return {field.name: field for field in getattr(popupcore, options_type).fields()}


def value_text(value):
    """A value as an error shows it: 8, 0.5, nan, -inf."""
    return f"{value:g}" if isinstance(value, float) else str(value)


def range_text(field, low=None):
    """The field's range as the core states it; from `low` instead of its minimum when a caller
    asks for more than the core does (a count)."""
    if low is None or low <= field.min:
        return field.range
    return f"{low:g} to {value_text(_whole(field.max))}"


def default_text(field):
    """'default 8'; '' when the default is unset (a rule decides: the doc says which)."""
    if field.default is None:
        return ""
    return f"default {value_text(field.default)}"


def help_text(field, low=None):
    """A flag's help: the doc, the range and the default ("at most this many mechanisms; 1 to
    32; default 8"); None without the core."""
    if field is None:
        return None
    parts = [field.doc]
    if field.kind in ("number", "count"):
        parts += [range_text(field, low), default_text(field)]
    return "; ".join(part for part in parts if part)


def add_flag(parser, flag, field, metavar, low=None):
    """`flag` for a number or count option: its type from the field's kind (int for a count),
    its help from the field; left out, its value is None and the core's default holds."""
    kind = field.kind if field is not None else "number"
    parser.add_argument(
        flag, type=int if kind == "count" else float, metavar=metavar, help=help_text(field, low)
    )


def add_vector_flag(parser, flag, field, options_type, metavar="X,Y,Z"):
    """`flag` X,Y,Z for a direction option, its help the field's doc and the default of a fresh
    popupcore.<options_type> (none when unset by default)."""
    if field is None:
        parser.add_argument(flag, metavar=metavar)
        return
    from popupwb.core import popupcore

    options = getattr(popupcore, options_type)()
    holder = getattr(options, field.group) if field.group else options
    default = getattr(holder, field.name)
    shown = "" if default is None else "; default " + ",".join(f"{v:g}" for v in default)
    parser.add_argument(flag, metavar=metavar, help=field.doc + shown)


def check(field, value, flag, low=None):
    """`value` when the field accepts it (and it is at least `low`); else ValueError naming the
    flag, the value and the range: "--max-mechanisms 0: must be 1 to 32"."""
    if field is None or value is None:
        return value
    ok = field.accepts(float(value)) and (low is None or value >= low)
    if not ok:
        raise ValueError(f"{flag} {value_text(value)}: must be {range_text(field, low)}")
    return value


def set_options(options, table, values):
    """Sets each {name: value} that is not None on `options` (a grouped field on its nested
    options: options.view.first_frame), checked against its field first; ValueError naming the
    option and its range. Vectors and lists of names are set as they are (the binding checks a
    vector's length)."""
    for name, value in values.items():
        if value is None:
            continue
        field = table[name]
        if field.kind in ("number", "count", "flag") and not field.accepts(float(value)):
            raise ValueError(f"{name} = {value_text(value)}, must be {field.range}")
        if field.kind == "count":
            value = int(value)
        elif field.kind == "number":
            value = float(value)
        holder = getattr(options, field.group) if field.group else options
        setattr(holder, name, value)
    return options


def raise_if_bad(options, flags=None):
    """`options`, or ValueError with the core's own messages when options.check() finds an
    option out of range or two that do not go together (the card's size and min_part_mm, view
    and up, the frame range). `flags` {option name: "--flag VALUE"} leads each message about
    that option with the flag the user typed."""
    bad = options.check()
    if bad:
        raise ValueError("; ".join(_led_by_flag(d, flags or {}) for d in bad))
    return options


def _led_by_flag(diagnostic, flags):
    flag = flags.get(diagnostic.get("parameter"))
    return f"{flag}: {diagnostic['message']}" if flag else diagnostic["message"]


def as_dict(options, table):
    """The options as plain JSON values, a group's in a dict of its own (for the reports)."""
    values = {}
    for field in table.values():
        holder = getattr(options, field.group) if field.group else options
        target = values.setdefault(field.group, {}) if field.group else values
        target[field.name] = _plain(getattr(holder, field.name))
    return values


def _plain(value):
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, (list, tuple)) and all(isinstance(v, str) for v in value):
        return list(value)  # names (animate_only); [] stays []
    try:
        return [float(v) for v in value]
    except TypeError:
        return str(value)


def _whole(number):
    return int(number) if math.isfinite(number) else number
