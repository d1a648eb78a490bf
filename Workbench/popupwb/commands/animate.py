"""PopUp_Animate: plays the selected card (or the only one) from open to closed and back with the
fold player (gui/fold_player.py); running the command again stops the play."""

import FreeCAD
import FreeCADGui

import popupwb
from popupwb.model import card_scaffold
from popupwb.gui import fold_player
from popupwb.commands.selection import SelectionError, selected_card

COMMAND_ID = "PopUp_Animate"


class AnimateCommand:
    def GetResources(self):
        return {
            "Pixmap": popupwb.icon_path(COMMAND_ID),
            "MenuText": "Animate",
            "ToolTip": "Close the selected card and open it again (run again to stop)",
        }

    def IsActive(self):
        doc = FreeCAD.ActiveDocument
        return doc is not None and any(card_scaffold.is_card(o) for o in doc.Objects)

    def Activated(self):
        if fold_player.stop():
            return
        try:
            card = selected_card(FreeCAD.ActiveDocument)
        except SelectionError as error:
            FreeCAD.Console.PrintError(f"{COMMAND_ID}: {error}\n")
            return
        fold_player.play(card)


FreeCADGui.addCommand(COMMAND_ID, AnimateCommand())
