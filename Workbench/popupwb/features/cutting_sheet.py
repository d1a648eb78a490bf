"""CuttingSheet: a PopUpCard laid out flat on sheets of paper, to cut, crease and glue.

Recompute lays out the card's current design with the core (sheets.export.layout, a
popupcore.SheetSet) and keeps the sheet set in SheetSetJson (its JSON, docs/SHEET_FORMAT.md), so
export writes what is shown without laying out again (popupcore.sheet_set_from_json reads it
back). Shape: one sub-compound per sheet, side by side like sheets.dxf (sheet k
at x = k * (paper width + 20 mm)), holding each patch as an exact planar face at z = 0, then the
fold lines and the tab outlines as wires. With MakePages, one TechDraw page per sheet
(sheets.techdraw_pages).

A card the validity check rejects (popupcore.check_validity with `popup check`'s defaults) is not
laid out: the feature goes into error with the reason, unless Force is set; then the pages and
the exported files carry "NOT VALID: <reason>" (sheets.not_valid_stamp).

A card designed from a model (its SourceModel, PopUp_FromModel and `popup fit`) prints that
model's appearance on the patches when PrintArtwork is set (the default): export renders it
(print_artwork.render_sheet_artwork, as `popup sheet` does) onto the print layer of the PDF and
SVG, with the registration marks; the DXF stays a cut file. A card made by hand has nothing to
print.

A changed FoldAngle recomputes the card, and so this feature: it lays out again only when the
design, an option or the page settings changed (InputDigest). The module path, class name and
property names are stored in .FCStd files: never rename them.
"""

import hashlib

import FreeCAD

from popupwb import freecad_version
from popupwb import progress
from popupwb.model import card_scaffold
from popupwb.features.one_line_errors import one_line_errors
from popupwb.features.property_adder import property_adder
from popupwb.validity.check import add_build_problems
from popupwb.sheets.sheet_options import SHEET_OPTIONS, defaults, sides_text
from popupwb.stateless_proxy import StatelessProxy
from popupwb.view_provider_by_name import attach_view_provider

TYPE = "PopUp::CuttingSheet"
VERSION = "1"
CUSTOM = "Custom"
PAPERS = ["A4", "A3", "Letter", "Tabloid", CUSTOM]

# A layout option (sheets/sheet_options.py) as a property: kind "length" (App::PropertyDistance,
# signed so that the core, not FreeCAD's clamping, judges a negative value), "angle" or "bool".
OPTIONS = SHEET_OPTIONS
_PROPERTY_TYPES = {
    "length": "App::PropertyDistance",
    "angle": "App::PropertyAngle",
    "bool": "App::PropertyBool",
    "sides": "App::PropertyStringList",
}
LINE_STYLE_NAMES = "1 continuous, 2 dash, 3 dot, 4 dash-dot, 5 dash-dot-dot"


def is_cutting_sheet(obj):
    """True for document objects driven by CuttingSheet."""
    return getattr(getattr(obj, "Proxy", None), "TYPE", None) == TYPE


