"""PopUp_FromModel: a pop-up card designed from the selected mesh or Part shape (issue 12), through
FromModelPanel (taskpanels/from_model_panel.py): alignment, maximum mechanisms, detail and seed,
a fit with progress and Cancel, the fitted prisms over the model, then OK builds the card."""

import FreeCAD
import FreeCADGui

import popupwb
from popupwb import preferences
from popupwb.commands.selection import SelectionError, selected_model

COMMAND_ID = "PopUp_FromModel"


class FromModelCommand:
    def GetResources(self):
        return {
            "Pixmap": popupwb.icon_path(COMMAND_ID),
            "MenuText": "Pop-up from model",
            "ToolTip": "Design a pop-up card from the selected mesh or Part shape: prisms fitted "
            "to the model become box, step, v- and tent folds you can keep editing",
        }

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None and FreeCADGui.Control.activeDialog() is False

    def Activated(self):
        open_panel()


def card_size():
    """(width, depth) of the maker's new-card preset, or None for a custom one (the core's)."""
    from popupwb.features.card_feature import PRESETS

    return PRESETS.get(preferences.read_or_built_in(COMMAND_ID).card_preset)


def open_panel(obj=None):
    """Opens the panel on `obj` (default: the selected or only mesh or shape); returns it, or None
    with the reason in the report view."""
    from popupwb.taskpanels.from_model_panel import FromModelPanel

    try:
        obj = obj or selected_model(FreeCAD.ActiveDocument)
    except SelectionError as error:
        FreeCAD.Console.PrintError(f"{COMMAND_ID}: {error}\n")
        return None
    panel = FromModelPanel(obj, card_size())
    FreeCADGui.Control.showDialog(panel)
    return panel


FreeCADGui.addCommand(COMMAND_ID, FromModelCommand())
