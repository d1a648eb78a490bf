"""PopUp_SetProfile: puts a Sketcher sketch on a principal part of a mechanism as its profile (a
tree drawn in a sketch on a step's riser). Select a mechanism and a sketch (in either order; the
sketch may be left out when the document has only one) and the command opens ProfilePanel
(taskpanels/profile_panel.py) on them: the part and Clip or Scale are chosen there, the outline
shows at once, OK keeps it in one undo step. A sketch without a closed outline is refused in one
line naming it."""

import FreeCAD
import FreeCADGui

import popupwb
from popupwb.model import card_scaffold
from popupwb.profiles import editing
from popupwb.commands.selection import SelectionError, selected_objects

COMMAND_ID = "PopUp_SetProfile"


class SetProfileCommand:
    def GetResources(self):
        return {
            "Pixmap": popupwb.icon_path(COMMAND_ID),
            "MenuText": "Profile from sketch",
            "ToolTip": "Cut the outline drawn in a Sketcher sketch into a part of the selected "
            "mechanism (select the mechanism and the sketch): choose the part, and whether the "
            "outline is clipped or scaled when the mechanism's dimensions change",
        }

    def IsActive(self):
        doc = FreeCAD.ActiveDocument
        if doc is None or FreeCADGui.Control.activeDialog():
            return False
        return any(card_scaffold.is_mechanism(o) for o in selected_objects(doc))

    def Activated(self):
        open_panel()


def selected_mechanism_and_sketch(doc):
    """(mechanism, sketch or None) from the selection: the first selected mechanism, the first
    selected Sketcher sketch, else the document's only sketch. SelectionError says what to
    select."""
    selected = selected_objects(doc)
    mechanisms = [o for o in selected if card_scaffold.is_mechanism(o)]
    if not mechanisms:
        raise SelectionError("select a mechanism and the Sketcher sketch of its profile")
    sketches = [o for o in selected if o in editing.sketches_of(doc)]
    if not sketches:
        sketches = editing.sketches_of(doc)
        if len(sketches) != 1:
            sketches = []  # none or several: the panel's Sketch box asks
    return mechanisms[0], (sketches[0] if sketches else None)


def open_panel(obj=None, sketch=None):
    """Opens ProfilePanel on `obj` and `sketch` (default: from the selection); returns it, or
    None with the reason in the report view."""
    from popupwb.taskpanels.profile_panel import ProfilePanel

    doc = FreeCAD.ActiveDocument
    if obj is None:
        try:
            obj, chosen = selected_mechanism_and_sketch(doc)
        except SelectionError as error:
            FreeCAD.Console.PrintError(f"{COMMAND_ID}: {error}\n")
            return None
        sketch = sketch or chosen
    panel = ProfilePanel(obj, sketch)
    FreeCADGui.Control.showDialog(panel)
    return panel


FreeCADGui.addCommand(COMMAND_ID, SetProfileCommand())
