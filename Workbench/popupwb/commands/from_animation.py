"""PopUp_FromAnimation: an animated pop-up card designed from a character's animation (issue 13),
through FromAnimationPanel (taskpanels/from_animation_panel.py): the animation file, frames,
viewpoint, pruning, weights, iterations and seed, a design with a progress bar and Cancel, the
target paths against the mechanisms' paths, then OK builds the card."""

import FreeCAD
import FreeCADGui

import popupwb

COMMAND_ID = "PopUp_FromAnimation"
FILE_FILTER = (
    "Animations (*.bvh *.fbx *.gltf *.glb *.dae *.json);;BVH (*.bvh);;FBX (*.fbx);;"
    "glTF (*.gltf *.glb);;Collada (*.dae);;Named trajectories (*.json);;All files (*)"
)


class FromAnimationCommand:
    def GetResources(self):
        return {
            "Pixmap": popupwb.icon_path(COMMAND_ID),
            "MenuText": "Pop-up from animation",
            "ToolTip": "Design an animated pop-up card from a character's animation (BVH, FBX, "
            "glTF, Collada or named trajectories): its limbs become motion mechanisms that move "
            "like them as the card opens",
        }

    def IsActive(self):
        return FreeCADGui.Control.activeDialog() is False

    def Activated(self):
        from PySide import QtGui

        path, _ = QtGui.QFileDialog.getOpenFileName(
            FreeCADGui.getMainWindow(), "Animation to design from", "", FILE_FILTER
        )
        if path:
            open_panel(path)


def open_panel(path, doc=None):
    """Opens the panel on the animation file `path`, for `doc` (default: the active document,
    else a new one); returns it."""
    from popupwb.commands.from_model import card_size
    from popupwb.taskpanels.from_animation_panel import FromAnimationPanel

    doc = doc or FreeCAD.ActiveDocument or FreeCAD.newDocument("PopUpAnimation")
    panel = FromAnimationPanel(path, doc, card_size())
    FreeCADGui.Control.showDialog(panel)
    return panel


FreeCADGui.addCommand(COMMAND_ID, FromAnimationCommand())
