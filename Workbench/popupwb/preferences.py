"""PopUp's preferences: the defaults a maker sets once (Edit › Preferences › PopUp) and the commands
and `popup` use, each command-line option overriding its preference.

They live where FreeCAD keeps every preference, the parameter group PARAMETER_GROUP of the user's
user.cfg: FreeCAD.ConfigGet("UserParameter"), which is $FREECAD_USER_HOME/user.cfg when that is
set, else ~/.config/FreeCAD/user.cfg (FreeCAD 0.20 on Linux). `popup` reads the same file through
FreeCAD.ParamGet, headless. A preference that is not set means PopUp's built-in default: the
core's for the layout options and the paper thickness, layer_style.SheetStyle's for the layers,
DEFAULTS below for the rest; so no default is written twice, and a newer default reaches a user
who never changed it. The page (gui/preferences_page.py) removes a value set back to its default.

read() needs FreeCAD only to find the file; without FreeCAD it gives the built-in defaults.
"""

import collections
import dataclasses
import math
from typing import Optional

PARAMETER_GROUP = "User parameter:BaseApp/Preferences/Mod/PopUp"

# kind: "text" (SetString), "length" / "angle" (SetFloat, mm / degrees), "colour" (SetUnsigned,
# 0xRRGGBBAA as FreeCAD's colour buttons store it).
Preference = collections.namedtuple("Preference", "key kind doc")

# The built-in defaults that have no other home.
DEFAULTS = {
    "CardPreset": "A5",  # as make_card's
    "SheetPaper": "",  # the smallest paper preset holding every piece (popup sheet without --paper)
    "ExportFolder": "",  # Export cutting sheets asks, from the current folder; popup needs --out
}

LAYERS = ("cut", "mountain", "valley", "glue", "label")  # SheetStyle's fields, in its order

PREFERENCES = (
    Preference("CardPreset", "text", "Size of a new card"),
    Preference("PaperThickness", "length", "Paper thickness of a new card"),
    Preference(
        "SheetPaper",
        "text",
        "Paper the cutting sheets are laid on: A4, A3, Letter, Tabloid or WxH in mm; empty: "
        "the smallest preset that holds every piece",
    ),
    Preference("Kerf", "length", "Width the cutter removes; cut lines move out by half"),
    Preference("TabWidth", "length", "Depth of a glue tab, away from its crease"),
    Preference("TabAngle", "angle", "Angle between a tab's crease and its sides"),
    *(
        Preference(f"{layer.capitalize()}Layer{what}", kind, f"{doc} of the {layer} lines")
        for layer in LAYERS
        for what, kind, doc in (("Name", "text", "Layer name"), ("Colour", "colour", "Colour"))
    ),
    Preference("ExportFolder", "text", "Folder the cutting sheets are exported into"),
)
BY_KEY = {p.key: p for p in PREFERENCES}


class PreferenceError(ValueError):
    """A stored preference PopUp cannot use; the message names it, its value and the range."""


@dataclasses.dataclass(frozen=True)
class Preferences:
    card_preset: str
    paper_thickness: Optional[float]  # mm; None: the card's own default
    sheet_paper: Optional[str]  # None: the smallest preset that holds every piece
    sheet_options: dict  # {core option name: value} of the layout options set
    style: object  # layer_style.SheetStyle
    export_folder: str  # "" when not set
    source: str  # the user.cfg they came from ("" without FreeCAD)


def parameter_group():
    """FreeCAD's parameter group of PopUp (None when FreeCAD cannot be imported)."""
    try:
        import FreeCAD
    except ImportError:
        return None
    return FreeCAD.ParamGet(PARAMETER_GROUP)


def config_path():
    """The user.cfg FreeCAD reads ("" without FreeCAD)."""
    try:
        import FreeCAD
    except ImportError:
        return ""
    return FreeCAD.ConfigGet("UserParameter")


def stored(group):
    """{key: value} of the preferences set in `group` (a FreeCAD ParameterGrp); colours as
    (r, g, b)."""
    if group is None:
        return {}
    names = {
        "text": set(group.GetStrings()),
        "length": set(group.GetFloats()),
        "angle": set(group.GetFloats()),
        "colour": set(group.GetUnsigneds()),
    }
    values = {}
    for p in PREFERENCES:
        if p.key not in names[p.kind]:
            continue
        if p.kind == "text":
            values[p.key] = group.GetString(p.key)
        elif p.kind == "colour":
            values[p.key] = rgb_of(group.GetUnsigned(p.key))
        else:
            values[p.key] = group.GetFloat(p.key)
    return values


def write(group, values):
    """Stores `values` ({key: value}, colours as (r, g, b)) in `group`; a value of None removes
    the preference (back to the built-in default)."""
    for key, value in values.items():
        kind = BY_KEY[key].kind
        remove, store = {
            "text": (group.RemString, group.SetString),
            "length": (group.RemFloat, group.SetFloat),
            "angle": (group.RemFloat, group.SetFloat),
            "colour": (group.RemUnsigned, group.SetUnsigned),
        }[kind]
        if value is None:
            remove(key)
        else:
            store(key, packed(value) if kind == "colour" else value)


def rgb_of(unsigned):
    """(r, g, b) of FreeCAD's packed 0xRRGGBBAA colour."""
    return ((unsigned >> 24) & 0xFF, (unsigned >> 16) & 0xFF, (unsigned >> 8) & 0xFF)


