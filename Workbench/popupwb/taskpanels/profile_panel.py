"""ProfilePanel: PopUp_SetProfile's task dialog. A ProfilePicker on one mechanism, its sketch
preselected from the selection; each choice applies at once and recomputes, so the 3D view shows
the profiled part, and the mechanism's own error (the core names the part and fold a profile
misses) shows under the picker. The whole edit is one undo transaction: OK commits it, Cancel
aborts it and restores what the mechanism had. OK also runs the headless line that gives the same
result through FreeCADGui.doCommand (`popupwb.profiles.set_profile_sketch(...)`), so the Python
console and the macro recorder show what the panel did, as the other commands do.
"""

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

from popupwb.taskpanels.mechanism_panel import in_error
from popupwb.taskpanels.profile_picker import ERROR_STYLE, OK_STYLE, ProfilePicker

last_panel = None  # the panel opened last (scripts and the GUI tests drive it)


class ProfilePanel:
    def __init__(self, obj, sketch=None):
        global last_panel
        last_panel = self
        self.obj = obj
        self.doc = obj.Document
        self.doc.openTransaction(f"Profile of {obj.Label}")
        self.form = QtGui.QWidget()
        self.form.setWindowTitle(f"Profile of {obj.Label}")
        self.form.setObjectName("PopUpProfilePanel")
        layout = QtGui.QVBoxLayout(self.form)
        self.status = QtGui.QLabel()
        self.status.setObjectName("MechanismStatus")
        self.status.setWordWrap(True)
        self.status.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)
        self.picker = ProfilePicker(obj, sketch, changed=self.recompute)
        layout.addWidget(self.picker.group)
        layout.addWidget(self.status)
        if sketch is not None:
            self.picker.apply()  # the selected sketch shows at once
        else:
            self.show_status()

    def recompute(self):
        self.doc.recompute()
        self.show_status()

    def show_status(self):
        if in_error(self.obj):
            self.status.setStyleSheet(ERROR_STYLE)
            self.status.setText(self.obj.getStatusString())
        else:
            self.status.setStyleSheet(OK_STYLE)
            self.status.setText(f"{self.obj.Label}: {len(self.obj.Shape.Faces)} faces, builds")

    # --- task dialog protocol ---------------------------------------------------------------

    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)

    def accept(self):
        if self.picker.error:
            return False  # keep the panel open: the line under the picker says why
        self.echo()
        self.doc.commitTransaction()
        FreeCADGui.Control.closeDialog()
        return True

    def echo(self):
        """Runs (and so shows and records) the line that sets what the panel set."""
        from popupwb.gui.echoed_python import import_echoed, object_expression

        obj, sketch = self.obj, self.obj.ProfileSketch
        if sketch is None:
            line = f"popupwb.profiles.clear_profile_sketch({object_expression(obj)})"
        else:
            line = (
                f"popupwb.profiles.set_profile_sketch({object_expression(obj)}, "
                f"{object_expression(sketch)}, {obj.ProfilePart!r}, {obj.ProfileMode!r})"
            )
        import_echoed("popupwb.profiles")
        FreeCADGui.doCommand(line)
        FreeCADGui.doCommand("FreeCAD.ActiveDocument.recompute()")

    def reject(self):
        self.doc.abortTransaction()
        self.doc.recompute()
        FreeCADGui.Control.closeDialog()
        FreeCAD.Console.PrintLog(f"{self.obj.Label}: profile unchanged\n")
        return True
