"""PopUp_ExportSheets: writes the selected CuttingSheet's production files (sheets.dxf, .svg,
.pdf, instructions.pdf, report.json, sheets.json) into a folder chosen in a dialog, which opens
on the preferences' export folder; the layers have the preferences' names and colours. A card
designed from a model gets the model's artwork and registration marks on the PDF and SVG print
layer while the sheet's PrintArtwork is set (rendering shows progress and can be cancelled).

The files come from the layout the CuttingSheet keeps (SheetSetJson): what it shows is what is
written, with no second layout. The command is disabled until there is a layout to write (the
selected cutting sheet's, or any when none is selected); a failure says why in one line and
selects the piece to fix (gui/select_at_fault.py). export_cutting_sheet() does the work without
GUI; it lives with the feature because importing this package needs the GUI.
"""

import json

import FreeCAD
import FreeCADGui

import popupwb
from popupwb import preferences, progress
from popupwb.commands.selection import SelectionError, selected_cutting_sheet
from popupwb.features.cutting_sheet import export_cutting_sheet, has_layout, is_cutting_sheet
from popupwb.gui.select_at_fault import select_at_fault
from popupwb.model.model_source import has_source_model

COMMAND_ID = "PopUp_ExportSheets"


class ExportSheetsCommand:
    def GetResources(self):
        return {
            "Pixmap": popupwb.icon_path(COMMAND_ID),
            "MenuText": "Export cutting sheets",
            "ToolTip": "Write the selected cutting sheet (or the only one) as DXF, SVG and PDF, "
            "with assembly instructions and a report, into a folder",
        }

    def IsActive(self):
        doc = FreeCAD.ActiveDocument
        if doc is None:
            return False
        try:
            return has_layout(selected_cutting_sheet(doc))
        except SelectionError:  # none or several: Activated asks which
            return any(is_cutting_sheet(o) and has_layout(o) for o in doc.Objects)

    def Activated(self):
        from PySide import QtGui

        try:
            obj = selected_cutting_sheet(FreeCAD.ActiveDocument)
        except SelectionError as error:
            FreeCAD.Console.PrintError(f"{COMMAND_ID}: {error}\n")
            return
        prefs = preferences.read_or_built_in(COMMAND_ID)
        folder = QtGui.QFileDialog.getExistingDirectory(
            FreeCADGui.getMainWindow(), f"Export {obj.Label} into", prefs.export_folder
        )
        if not folder:
            return
        try:
            paths = export_cutting_sheet(obj, folder, style=prefs.style)
        except progress.Cancelled as cancelled:
            FreeCAD.Console.PrintWarning(f"{cancelled}: nothing written\n")
            return
        except (OSError, ValueError) as error:
            FreeCAD.Console.PrintError(f"{COMMAND_ID}: {error}\n")
            if isinstance(error, ValueError):
                select_at_fault(obj)
            return
        report(obj, paths)


def report(obj, paths):
    """Prints the written files and the layout's findings to the report view."""
    artwork = "with" if obj.PrintArtwork and has_source_model(obj.Card) else "without"
    lines = [f"{obj.Label}: wrote ({artwork} artwork)"]
    for kind, written in paths.items():
        for path in written if isinstance(written, list) else [written]:
            lines.append(f"  {kind}: {path}")
    FreeCAD.Console.PrintMessage("\n".join(lines) + "\n")
    for line in obj.Diagnostics:
        FreeCAD.Console.PrintWarning(f"{obj.Label}: {line}\n")
    with open(paths["report"]) as f:
        checks = json.load(f)
    if not checks["round_trip"]["ok"]:
        FreeCAD.Console.PrintError(f"{obj.Label}: the flat pieces do not fold back into the card\n")
    for error in checks["errors"]:
        FreeCAD.Console.PrintError(f"{obj.Label}: {error['message']}\n")


FreeCADGui.addCommand(COMMAND_ID, ExportSheetsCommand())
