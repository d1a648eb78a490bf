"""PopUp_Card: a new folded card (A5 by default, or the preferences' size and paper thickness) in
the active document."""

import FreeCAD
import FreeCADGui

import popupwb
from popupwb import preferences
from popupwb.model import card_scaffold
from popupwb.gui.echoed_python import run_echoed

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


def create(preset=None):
    """What the command does; returns the new card, of `preset` (default: the preferences'). The
    console shows the `popupwb.make.make_card(...)` line it ran (and `FreeCAD.newDocument()`
    without a document)."""
    prefs = preferences.read_or_built_in(COMMAND_ID)
    preset = preset or prefs.card_preset
    if FreeCAD.ActiveDocument is None:
        FreeCADGui.doCommand("FreeCAD.newDocument()")
    doc = FreeCAD.ActiveDocument
    lines = [f"card = popupwb.make.make_card(FreeCAD.ActiveDocument, preset={preset!r})"]
    if prefs.paper_thickness is not None:
        lines.append(f"card.PaperThickness = {prefs.paper_thickness!r}")
    added = run_echoed(doc, "Add pop-up card", lines)
    card = next(o for o in added if card_scaffold.is_card(o))
    if FreeCADGui.ActiveDocument is not None:
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(card)
        FreeCADGui.ActiveDocument.ActiveView.fitAll()
    return card


FreeCADGui.addCommand(COMMAND_ID, CreateCardCommand())