class CuttingSheet(StatelessProxy):
    """Proxy of a Part::FeaturePython: the flat layout of its Card."""

    TYPE = TYPE
    # popupwb.viewproviders module and class, imported only in the GUI (view_provider_by_name)
    VIEW_PROVIDER = ("cutting_sheet_viewprovider", "CuttingSheetViewProvider")

    def __init__(self, obj):
        obj.Proxy = self
        self.add_properties(obj)

    def add_properties(self, obj):
        """Adds every property that is missing, so files written by older versions upgrade."""
        default = defaults()
        have = set(obj.PropertiesList)
        add = property_adder(obj, "Sheets")
        add("App::PropertyLink", "Card", "The PopUpCard laid out on the sheets")
        if "Paper" not in have:
            obj.addProperty(
                "App::PropertyEnumeration",
                "Paper",
                "Sheets",
                "Paper size (portrait); Custom uses PaperWidth and PaperHeight",
            )
            obj.Paper = PAPERS
            obj.Paper = default["paper"]
        add("App::PropertyDistance", "PaperWidth", "Paper width when Paper is Custom", 210.0)
        add("App::PropertyDistance", "PaperHeight", "Paper height when Paper is Custom", 297.0)
        for option in OPTIONS:
            value = default[option.name]
            if option.kind == "sides":
                value = sides_text(value)
            add(_PROPERTY_TYPES[option.kind], option.prop, option.doc, value)
        add(
            "App::PropertyInteger",
            "MountainStyle",
            f"TechDraw line style of mountain folds on the pages ({LINE_STYLE_NAMES})",
            4,
        )
        add(
            "App::PropertyInteger",
            "ValleyStyle",
            f"TechDraw line style of valley folds on the pages ({LINE_STYLE_NAMES})",
            2,
        )
        add("App::PropertyBool", "MakePages", "Draw one TechDraw page per sheet", True)
        add(
            "App::PropertyBool",
            "PrintArtwork",
            "Print the source model's appearance on the patches of the exported PDF and SVG, with "
            "registration marks (cards designed from a model; a hand-made card has none)",
            True,
        )
        add(
            "App::PropertyBool",
            "Force",
            "Lay out a card the validity check rejects; every page and file then says NOT VALID",
            False,
        )

        report = property_adder(obj, "Report")
        for name, doc in (
            ("SheetCount", "Sheets of paper used"),
            ("ShelfSheetCount", "Sheets a simple shelf packer would use, for comparison"),
            ("PieceCount", "Pieces to cut"),
            ("TabCount", "Glue tabs"),
        ):
            report("App::PropertyInteger", name, doc, 0, mode=1, output=True)
        for name, doc in (
            ("CutLength", "Total length of the cut lines"),
            ("StackHeight", "Thickness of the folded card's thickest stack of paper"),
            ("RoundTripError", "Largest distance between the re-folded flat pieces and the design"),
        ):
            report("App::PropertyLength", name, doc, 0.0, mode=1, output=True)
        report(
            "App::PropertyBool",
            "RoundTripOk",
            "True when the flat pieces fold back into the design within 1e-6 x the card's size",
            False,
            mode=1,
            output=True,
        )
        report(
            "App::PropertyStringList",
            "Diagnostics",
            "Findings of the last layout (severity: code: message)",
            mode=1,
            output=True,
        )
        report(
            "App::PropertyString",
            "NotValid",
            "The NOT VALID stamp of the pages when Force laid out a rejected card; empty otherwise",
            "",
            mode=1,
            output=True,
        )
        report(
            "App::PropertyStringList",
            "ValidityFindings",
            "The validity check's findings when Force laid out a rejected card",
            mode=1,
            output=True,
        )
        report(
            "App::PropertyString",
            "SheetSetJson",
            "The last layout (docs/SHEET_FORMAT.md), what export writes",
            "",
            mode=2,
            output=True,
        )
        report(
            "App::PropertyString",
            "InputDigest",
            "Digest of the design and settings the outputs were made from",
            "",
            mode=2,
            output=True,
        )
        add("App::PropertyString", "Version", "Version of this object's properties", VERSION, 1)

    # --- FreeCAD callbacks ------------------------------------------------------------------

    def onDocumentRestored(self, obj):
        self.add_properties(obj)
        attach_view_provider(obj)  # saved headless: it has none yet

    @one_line_errors
    def execute(self, obj):
        from popupwb.sheets import export

        built = card_scaffold.for_card(self._card(obj))
        options = layout_options(obj)
        self._check_styles(obj)
        digest = input_digest(obj, built)
        if digest == obj.InputDigest and self._pages_complete(obj):
            return  # a new FoldAngle: same design, same sheets
        not_valid = self._not_valid(obj, built)
        try:
            sheet_set = progress.run(
                f"{obj.Label}: laying out the sheets",
                export.layout,
                built.scaffold,
                cancel=progress.CANCEL_FLAG,
                **options,
            )
        except ValueError as error:  # DesignError names the option and its range
            raise self._error(obj, property_message(error, obj)) from error
        errors = [d for d in sheet_set.diagnostics if d.severity == "error"]
        if errors:
            raise self._error(obj, "; ".join(d.message for d in errors))
        self._show(obj, sheet_set, not_valid)
        obj.InputDigest = digest

    # --- steps of execute -------------------------------------------------------------------

    def _card(self, obj):
        """The linked card, built; raises naming what is wrong with it."""
        card = obj.Card
        if card is None or not card_scaffold.is_card(card):
            found = "empty" if card is None else card.Label
            raise self._error(obj, f"Card = {found}, must be a PopUpCard")
        built = card_scaffold.for_card(card)
        if built.card_error:
            raise self._error(
                obj, f"the card {card.Label} is in error, fix it first: {built.card_error}"
            )
        if built.errors:
            # Sheets without a mechanism the user designed would be wrong: none rather than those.
            name, message = next(iter(built.errors.items()))
            label = obj.Document.getObject(name).Label
            raise self._error(obj, f"{label} of {card.Label} is in error, fix it first: {message}")
        return card

    def _not_valid(self, obj, built):
        """The card's NotValid (None when the validity check accepts it); raises, leaving the
        feature in error, for a rejected card unless Force is set."""
        from popupwb.core import popupcore
        from popupwb.validity.card_titles import add_scaffold_titles, titles_of_card
        from popupwb.sheets.not_valid_stamp import not_valid_of

        try:
            report = progress.run(
                f"{obj.Label}: checking validity",
                popupcore.check_validity,
                built.scaffold,
                cancel=progress.CANCEL_FLAG,
            ).to_dict()
        except ValueError as error:
            raise self._error(obj, f"the validity check cannot run: {error}") from error
        # A mechanism that does not build (a damaged file's Host loop, say) is left out of the
        # scaffold: the card is not valid, however well the rest folds.
        add_build_problems(report, obj.Card, built)
        titles = titles_of_card(obj.Card, built)
        not_valid = not_valid_of(add_scaffold_titles(report, titles, built.scaffold))
        if not_valid is not None and not obj.Force:
            # The first finding, unless it is already the reason (all verdicts passed).
            first = not_valid.findings[0] if not_valid.findings else not_valid.reason
            first = "" if first == not_valid.reason else f": {first}"
            raise self._error(
                obj,
                f"the card {obj.Card.Label} is {not_valid.text()}{first}; fix it, or set Force "
                "to lay it out anyway with every page stamped NOT VALID",
            )
        return not_valid

    def _check_styles(self, obj):
        from popupwb.sheets.techdraw_pages import LINE_STYLES

        for name in ("MountainStyle", "ValleyStyle"):
            value = getattr(obj, name)
            if obj.MakePages and value not in LINE_STYLES:
                raise self._error(obj, f"{name} = {value}, must be 1 to 5 ({LINE_STYLE_NAMES})")

    def _pages_complete(self, obj):
        from popupwb.sheets.techdraw_pages import pages_of

        pages = len(pages_of(obj))
        return pages == (obj.SheetCount if obj.MakePages else 0)

    def _error(self, obj, message):
        """Records `message` and returns it as the ValueError execute raises: FreeCAD puts the
        feature in error and keeps the last good shape; export refuses an empty SheetSetJson."""
        message = f"{obj.Label}: {message}"
        obj.Diagnostics = [f"error: {message}"]
        obj.NotValid = ""
        obj.ValidityFindings = []
        obj.SheetSetJson = ""
        obj.InputDigest = ""
        obj.RoundTripOk = False
        return ValueError(message)

    def _show(self, obj, sheet_set, not_valid=None):
        import Part

        from popupwb.sheets import techdraw_pages
        from popupwb.sheets.dxf_writer import SHEET_GAP
        from popupwb.sheets.sheet_shapes import flat_sheet

        pitch = sheet_set.options.paper_width + SHEET_GAP
        sheets = []
        for index in range(sheet_set.sheet_count):
            sheet = flat_sheet(sheet_set, index)
            sheet.translate(FreeCAD.Vector(index * pitch, 0.0, 0.0))
            sheets.append(sheet)
        placement = obj.Placement  # assigning Shape resets it to the shape's own
        obj.Shape = freecad_version.compound(sheets)
        obj.Placement = placement

        pieces = sheet_set.pieces
        obj.SheetCount = sheet_set.sheet_count
        obj.ShelfSheetCount = sheet_set.shelf_sheet_count
        obj.PieceCount = len(pieces)
        obj.TabCount = sum(len(piece.tabs) for piece in pieces)
        obj.CutLength = sheet_set.cut_length
        obj.StackHeight = sheet_set.stack_height
        obj.RoundTripError = sheet_set.round_trip.max_error
        obj.RoundTripOk = bool(sheet_set.round_trip.ok)
        diagnostics = [diagnostic_line(d.to_dict()) for d in sheet_set.diagnostics]
        if not_valid is not None:
            diagnostics.insert(0, f"warning: {not_valid.text()} (laid out because Force is set)")
        obj.Diagnostics = diagnostics
        obj.NotValid = "" if not_valid is None else not_valid.text()
        obj.ValidityFindings = [] if not_valid is None else list(not_valid.findings)
        obj.SheetSetJson = sheet_set.to_json()
        if obj.MakePages:
            techdraw_pages.update_pages(
                obj, sheet_set, obj.MountainStyle, obj.ValleyStyle, not_valid=not_valid
            )
        else:
            techdraw_pages.remove_pages(obj)


