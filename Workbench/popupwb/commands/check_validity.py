"""PopUp_CheckValidity: validity report of the selected Scaffolds (all of them when none is)."""

import FreeCAD
import FreeCADGui

import popupwb
from popupwb.features.scaffold_feature import is_scaffold

COMMAND_ID = "PopUp_CheckValidity"

# Reports of the last run, for scripts and the GUI smoke test (the command returns nothing).
last_reports = []


def _targets():
    doc = FreeCAD.ActiveDocument
    if doc is None:
        return []
    selected = [o for o in FreeCADGui.Selection.getSelection(doc.Name) if is_scaffold(o)]
    return selected or [o for o in doc.Objects if is_scaffold(o)]


class CheckValidityCommand:
    def GetResources(self):
        return {
            "Pixmap": popupwb.icon_path(COMMAND_ID),
            "MenuText": "Check validity",
            "ToolTip": "Check that the selected pop-ups (or all) fold flat, are stable, do not "
            "intersect and stay inside the closed card; the report goes to the report view",
        }

    def IsActive(self):
        doc = FreeCAD.ActiveDocument
        return doc is not None and any(is_scaffold(o) for o in doc.Objects)

    def Activated(self):
        from popupwb.validity import run_check

        _show_report_view()
        reports = []
        for obj in _targets():
            try:
                reports.append(run_check(obj))
            except RuntimeError as error:  # a core failure on one object must not stop the rest
                FreeCAD.Console.PrintError(f"{obj.Label}: validity check failed: {error}\n")
        last_reports[:] = reports


def _show_report_view():
    # Non-blocking: the report goes to the report view, never to a modal dialog.
    from PySide import QtGui

    window = FreeCADGui.getMainWindow()
    dock = window.findChild(QtGui.QDockWidget, "Report view") if window else None
    if dock is not None:
        dock.show()


FreeCADGui.addCommand(COMMAND_ID, CheckValidityCommand())
