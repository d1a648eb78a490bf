"""PopUp_CheckValidity: validity report of the selected Scaffolds and cards (a selected mechanism
stands for its card; all of them when none is selected)."""

import FreeCAD
import FreeCADGui

import popupwb
from popupwb import card_scaffold
from popupwb.commands.selection import SelectionError, selected_designs
from popupwb.features.scaffold_feature import is_scaffold

COMMAND_ID = "PopUp_CheckValidity"

# Reports of the last run, for scripts and the GUI smoke test (the command returns nothing).
last_reports = []


def _checkable(obj):
    return is_scaffold(obj) or card_scaffold.is_card(obj)


class CheckValidityCommand:
    def GetResources(self):
        return {
            "Pixmap": popupwb.icon_path(COMMAND_ID),
            "MenuText": "Check validity",
            "ToolTip": "Check that the selected pop-ups (or all) fold flat, are stable, do not "
            "intersect and stay inside the closed card; the report goes to the report view and "
            "offending patches turn red",
        }

    def IsActive(self):
        doc = FreeCAD.ActiveDocument
        return doc is not None and any(_checkable(o) for o in doc.Objects)

    def Activated(self):
        from popupwb.validity import run_check

        _show_report_view()
        try:
            targets = selected_designs(FreeCAD.ActiveDocument)
        except SelectionError as error:
            FreeCAD.Console.PrintError(f"{COMMAND_ID}: {error}\n")
            return
        reports = []
        for obj in targets:
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