def input_digest(obj, built):
    """Digest of what the layout of `obj` is made from: the card's design (`built`, its
    CardScaffold), the layout options and the page settings."""
    settings = (obj.MakePages, obj.MountainStyle, obj.ValleyStyle, obj.Force)
    text = repr((built.key, layout_options(obj), settings))
    return hashlib.sha1(text.encode()).hexdigest()[:16]


def layout_options(obj):
    """The core's layout options from the properties (mm, degrees)."""
    if obj.Paper == CUSTOM:
        paper = f"{obj.PaperWidth.Value}x{obj.PaperHeight.Value}"
    else:
        paper = obj.Paper
    options = {"paper": paper}
    for option in OPTIONS:
        value = getattr(obj, option.prop)
        if option.kind == "bool":
            options[option.name] = bool(value)
        elif option.kind == "sides":
            options[option.name] = list(value)
        else:
            options[option.name] = float(value.Value)
    return options


def property_message(error, obj):
    """A DesignError's findings, each led by the property of the option at fault:
    "TabAngle: tab_angle = 0, must be ..."."""
    names = {option.name: option.prop for option in OPTIONS}
    names["paper"] = "PaperWidth/PaperHeight" if obj.Paper == CUSTOM else "Paper"
    findings = getattr(error, "diagnostics", None)
    if not findings:
        return str(error)
    return "; ".join(
        f"{names.get(d['parameter'], d['parameter'])}: {d['message']}"
        if d["parameter"]
        else d["message"]
        for d in findings
    )


