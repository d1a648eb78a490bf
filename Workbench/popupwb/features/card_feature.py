"""PopUpCard: a folded card of a paper size, carrying the mechanism features nested on it.

Its shape is its two pages at FoldAngle; each mechanism shows its own patches (so selecting or
hiding one acts on its faces), and card_scaffold.assembled_shape() gives the whole card.
The module path, the class name and the property names are stored in .FCStd files: never rename
them.
"""

import time

import FreeCAD

from popupwb.features.no_stale_shape import clears_shape_on_error
from popupwb.features.one_line_errors import one_line_errors
from popupwb.features.property_adder import add_validity_outputs, property_adder
from popupwb.features.signed_lengths import SIGNED, make_signed
from popupwb.model import card_scaffold, validity_state
from popupwb.stateless_proxy import StatelessProxy
from popupwb.view_provider_by_name import attach_view_provider

TYPE = card_scaffold.CARD_TYPE
VERSION = "1"

# Width (along the fold) and Depth (each page) of the sheet folded in half across its long side:
# the fold runs parallel to the short side, so Width is the short side and Depth half the long one.
PRESETS = {
    "A4": (210.0, 148.5),  # 297 x 210
    "A5": (148.0, 105.0),  # 210 x 148
    "A6": (105.0, 74.0),  # 148 x 105
    "Letter": (215.9, 139.7),  # 11 x 8.5 in
    "HalfLetter": (139.7, 107.95),  # 8.5 x 5.5 in
}
CUSTOM = "Custom"
PRESET_NAMES = list(PRESETS) + [CUSTOM]


def is_card(obj):
    """True for document objects driven by PopUpCard."""
    return card_scaffold.is_card(obj)


def _restoring(obj):
    return "Restore" in obj.State or obj.Document.Restoring


# Cards whose Width and Depth this module is setting from their Preset.
_APPLYING_PRESET = set()


class PopUpCard(StatelessProxy):
    """Proxy of a Part::FeaturePython: the card and, through its scaffold, all its mechanisms."""

    TYPE = TYPE
    # popupwb.viewproviders module and class, imported only in the GUI (view_provider_by_name)
    VIEW_PROVIDER = ("card_viewprovider", "CardViewProvider")

    def __init__(self, obj):
        obj.Proxy = self
        self.add_properties(obj)

    def add_properties(self, obj):
        """Adds every property that is missing, so files written by older versions upgrade."""
        have = set(obj.PropertiesList)

        add = property_adder(obj, "Card")

        if "Preset" not in have:
            obj.addProperty(
                "App::PropertyEnumeration",
                "Preset",
                "Card",
                "Paper size folded in half across its long side; sets Width and Depth",
            )
            obj.Preset = PRESET_NAMES
            obj.Preset = "A5"
        make_signed(obj, ("Width", "Depth", "PaperThickness"))
        add(SIGNED, "Width", "Length of the central fold", PRESETS["A5"][0])
        add(SIGNED, "Depth", "Depth of each page, from the fold", PRESETS["A5"][1])
        add("App::PropertyAngle", "FoldAngle", "Opening angle of the card, 0° to 180°", 180.0)
        add(SIGNED, "PaperThickness", "Paper thickness", 0.2)
        add("App::PropertyBool", "Thickened", "Show the patches as solids of PaperThickness", False)
        add_validity_outputs(
            add, "True when the last validity check passed; reset when the design changes"
        )
        if "Validity" not in have:
            add(
                "App::PropertyEnumeration",
                "Validity",
                "Verdict of the last validity check: NotChecked, Valid or Invalid (back to "
                "NotChecked when the design changes)",
                mode=1,
                output=True,
            )
            obj.Validity = validity_state.VALIDITY_STATES
            obj.Validity = validity_state.verdict_of_old_file(obj)
        add(
            "App::PropertyString",
            "CheckedDesign",
            "Digest of the design the last validity check saw (resets Valid when it changes)",
            "",
            mode=2,
            output=True,
        )
        add("App::PropertyString", "Version", "Version of this object's properties", VERSION, 1)

    def onChanged(self, obj, prop):
        if _restoring(obj) or not hasattr(obj, "Depth"):
            return
        key = (obj.Document.Name, obj.Name)
        if prop == "Preset" and obj.Preset in PRESETS:
            width, depth = PRESETS[obj.Preset]
            _APPLYING_PRESET.add(key)
            try:
                if abs(obj.Width.Value - width) > 1e-9:
                    obj.Width = width
                if abs(obj.Depth.Value - depth) > 1e-9:
                    obj.Depth = depth
            finally:
                _APPLYING_PRESET.discard(key)
        elif prop in ("Width", "Depth") and obj.Preset in PRESETS and key not in _APPLYING_PRESET:
            # A size of one's own is no longer the preset.
            width, depth = PRESETS[obj.Preset]
            if abs(obj.Width.Value - width) > 1e-9 or abs(obj.Depth.Value - depth) > 1e-9:
                obj.Preset = CUSTOM

    def onDocumentRestored(self, obj):
        self.add_properties(obj)
        attach_view_provider(obj)  # saved headless: it has none yet

    @one_line_errors
    @clears_shape_on_error
    def execute(self, obj):
        start = time.perf_counter()
        angle = obj.FoldAngle.Value
        if not 0.0 <= angle <= 180.0:
            raise ValueError(f"{obj.Label}: FoldAngle = {angle:g}°, must be within 0° and 180°")
        thickness = obj.PaperThickness.Value if obj.Thickened else 0.0
        if obj.Thickened and thickness <= 0.0:
            raise ValueError(
                f"{obj.Label}: PaperThickness = {thickness:g} mm, must be > 0 when Thickened"
            )
        built = card_scaffold.for_card(obj)
        if built.card_error:
            raise ValueError(built.card_error)
        if obj.CheckedDesign != built.digest and obj.Validity != validity_state.NOT_CHECKED:
            # The verdict belongs to another design.
            validity_state.record_verdict(obj, validity_state.NOT_CHECKED)
        try:
            # Its pages only: each mechanism shows its own patches.
            shape = built.own_shape(obj.Name, angle, thickness)
        except ValueError as error:
            raise ValueError(f"{obj.Label}: FoldAngle = {angle:g}° {error}") from error
        # Assigning Shape resets Placement to the shape's own: keep the user's placement.
        placement = obj.Placement
        obj.Shape = shape
        obj.Placement = placement
        for name, message in built.errors.items():
            FreeCAD.Console.PrintLog(f"{obj.Label}: left out {name}: {message}\n")
        FreeCAD.Console.PrintLog(
            f"{obj.Label}: {len(built.scaffold.patches)} patches at {angle:g}° in "
            f"{1000.0 * (time.perf_counter() - start):.1f} ms\n"
        )
