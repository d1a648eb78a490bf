"""The right-click menu of the 3D view and the tree on PopUp objects: what applies to the selected
card or mechanism. InitGui's ContextMenu appends these entries; nothing PopUp is selected, nothing
is added."""

import FreeCAD
import FreeCADGui

from popupwb.model import card_scaffold
from popupwb import commands as c


def entries():
    """[(submenu name, "" for the menu itself; [command ids and "Separator"])] for the current
    selection: the mechanism submenu on a card or a mechanism offering base patch pairs (the
    commands nest on it), then the profile from a sketch on a mechanism, check and play; a card's
    menu adds the cutting sheet."""
    doc = FreeCAD.ActiveDocument
    selected = list(FreeCADGui.Selection.getSelection(doc.Name)) if doc is not None else []
    popup = [o for o in selected if card_scaffold.is_card(o) or card_scaffold.is_mechanism(o)]
    if not popup:
        return []
    found = []
    if any(card_scaffold.host_pair_names(o) for o in popup):
        found.append((c.ADD_MECHANISM_SUBMENU, c.add_mechanism_commands()))
    tail = [c.SEPARATOR] if found else []  # FreeCAD separates ours
    if any(card_scaffold.is_mechanism(o) for o in popup):
        tail += c.PROFILE_COMMANDS + [c.SEPARATOR]
    tail += c.CHECK_COMMANDS
    if any(card_scaffold.is_card(o) for o in popup):
        tail.append(c.SHEET_COMMANDS[0])  # the cutting sheet is made from a card
    found.append(("", tail))
    return found