def diagnostic_line(diagnostic):
    """A sheet set diagnostic as one line: "warning: code: message"."""
    from popupwb.validity.report_text import format_diagnostic

    return f"{diagnostic['severity']}: {format_diagnostic(diagnostic)}"


def has_layout(obj):
    """True when the CuttingSheet `obj` holds a layout export can write (not in error)."""
    return "Invalid" not in obj.State and bool(obj.SheetSetJson)


def export_cutting_sheet(obj, folder, style=None):
    """Writes the production files of the CuttingSheet `obj` into `folder` (created if needed) from
    the layout it keeps, in the layer_style.SheetStyle `style`; returns {kind: path(s)} as
    export.export_sheets. With PrintArtwork, a card designed from a model gets its artwork and
    registration marks on the PDF and SVG (sheet_artwork). Raises ValueError when `obj` has no
    layout (in error, or never recomputed) or the artwork cannot be made;
    progress.Cancelled when the maker cancels the rendering."""
    from popupwb.sheets import export

    if not has_layout(obj):
        reason = obj.getStatusString() if "Invalid" in obj.State else "never recomputed"
        raise ValueError(f"{obj.Label}: no layout to export ({reason}); fix it and recompute")
    sheet_set = stored_sheet_set(obj)
    artwork = sheet_artwork(obj, sheet_set) if getattr(obj, "PrintArtwork", False) else None
    if artwork:
        from popupwb.sheets.print_artwork import artwork_warnings

        for d in artwork_warnings(artwork):  # an unreadable texture: the model prints shaded
            FreeCAD.Console.PrintWarning(f"{obj.Label}: {d['message']}\n")
    try:
        return export.export_sheets(
            sheet_set, folder, style=style, not_valid=not_valid_of(obj), artwork=artwork
        )
    except ValueError as error:  # no room for the registration marks: names the margin
        if artwork:
            raise ValueError(f"{obj.Label}: Margin: {error}; or turn PrintArtwork off") from None
        raise


