"""PopUp_CheckValidity: validity report of the selected Scaffolds and cards (a selected mechanism
stands for its card; all of them when none is selected)."""

import FreeCAD
import FreeCADGui

import popupwb
from popupwb import card_scaffold
from popupwb.features.scaffold_feature import is_scaffold

COMMAND_ID = "PopUp_CheckValidity"

# Reports of the last run, for scripts and the GUI smoke test (the command returns nothing).
last_reports = []


def _checkable(obj):
    return is_scaffold(obj) or card_scaffold.is_card(obj)


def _target(obj):
    """The object a check of `obj` runs on: itself, or the card of a mechanism (None if none)."""
    if _checkable(obj):
        return obj
    if card_scaffold.is_mechanism(obj):
        try:
            return card_scaffold.root_card(obj)
        except ValueError:
            return None
    return None


def _targets():
    doc = FreeCAD.ActiveDocument
    if doc is None:
        return []
    selected = []
    for obj in FreeCADGui.Selection.getSelection(doc.Name):
        target = _target(obj)
        if target is not None and all(target is not other for other in selected):
            selected.append(target)
    return selected or [o for o in doc.Objects if _checkable(o)]


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
