"""One command per entry of popupwb.mechanism_registry (PopUp_TentFold, PopUp_BoxFold, ...): a
mechanism on the selected host (a card or a mechanism offering base patch pairs), or on the
document's only card."""

import FreeCAD
import FreeCADGui

from popupwb import card_scaffold
from popupwb.mechanism_registry import COMMAND_IDS, by_command


def _is_host(obj):
    return bool(card_scaffold.host_pair_names(obj))


def find_host(doc):
    """The selected card or mechanism that offers base patch pairs, else the only card, else
    None."""
    if doc is None:
        return None
    selected = [o for o in FreeCADGui.Selection.getSelection(doc.Name) if _is_host(o)]
    if selected:
        return selected[0]
    cards = [o for o in doc.Objects if card_scaffold.is_card(o)]
    return cards[0] if len(cards) == 1 else None


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
    """What the command does; returns the new mechanism (None, with a message, without host)."""
    from popupwb import make

    doc = FreeCAD.ActiveDocument
    host = host or find_host(doc)
    if host is None:
        FreeCAD.Console.PrintError(
            f"{command_id}: select a card or a box fold to build on (the document has "
            "several cards or none)\n"
        )
        return None
    mechanism = by_command(command_id)
    doc.openTransaction(f"Add {mechanism.menu_text.lower()}")
    try:
        obj = getattr(make, mechanism.make_name)(host)
    except ValueError as error:
        doc.abortTransaction()
        FreeCAD.Console.PrintError(f"{command_id}: {error}\n")
        return None
    doc.commitTransaction()
    doc.recompute()
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(obj)
    return obj


for _command_id in COMMAND_IDS:
    FreeCADGui.addCommand(_command_id, CreateMechanismCommand(_command_id))
