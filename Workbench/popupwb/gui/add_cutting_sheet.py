"""Adding a card's CuttingSheet from the GUI: what PopUp_CuttingSheet and the card panel's Make
sheets button do. The paper is the preferences' or the first that fits; the console shows the
`popupwb.make.make_cutting_sheet(...)` line it ran, as an undo step of its own. A cancelled or
refused layout says why in one line (and selects the piece to fix) and leaves no sheet behind.
"""

import FreeCAD
import FreeCADGui

from popupwb import preferences, progress
from popupwb.model import card_scaffold
from popupwb.features.cutting_sheet import has_layout, is_cutting_sheet
from popupwb.gui.echoed_python import object_expression, run_echoed
from popupwb.gui.select_at_fault import select_at_fault

MESSAGE_PREFIX = "PopUp_CuttingSheet"  # what the preferences' messages start with: the command
FIRST_PAPERS = ("A4", "A3")


def first_paper(card):
    """The first of FIRST_PAPERS the card can be laid out on (an A4 card opens to A4 size and
    needs A3 paper); the first when none fits or the card does not build, and the sheet shows why.
    """
    from popupwb.sheets import export

    built = card_scaffold.for_card(card)
    if built.card_error is None:
        for paper in FIRST_PAPERS:
            try:
                progress.run(
                    f"{card.Label}: trying {paper} paper",
                    export.layout,
                    built.scaffold,
                    paper=paper,
                    cancel=progress.CANCEL_FLAG,
                )
                return paper
            except ValueError:
                continue
    return FIRST_PAPERS[0]


def paper_arguments(prefs, card):
    """make_cutting_sheet's paper keywords: the preferences' paper (a preset, or its width and
    height), else the first of FIRST_PAPERS the card fits."""
    from popupwb.core import popupcore
    from popupwb.features.cutting_sheet import PAPERS

    if prefs.sheet_paper is None:
        return f"paper={first_paper(card)!r}"
    name, width, height = popupcore.paper_size(prefs.sheet_paper)
    return (
        f"paper={name!r}" if name in PAPERS else f"paper_width={width!r}, paper_height={height!r}"
    )


def add_cutting_sheet(card):
    """Adds a CuttingSheet laying out `card` (in the active document) and selects it; returns it
    (None, with a message, when the user cancelled it in its progress dialog or it could not be
    laid out). The layout options are the preferences'."""
    doc = FreeCAD.ActiveDocument
    prefs = preferences.read_or_built_in(MESSAGE_PREFIX)
    options = "".join(f", {key}={value!r}" for key, value in prefs.sheet_options.items())
    try:
        paper = paper_arguments(prefs, card)
    except progress.Cancelled as cancelled:
        FreeCAD.Console.PrintWarning(f"{cancelled}\n")
        return None
    line = (
        f"sheet = popupwb.make.make_cutting_sheet({object_expression(card)}, "
        f"{paper}{options}, name={card.Name + 'Sheets'!r})"
    )
    cancels = len(progress.cancelled)
    added = run_echoed(doc, "Add cutting sheets", [line])
    obj = next(o for o in added if is_cutting_sheet(o))
    # Cancelled in its recompute; FreeCAD may have run it once more since, so its status alone
    # does not tell.
    if len(progress.cancelled) > cancels or progress.is_cancelled_message(obj.getStatusString()):
        FreeCAD.Console.PrintWarning(f"{obj.getStatusString()}: no cutting sheets added\n")
        doc.undo()  # the transaction that added it
        return None
    if "Invalid" not in obj.State and not has_layout(obj):
        # FreeCAD recomputes nothing in a document whose links form a loop (a damaged file's
        # Host loop): the sheet was never laid out. Say why rather than leave it silently empty.
        why = list(card_scaffold.for_card(card).errors.values()) or [
            "FreeCAD did not recompute the document (see the report view)"
        ]
        FreeCAD.Console.PrintError(f"{obj.Label}: not laid out: {'; '.join(why)}\n")
        doc.undo()  # the transaction that added it
        return None
    if "Invalid" in obj.State:
        # Refused (an invalid card needs Force): say why in one line, select the piece to fix.
        FreeCAD.Console.PrintError(f"{obj.getStatusString()}\n")
        if select_at_fault(obj):
            return obj
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(obj)
    return obj
