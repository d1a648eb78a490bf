"""One command per entry of popupwb.mechanism_registry (PopUp_TentFold, PopUp_BoxFold, ...): a
mechanism on the selected host (a card or a mechanism offering base patch pairs), or on the
document's only card."""

import FreeCAD
import FreeCADGui

from popupwb.model import card_scaffold
from popupwb.gui.echoed_python import object_expression, run_echoed
from popupwb.commands.selection import SelectionError, selected_host
from popupwb.mechanism_registry import COMMAND_IDS, by_command


class CreateMechanismCommand:
    def __init__(self, command_id):
        self.command_id = command_id

    def GetResources(self):
        mechanism = by_command(self.command_id)
        return {
            "Pixmap": mechanism.icon,
            "MenuText": mechanism.menu_text,
            "ToolTip": mechanism.tool_tip + " (or on the only card); double-click it to edit",
        }

    def IsActive(self):
        doc = FreeCAD.ActiveDocument
        return doc is not None and any(card_scaffold.is_card(o) for o in doc.Objects)

    def Activated(self):
        create(self.command_id)


def create(command_id, host=None):
    """What the command does; returns the new mechanism (None, with a message, without host).
    The console shows `popupwb.make.make_<type>(<host>)`: the host's defaults are fitted and
    placed beside the mechanisms already on the pair again on replay, so the line stays short and
    reproduces the same mechanism; with no free span left, the report view says so."""
    doc = FreeCAD.ActiveDocument
    try:
        host = host or selected_host(doc)
    except SelectionError as error:
        FreeCAD.Console.PrintError(f"{command_id}: {error}\n")
        return None
    mechanism = by_command(command_id)
    line = f"mechanism = popupwb.make.{mechanism.make_name}({object_expression(host)})"
    try:
        added = run_echoed(doc, f"Add {mechanism.menu_text.lower()}", [line])
    except ValueError as error:
        FreeCAD.Console.PrintError(f"{command_id}: {error}\n")
        return None
    obj = next(o for o in added if card_scaffold.is_mechanism(o))
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(obj)
    return obj


for _command_id in COMMAND_IDS:
    FreeCADGui.addCommand(_command_id, CreateMechanismCommand(_command_id))