def packed(rgb):
    """FreeCAD's packed 0xRRGGBBAA (opaque) of (r, g, b)."""
    r, g, b = rgb
    return (r << 24) | (g << 16) | (b << 8) | 0xFF


def built_in():
    """{key: the value PopUp uses when the preference is not set} (colours (r, g, b)); needs
    popupcore."""
    from popupwb.core import popupcore
    from popupwb.sheets import sheet_options
    from popupwb.sheets.layer_style import SheetStyle

    values = dict(DEFAULTS)
    values["PaperThickness"] = popupcore.CardParams().paper_thickness
    core = sheet_options.defaults()
    for key in sheet_options.PREFERRED:
        values[key] = core[sheet_options.option_named(key).name]
    style = SheetStyle()
    for layer in LAYERS:
        values[f"{layer.capitalize()}LayerName"] = getattr(style, layer).name
        values[f"{layer.capitalize()}LayerColour"] = getattr(style, layer).rgb
    return values


def read(group=None):
    """The Preferences of `group` (default: FreeCAD's PopUp group of the user's user.cfg; the
    built-in defaults without FreeCAD). Raises PreferenceError for a stored value out of range."""
    return from_values(stored(parameter_group() if group is None else group), config_path())


def read_or_built_in(command):
    """read() for a GUI command: a preference out of range is one line in the report view, and
    the command goes on with the built-in defaults."""
    try:
        return read()
    except PreferenceError as error:
        import FreeCAD

        FreeCAD.Console.PrintError(f"{command}: {error}; using PopUp's built-in defaults\n")
        return from_values({}, config_path())


def from_values(values, source=""):
    """The Preferences of {key: value} (colours (r, g, b)); `source` the file they came from, for
    the messages. Raises PreferenceError for a value out of range."""

    def fail(key, why):
        shown = values[key]
        unit = {"length": " mm", "angle": "°"}.get(BY_KEY[key].kind, "")
        shown = f"{shown:g}{unit}" if isinstance(shown, float) else repr(shown)
        raise PreferenceError(
            f"PopUp preference {key} = {shown}: {why} (Edit › Preferences › PopUp"
            + (f"; stored in {source})" if source else ")")
        )

    return Preferences(
        card_preset=_card_preset(values, fail),
        paper_thickness=_paper_thickness(values, fail),
        sheet_paper=_sheet_paper(values, fail),
        sheet_options=_sheet_options(values, fail),
        style=_style(values, fail),
        export_folder=values.get("ExportFolder", DEFAULTS["ExportFolder"]),
        source=source,
    )


def _card_preset(values, fail):
    from popupwb.features.card_feature import PRESETS

    preset = values.get("CardPreset", DEFAULTS["CardPreset"])
    if preset not in PRESETS:
        fail("CardPreset", f"must be one of {', '.join(PRESETS)}")
    return preset


def _paper_thickness(values, fail):
    thickness = values.get("PaperThickness")
    if thickness is not None and not (math.isfinite(thickness) and thickness >= 0.0):
        fail("PaperThickness", "must be a finite length >= 0 mm")
    return thickness


def _sheet_paper(values, fail):
    paper = values.get("SheetPaper", "").strip()
    if not paper:
        return None
    from popupwb.core import popupcore

    try:
        popupcore.paper_size(paper)
    except ValueError as error:
        fail("SheetPaper", str(error))
    return paper


def _sheet_options(values, fail):
    from popupwb.sheets import sheet_options
    from popupwb.sheets.sheet_options import PREFERRED

    options = {}
    for key in PREFERRED:
        if key in values:
            options[sheet_options.option_named(key).name] = values[key]
    for finding in sheet_options.core_options(**options).check() if options else []:
        # A finding on an option not set here (spacing: at least kerf + min gap) is the doing of
        # the preferences that are set.
        keys = {sheet_options.option_named(k).name: k for k in PREFERRED if k in values}
        fail(keys.get(finding["parameter"], next(iter(keys.values()))), finding["message"])
    return options


def _style(values, fail):
    from popupwb.sheets.layer_style import SheetStyle, nearest_aci

    style = SheetStyle()
    layers = {}
    for layer in LAYERS:
        base = getattr(style, layer)
        name_key = f"{layer.capitalize()}LayerName"
        colour_key = f"{layer.capitalize()}LayerColour"
        name = values.get(name_key, base.name)
        if not name.strip():
            fail(name_key, "must not be empty")
        # ezdxf (a third of a second to import) only for a name the maker chose.
        if name != base.name and not _valid_layer_name(name):
            fail(name_key, "a DXF layer name cannot hold any of < > / \\ \" : ; ? * | = '")
        rgb = tuple(values.get(colour_key, base.rgb))
        aci = base.aci if rgb == tuple(base.rgb) else nearest_aci(rgb)
        layers[layer] = dataclasses.replace(base, name=name, aci=aci, rgb=rgb)
    seen = {}
    for layer in LAYERS:
        name = layers[layer].name.upper()  # DXF layer names are case-insensitive
        if name in seen:
            key = f"{layer.capitalize()}LayerName"
            if key not in values:  # the other one was renamed onto this default name
                key = f"{seen[name].capitalize()}LayerName"
            fail(key, f"the {seen[name]} layer has this name too; layer names must differ")
        seen[name] = layer
    return dataclasses.replace(style, **layers)


def _valid_layer_name(name):
    from ezdxf.lldxf.validator import is_valid_layer_name

    return is_valid_layer_name(name)
