"""PopUp_CuttingSheet: a CuttingSheet laying out the selected card (a selected mechanism stands
for its card), or the document's only card (gui/add_cutting_sheet.py does the work)."""

import FreeCAD
import FreeCADGui

import popupwb
from popupwb.model import card_scaffold
from popupwb.gui.add_cutting_sheet import add_cutting_sheet
from popupwb.commands.selection import SelectionError, selected_card

COMMAND_ID = "PopUp_CuttingSheet"


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
    """What the command does; returns the new CuttingSheet (None, with a message, without card or
    when the user cancelled it in its progress dialog). The console shows the
    `popupwb.make.make_cutting_sheet(...)` line it ran, with the layout options the preferences
    set."""
    try:
        card = card or selected_card(FreeCAD.ActiveDocument)
    except SelectionError as error:
        FreeCAD.Console.PrintError(f"{COMMAND_ID}: {error}\n")
        return None
    return add_cutting_sheet(card)


FreeCADGui.addCommand(COMMAND_ID, CreateCuttingSheetCommand())