def stored_sheet_set(obj):
    """The layout `obj` keeps (SheetSetJson) as a popupcore.SheetSet; ValueError naming `obj`
    when the stored text is damaged."""
    from popupwb.core import popupcore

    try:
        return popupcore.sheet_set_from_json(obj.SheetSetJson)
    except ValueError as error:  # DesignError: names the key path
        raise ValueError(
            f"{obj.Label}: SheetSetJson: {error}; recompute to lay it out again"
        ) from None


def sheet_artwork(obj, sheet_set):
    """{patch id: popupcore.PatchArtwork} of the laid-out patches, rendered from the model the
    card was designed from (model_source.card_model: the model file while it is there,
    read through popupcore.load_model, else the mesh the card keeps); None for a card without a
    source model. ValueError naming obj when the layout is out of date or the model cannot be
    rendered."""
    from popupwb.model.model_source import card_limbs, card_model
    from popupwb.sheets.print_artwork import source_model_artwork

    card = obj.Card
    built = card_scaffold.for_card(card)
    if obj.InputDigest != input_digest(obj, built):
        # The images must be of the patches laid out, id for id.
        raise ValueError(
            f"{obj.Label}: the card or the sheet's settings changed since the layout; recompute "
            "first"
        )
    try:
        model = card_model(card)
        limbs = card_limbs(card) if model is not None else None
    except ValueError as error:
        raise ValueError(f"{obj.Label}: {card.Label}.SourceModel: {error}") from None
    if model is None:
        return None
    return source_model_artwork(
        model,
        built.scaffold,
        sheet_set,
        f"{obj.Label}: {card.Label}",
        run=lambda function, *args: progress.run(
            f"{obj.Label}: printing {card.Label}'s model on the patches", function, *args
        ),
        limbs=limbs,
    )


def card_prints_artwork(card):
    """Whether `card`'s sheets print its source model: False when every CuttingSheet laying it
    out has PrintArtwork off, True otherwise (a card without one prints, as the property's
    default does). `popup sheet` asks this of the document, the GUI export each sheet's own."""
    sheets = [
        o
        for o in card.Document.Objects
        if is_cutting_sheet(o) and o.Card is not None and o.Card.Name == card.Name
    ]
    return not sheets or any(bool(getattr(o, "PrintArtwork", True)) for o in sheets)


def not_valid_of(obj):
    """The NotValid stamp the CuttingSheet `obj` laid out with (None for a valid card)."""
    from popupwb.sheets.not_valid_stamp import PREFIX, NotValid

    if not obj.NotValid:
        return None
    return NotValid(obj.NotValid[len(PREFIX) :], tuple(obj.ValidityFindings))
