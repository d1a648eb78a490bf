"""PopUp_Card: a new folded card (A5 by default) in the active document."""

import FreeCAD
import FreeCADGui

import popupwb

COMMAND_ID = "PopUp_Card"


class CreateCardCommand:
    def GetResources(self):
        return {
            "Pixmap": popupwb.icon_path(COMMAND_ID),
            "MenuText": "Card",
            "ToolTip": "Add a folded card (A5; change Preset, Width and Depth in its properties) "
            "to carry pop-up mechanisms",
        }

    def IsActive(self):
        return True

    def Activated(self):
        create()


def create(preset="A5"):
    """What the command does; returns the new card."""
    from popupwb.make import make_card

    doc = FreeCAD.ActiveDocument or FreeCAD.newDocument()
    doc.openTransaction("Add pop-up card")
    card = make_card(doc, preset=preset)
    doc.commitTransaction()
    doc.recompute()
    if FreeCADGui.ActiveDocument is not None:
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(card)
        FreeCADGui.ActiveDocument.ActiveView.fitAll()
    return card


FreeCADGui.addCommand(COMMAND_ID, CreateCardCommand())
