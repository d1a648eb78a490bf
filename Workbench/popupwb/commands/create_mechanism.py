"""PopUp_TentFold, PopUp_StepFold, PopUp_VFold, PopUp_BoxFold, PopUp_VBoxFold,
PopUp_RotationArm, PopUp_HorizontalTranslation, PopUp_VerticalTranslation, PopUp_FloatingLayer:
a mechanism on the selected host (a card or a mechanism offering base patch pairs), or on the
document's only card."""

import FreeCAD
import FreeCADGui

import popupwb
from popupwb import card_scaffold

# command id -> (make function name, menu text, tool tip)
MECHANISMS = {
    "PopUp_TentFold": (
        "make_tent_fold",
        "Tent fold",
        "Add a tent fold (two slopes meeting at an apex) on the selected card, box fold or floating layer",
    ),
    "PopUp_StepFold": (
        "make_step_fold",
        "Step fold",
        "Add a parallelogram step fold on the selected card, box fold or floating layer",
    ),
    "PopUp_VFold": (
        "make_v_fold",
        "V-fold",
        "Add a v-fold (two triangles on a spine) on the selected card, box fold or floating layer",
    ),
    "PopUp_BoxFold": (
        "make_box_fold",
        "Box fold",
        "Add a box fold on the selected card, box fold or floating layer; it offers its top and sides as hosts",
    ),
    "PopUp_VBoxFold": (
        "make_v_box_fold",
        "V-box",
        "Add a type-1 v-fold (four walls on a rhombus, two-triangle top) on the selected card "
        "or box fold",
    ),
    "PopUp_RotationArm": (
        "make_rotation_arm",
        "Rotation arm",
        "Add a rotation arm (a flat v-fold whose wing carries an arm past the spine) on the "
        "selected card or box fold",
    ),
    "PopUp_HorizontalTranslation": (
        "make_horizontal_translation",
        "Horizontal translation",
        "Add a horizontal translation (a step fold and a patch sliding through a slit at its "
        "nose) on the selected card or box fold",
    ),
    "PopUp_VerticalTranslation": (
        "make_vertical_translation",
        "Vertical translation",
        "Add a vertical translation (front walls and a two-triangle top whose front corner slides "
        "along the fold) on the selected card or box fold",
    ),
    "PopUp_FloatingLayer": (
        "make_floating_layer",
        "Floating layer",
        "Add a floating layer (a platform parallel to its host on two supports) on the selected "
        "card or box fold; it offers its platform and supports as hosts",
    ),
}
COMMAND_IDS = list(MECHANISMS)


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
        self.make_name, self.menu_text, self.tool_tip = MECHANISMS[command_id]

    def GetResources(self):
        return {
            "Pixmap": popupwb.icon_path(self.command_id),
            "MenuText": self.menu_text,
            "ToolTip": self.tool_tip + " (or on the only card); double-click it to edit",
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
    make_name, menu_text, _ = MECHANISMS[command_id]
    doc.openTransaction(f"Add {menu_text.lower()}")
    try:
        obj = getattr(make, make_name)(host)
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
