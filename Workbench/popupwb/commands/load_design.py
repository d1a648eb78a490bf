"""PopUp_LoadDesign: a Scaffold from a design file chosen in a file dialog."""

import os

import FreeCAD
import FreeCADGui

import popupwb

COMMAND_ID = "PopUp_LoadDesign"


def _start_dir():
    samples = os.path.join(popupwb.REPO_DIR, "resources", "samples")
    return samples if os.path.isdir(samples) else os.path.expanduser("~")


class LoadDesignCommand:
    def GetResources(self):
        return {
            "Pixmap": popupwb.icon_path(COMMAND_ID),
            "MenuText": "Load design",
            "ToolTip": "Load a pop-up design file (*.json) as a Scaffold object",
        }

    def IsActive(self):
        return True

    def Activated(self):
        from PySide import QtGui

        path, _ = QtGui.QFileDialog.getOpenFileName(
            FreeCADGui.getMainWindow(),
            "Load a pop-up design",
            _start_dir(),
            "PopUp designs (*.json);;All files (*)",
        )
        if path:
            load(path)


def load(path):
    """What the command does once a file is chosen; returns the new object (or None)."""
    from popupwb.make import make_scaffold

    doc = FreeCAD.ActiveDocument or FreeCAD.newDocument()
    doc.openTransaction("Load pop-up design")
    try:
        obj = make_scaffold(doc, path)
    except (OSError, ValueError) as error:
        doc.abortTransaction()
        FreeCAD.Console.PrintError(f"PopUp: {error}\n")
        return None
    obj.Label = os.path.splitext(os.path.basename(path))[0]
    doc.commitTransaction()
    doc.recompute()
    if FreeCADGui.ActiveDocument is not None:
        FreeCADGui.ActiveDocument.ActiveView.fitAll()
    return obj


FreeCADGui.addCommand(COMMAND_ID, LoadDesignCommand())
