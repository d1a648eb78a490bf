"""PopUp_LoadDesign: a Scaffold from a design file chosen in a file dialog."""

import os

import FreeCAD
import FreeCADGui

import popupwb
from popupwb.gui.echoed_python import run_echoed
from popupwb.features.scaffold_feature import is_scaffold

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
    """What the command does once a file is chosen; returns the new object (or None). The console
    shows the `popupwb.make.make_scaffold(...)` line it ran."""
    if FreeCAD.ActiveDocument is None:
        FreeCADGui.doCommand("FreeCAD.newDocument()")
    doc = FreeCAD.ActiveDocument
    label = os.path.splitext(os.path.basename(path))[0]
    lines = [
        f"scaffold = popupwb.make.make_scaffold(FreeCAD.ActiveDocument, {path!r})",
        f"scaffold.Label = {label!r}",
    ]
    try:
        added = run_echoed(doc, "Load pop-up design", lines)
    except (OSError, ValueError) as error:
        FreeCAD.Console.PrintError(f"PopUp: {error}\n")
        return None
    obj = next(o for o in added if is_scaffold(o))
    if FreeCADGui.ActiveDocument is not None:
        FreeCADGui.ActiveDocument.ActiveView.fitAll()
    return obj


FreeCADGui.addCommand(COMMAND_ID, LoadDesignCommand())
