"""The modal progress dialog with Cancel that popupwb.progress shows in FreeCAD's GUI once work has
taken SHOW_AFTER_MS. Importing this module registers it with popupwb.progress (InitGui.py does,
when FreeCAD's GUI loads the workbench), so the headless module needs no Qt of its own.
"""

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

from popupwb import progress


class ProgressDialogs:
    """What popupwb.progress asks of the GUI: whether a dialog can be shown, a dialog shown, the
    events processed while the work runs, the dialog closed."""

    @staticmethod
    def can_show():
        return bool(FreeCAD.GuiUp) and QtGui.QApplication.instance() is not None

    @staticmethod
    def show(label, count, value):
        window = FreeCADGui.getMainWindow()
        dialog = QtGui.QProgressDialog(label, "Cancel", 0, count, window)
        dialog.setObjectName(progress.DIALOG_NAME)
        dialog.setWindowTitle("PopUp")
        dialog.setWindowModality(QtCore.Qt.ApplicationModal)
        dialog.setAutoClose(False)
        dialog.setAutoReset(False)
        dialog.setMinimumDuration(0)
        dialog.setMinimumWidth(360)
        dialog.setValue(value)
        dialog.show()
        return dialog

    @staticmethod
    def process_events():
        # The dialog is application modal: only its Cancel button takes input.
        QtCore.QCoreApplication.processEvents(QtCore.QEventLoop.AllEvents, 50)

    @staticmethod
    def close(dialog):
        # Deleted now: deleteLater would wait for the outermost event loop when this runs inside a
        # recompute or another wait.
        dialog.hide()
        dialog.setParent(None)


progress.dialogs = ProgressDialogs()
