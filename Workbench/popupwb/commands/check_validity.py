"""PopUp_CheckValidity: validity report of the selected Scaffolds and cards (a selected mechanism
stands for its card; all of them when none is selected). The offending patches turn red and are
outlined; the check leaves nothing selected so that no selection colour hides them, and the card's
Validity (NotChecked, Valid, Invalid) marks its tree icon."""

import FreeCAD
import FreeCADGui

import popupwb
from popupwb.model import card_scaffold
from popupwb.gui.echoed_python import import_echoed, object_expression
from popupwb.commands.selection import SelectionError, selected_designs
from popupwb.features.scaffold_feature import is_scaffold

COMMAND_ID = "PopUp_CheckValidity"

# Names of the objects the last run checked, for scripts and the GUI smoke test (each check
# writes its verdict into the object's Valid and Diagnostics).
last_checked = []


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
        _show_report_view()
        try:
            targets = selected_designs(FreeCAD.ActiveDocument)
        except SelectionError as error:
            FreeCAD.Console.PrintError(f"{COMMAND_ID}: {error}\n")
            return
        import_echoed("popupwb.validity")
        checked = []
        for obj in targets:
            # Echoed like the commands that add objects, so a macro can re-run the check.
            try:
                FreeCADGui.doCommand(f"popupwb.validity.run_check({object_expression(obj)})")
                checked.append(obj.Name)
            except RuntimeError as error:  # a core failure on one object must not stop the rest
                FreeCAD.Console.PrintError(f"{obj.Label}: validity check failed: {error}\n")
        last_checked[:] = checked
        # A selected object is drawn in the selection colour, which covers the red of its
        # offending faces: leave nothing selected, so the findings are what the view shows.
        FreeCADGui.Selection.clearSelection()


def _show_report_view():
    # Non-blocking: the report goes to the report view, never to a modal dialog.
    from PySide import QtGui

    window = FreeCADGui.getMainWindow()
    dock = window.findChild(QtGui.QDockWidget, "Report view") if window else None
    if dock is not None:
        dock.show()


FreeCADGui.addCommand(COMMAND_ID, CheckValidityCommand())
