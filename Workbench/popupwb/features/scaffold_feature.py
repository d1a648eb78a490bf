"""Scaffold: a pop-up design file shown at a fold angle, as an exact compound of planar faces.

The feature only translates: it reads its properties, asks popupcore for the pose of every patch
at FoldAngle and for the B-rep of the posed patches, and hands the BREP text to Part. The module
path, the class name and the property names are stored in .FCStd files: never rename them.
"""

import collections
import hashlib
import math
import time

import FreeCAD
import Part

from popupwb.core import popupcore
from popupwb.features.one_line_errors import one_line_errors
from popupwb.features.property_adder import add_validity_outputs, property_adder
from popupwb.features.signed_lengths import SIGNED, make_signed
from popupwb.stateless_proxy import StatelessProxy
from popupwb.view_provider_by_name import attach_view_provider

TYPE = "PopUp::Scaffold"
VERSION = "1"

# Parsed designs by the SHA-256 of their text. Module-level, never in proxy state: the proxy must
# stay JSON-serialisable and a reopened document simply parses again. Keyed by content rather than
# path so that an edited file is re-read and identical designs share one parse.
_DESIGN_CACHE = collections.OrderedDict()
_DESIGN_CACHE_SIZE = 16


def load_design(path):
    """The popupcore.Scaffold of the design file at `path`, parsed once per distinct content.

    Raises OSError when the file cannot be read and popupcore.DesignError (a ValueError) when it is
    not a valid design (RuntimeError for a parser failure it missed; scaffold_of() folds both).
    """
    with open(path, "rb") as stream:
        data = stream.read()
    key = hashlib.sha256(data).hexdigest()
    scaffold = _DESIGN_CACHE.get(key)
    if scaffold is None:
        try:
            text = data.decode("utf-8")
        except UnicodeDecodeError as error:
            raise popupcore.DesignError(f"file: not UTF-8 text ({error})") from error
        scaffold = popupcore.scaffold_from_json(text)
        _DESIGN_CACHE[key] = scaffold
        while len(_DESIGN_CACHE) > _DESIGN_CACHE_SIZE:
            _DESIGN_CACHE.popitem(last=False)
    else:
        _DESIGN_CACHE.move_to_end(key)
    return scaffold


def scaffold_of(obj):
    """The parsed design of a Scaffold object; errors name the object and its DesignFile."""
    path = obj.DesignFile
    if not path:
        raise ValueError(f"{obj.Label}: DesignFile is empty, choose a pop-up design (*.json)")
    try:
        return load_design(path)
    except OSError as error:
        raise ValueError(
            f"{obj.Label}: DesignFile '{path}' cannot be read: {error.strerror or error}"
        ) from error
    except (ValueError, RuntimeError) as error:  # DesignError, or a parser failure it missed
        raise ValueError(
            f"{obj.Label}: DesignFile '{path}' is not a valid design: {error}"
        ) from error


def is_scaffold(obj):
    """True for document objects driven by ScaffoldFeature."""
    return getattr(getattr(obj, "Proxy", None), "TYPE", None) == TYPE


class ScaffoldFeature(StatelessProxy):
    """Proxy of a Part::FeaturePython showing a design file at a fold angle."""

    TYPE = TYPE
    # popupwb.viewproviders module and class, imported only in the GUI (view_provider_by_name)
    VIEW_PROVIDER = ("scaffold_viewprovider", "ScaffoldViewProvider")

    def __init__(self, obj):
        obj.Proxy = self
        self.add_properties(obj)

    def add_properties(self, obj):
        """Adds every property that is missing, so files written by older versions upgrade."""

        add = property_adder(obj, "PopUp")

        # PropertyFileIncluded rather than PropertyFile: the design is copied into the .FCStd, so a
        # saved document is self-contained and recomputes anywhere (checked by the save/reopen
        # test). The price: editing the original file later needs DesignFile to be set again.
        add(
            "App::PropertyFileIncluded",
            "DesignFile",
            "Pop-up design file (JSON, docs/DESIGN_FORMAT.md), stored inside the document",
        )
        add("App::PropertyAngle", "FoldAngle", "Opening angle of the card, 0° to 180°", 180.0)
        make_signed(obj, ("PaperThickness",))
        add(
            SIGNED,
            "PaperThickness",
            "Paper thickness, used when Thickened (the design file's value by default)",
            0.2,
        )
        add("App::PropertyBool", "Thickened", "Show the patches as solids of PaperThickness", False)
        add_validity_outputs(
            add, "True when the last validity check passed; reset when DesignFile changes"
        )
        add("App::PropertyString", "Version", "Version of this object's properties", VERSION, 1)

    def onChanged(self, obj, prop):
        # A new design invalidates the verdict of the old one. Not while a file is restored: the
        # stored verdict belongs to the stored design (and FileIncluded is set after the others).
        restoring = "Restore" in obj.State or obj.Document.Restoring
        if prop == "DesignFile" and not restoring and hasattr(obj, "Valid"):
            obj.Valid = False
            obj.Diagnostics = []

    def onDocumentRestored(self, obj):
        self.add_properties(obj)
        attach_view_provider(obj)  # saved headless: it has none yet

    @one_line_errors
    def execute(self, obj):
        start = time.perf_counter()
        angle = obj.FoldAngle.Value
        if not 0.0 <= angle <= 180.0:
            raise ValueError(f"{obj.Label}: FoldAngle = {angle:g}°, must be within 0° and 180°")
        paper = obj.PaperThickness.Value
        if not 0.0 <= paper <= 5.0:  # the core's range for paper (popup::make_card)
            raise ValueError(f"{obj.Label}: PaperThickness = {paper:g} mm, must be 0 to 5 mm")
        thickness = paper if obj.Thickened else 0.0
        if obj.Thickened and thickness <= 0.0:
            raise ValueError(
                f"{obj.Label}: PaperThickness = {thickness:g} mm, must be > 0 when Thickened"
            )
        scaffold = scaffold_of(obj)

        sweep = popupcore.simulate_fold(scaffold, [math.radians(angle)])
        if not sweep.complete or not sweep.states:
            findings = "; ".join(d.message for d in sweep.diagnostics)
            if sweep.locked_at >= 0.0:
                reason = f"the design locks at {math.degrees(sweep.locked_at):.2f}°"
            else:
                reason = "the simulation did not reach it"
            raise ValueError(
                f"{obj.Label}: FoldAngle = {angle:g}° cannot be reached, {reason}"
                + (f" ({findings})" if findings else "")
            )
        for d in sweep.diagnostics:
            FreeCAD.Console.PrintLog(f"{obj.Label}: {d.code}: {d.message}\n")

        try:
            brep = popupcore.patches_to_brep(scaffold, sweep.states[0], thickness)
        except RuntimeError as error:
            raise RuntimeError(
                f"{obj.Label}: building the patches at FoldAngle = {angle:g}° failed: {error}"
            ) from error
        shape = Part.Shape()
        shape.importBrepFromString(brep, False)  # returns None, fills `shape`
        # Assigning Shape resets Placement to the shape's own: keep the user's placement.
        placement = obj.Placement
        obj.Shape = shape
        obj.Placement = placement
        FreeCAD.Console.PrintLog(
            f"{obj.Label}: {len(scaffold.patches)} patches at {angle:g}° in "
            f"{1000.0 * (time.perf_counter() - start):.1f} ms\n"
        )
