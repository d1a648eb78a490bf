"""PopUp_CuttingSheet: a CuttingSheet laying out the selected card (a selected mechanism stands
for its card), or the document's only card."""

import FreeCAD
import FreeCADGui

import popupwb
from popupwb import card_scaffold

COMMAND_ID = "PopUp_CuttingSheet"
FIRST_PAPERS = ("A4", "A3")


def find_card(doc):
    """The root card of the first selected card or mechanism, else the only card, else None."""
    if doc is None:
        return None
    for obj in FreeCADGui.Selection.getSelection(doc.Name):
        try:
            return card_scaffold.root_card(obj)
        except ValueError:  # not a PopUp object, or a mechanism without card
            continue
    cards = [o for o in doc.Objects if card_scaffold.is_card(o)]
    return cards[0] if len(cards) == 1 else None


def first_paper(card):
    """The first of FIRST_PAPERS the card can be laid out on (an A4 card opens to A4 size and
    needs A3 paper); the first when none fits or the card does not build, and the sheet shows why.
    """
    from popupwb.sheets import export

    built = card_scaffold.for_card(card)
    if built.card_error is None:
        for paper in FIRST_PAPERS:
            try:
                export.layout(built.scaffold, paper=paper)
                return paper
            except ValueError:
                continue
    return FIRST_PAPERS[0]


class CreateCuttingSheetCommand:
    def GetResources(self):
        return {
            "Pixmap": popupwb.icon_path(COMMAND_ID),
            "MenuText": "Cutting sheets",
            "ToolTip": "Lay the selected card (or the only one) out flat on sheets of paper, with "
            "glue tabs, fold lines, labels and one TechDraw page per sheet",
        }

    def IsActive(self):
        doc = FreeCAD.ActiveDocument
        return doc is not None and any(card_scaffold.is_card(o) for o in doc.Objects)

    def Activated(self):
        create()


def create(card=None):
    """What the command does; returns the new CuttingSheet (None, with a message, without card)."""
    from popupwb.make import make_cutting_sheet

    doc = FreeCAD.ActiveDocument
    card = card or find_card(doc)
    if card is None:
        FreeCAD.Console.PrintError(
            f"{COMMAND_ID}: select a card or one of its mechanisms (the document has several "
            "cards or none)\n"
        )
        return None
    doc.openTransaction("Add cutting sheets")
    obj = make_cutting_sheet(card, paper=first_paper(card), name=f"{card.Name}Sheets")
    doc.commitTransaction()
    doc.recompute()
    if "Invalid" in obj.State:
        FreeCAD.Console.PrintError(f"{obj.getStatusString()}\n")
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(obj)
    return obj


FreeCADGui.addCommand(COMMAND_ID, CreateCuttingSheetCommand())
