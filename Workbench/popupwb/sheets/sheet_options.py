"""The one table of cutting-sheet layout options: `popup sheet`'s flags, the CuttingSheet feature's
properties, make_cutting_sheet's keywords and export.layout all come from it.

Defaults are the core's own (popupcore.SheetOptions()), so no default is written twice. Kinds:
"length" (mm), "angle" (degrees), "bool", "sides" (piece id → "front" or "back", written
"P1=back" on the command line and in the property).
"""

import collections

SheetOption = collections.namedtuple("SheetOption", "name prop kind doc")

SHEET_OPTIONS = (
    SheetOption("margin", "Margin", "length", "Blank border kept on every side of the paper"),
    SheetOption("spacing", "Spacing", "length", "Gap between pieces, at least Kerf + MinGap"),
    SheetOption("kerf", "Kerf", "length", "Width the cutter removes; cut lines move out by half"),
    SheetOption("min_gap", "MinGap", "length", "Least paper left between two pieces' cuts"),
    SheetOption("tab_width", "TabWidth", "length", "Depth of a glue tab, away from its crease"),
    SheetOption("tab_angle", "TabAngle", "angle", "Angle between a tab's crease and its sides"),
    SheetOption("min_tab_width", "MinTabWidth", "length", "Narrowest glue tab worth gluing"),
    SheetOption(
        "min_feature", "MinFeature", "length", "Narrower paper is reported as fragile (die cut)"
    ),
    SheetOption(
        "min_corner_angle",
        "MinCornerAngle",
        "angle",
        "Sharper convex corners are reported (die cut)",
    ),
    SheetOption("fold_hints", "FoldHints", "bool", "Print M or V beside each fold"),
    SheetOption(
        "printed_sides",
        "PrintedSides",
        "sides",
        "Pieces whose artwork is printed on their back, as P1=back (front otherwise)",
    ),
)

# Options whose default a maker can set in the preferences (popupwb/preferences.py).
PREFERRED = ("Kerf", "TabWidth", "TabAngle")

_BY_KEY = {key: option for option in SHEET_OPTIONS for key in (option.name, option.prop)}


def defaults():
    """{option name: the core's default}, plus "paper"."""
    from popupwb.core import popupcore

    core = popupcore.SheetOptions()
    values = {option.name: getattr(core, option.name) for option in SHEET_OPTIONS}
    values["paper"] = core.paper
    return values


def option_named(key):
    """The option called `key` (core name or property name); ValueError naming the known ones."""
    try:
        return _BY_KEY[key]
    except KeyError:
        known = ", ".join(option.name for option in SHEET_OPTIONS)
        raise ValueError(f"unknown sheet option {key!r}; known: paper, {known}") from None


def core_options(paper=None, **values):
    """A popupcore.SheetOptions from option values (core or property names); ValueError for an
    unknown option, popupcore.DesignError (a ValueError) for an unknown paper."""
    from popupwb.core import popupcore

    options = popupcore.SheetOptions()
    if paper is not None:
        options.paper = paper
    for key, value in values.items():
        option = option_named(key)
        setattr(options, option.name, _converted(option, value))
    return options


def _converted(option, value):
    if option.kind == "bool":
        return bool(value)
    if option.kind == "sides":
        return parse_sides(value)
    return float(value)


def parse_sides(value):
    """{piece: side} from a dict or from strings "P1=back"; ValueError naming a bad entry."""
    if isinstance(value, dict):
        return dict(value)
    sides = {}
    for entry in value:
        piece, equals, side = str(entry).partition("=")
        if not equals or not piece.strip():
            raise ValueError(f"printed side {entry!r}: write PIECE=SIDE, e.g. P1=back")
        sides[piece.strip()] = side.strip()
    return sides


def sides_text(sides):
    """["P1=back", ...] for a property or a report."""
    return [f"{piece}={side}" for piece, side in sorted(sides.items())]


def cli_flag(option):
    """--tab-width; --printed-side (given once per piece)."""
    name = "printed_side" if option.kind == "sides" else option.name
    return "--" + name.replace("_", "-")


def add_cli_arguments(parser):
    """One flag per option (--tab-width MM ...); an option left out keeps the core's default,
    which the help shows when popupcore imports."""
    units = {"length": "MM", "angle": "DEG"}
    try:
        shown = defaults()
    except ImportError:  # the CLI reports a missing module when it runs, not in --help
        shown = {}
    for option in SHEET_OPTIONS:
        if option.kind == "bool":
            parser.add_argument(cli_flag(option), action="store_true", help=option.doc)
            continue
        if option.kind == "sides":
            parser.add_argument(
                cli_flag(option),
                dest=option.name,
                action="append",
                metavar="PIECE=SIDE",
                help=option.doc + "; repeat for several pieces",
            )
            continue
        default = f"; default {shown[option.name]:g}" if option.name in shown else ""
        if option.prop in PREFERRED:
            default += " or the PopUp preference"
        parser.add_argument(
            cli_flag(option), type=float, metavar=units[option.kind], help=option.doc + default
        )


def from_cli(args):
    """{option name: value} of the options given on the command line (and every bool)."""
    values = {option.name: getattr(args, option.name) for option in SHEET_OPTIONS}
    return {name: value for name, value in values.items() if value is not None}
