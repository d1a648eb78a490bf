"""MechanismPanel: the parameters of any mechanism feature, with live preview and its error.

Every parameter of the feature's proxy (MechanismFeature.PARAMETERS) becomes a spin box (lengths
in mm, angles in degrees) or a check box, and the host pair a combo box. A change is applied at
once and the document recomputed, so the 3D view follows; the feature's error (the core names the
bad property) shows under the fields, and under it the span the mechanism occupies along its host
pair, drawn on the fold while the panel is open (SpanOverlay). Under them, the Profile group
(ProfilePicker) puts a Sketcher sketch on one of its parts, Clip or Scale. The whole edit is one undo
transaction: OK commits it, Cancel aborts it and restores the values the feature had.
"""

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

from popupwb.model import placement
from popupwb.taskpanels.span_overlay import SpanOverlay

LIMIT = 1.0e5  # mm or degrees: wide enough for any card, the core judges the real range

last_panel = None  # the panel opened last (scripts and the GUI smoke test drive it)


def in_error(obj):
    return "Invalid" in obj.State or "Error" in obj.State


class MechanismPanel:
    """Task dialog of one mechanism (FreeCADGui.Control.showDialog(MechanismPanel(obj)))."""

    def __init__(self, obj):
        global last_panel
        last_panel = self
        self.obj = obj
        self.doc = obj.Document
        self.doc.openTransaction(f"Edit {obj.Label}")
        self.form = QtGui.QWidget()
        self.form.setWindowTitle(obj.Label)
        layout = QtGui.QFormLayout(self.form)
        self.fields = {}

        self.host_pair = QtGui.QComboBox()
        self.host_pair.addItems(list(obj.getEnumerationsOfProperty("HostPair") or []))
        self.host_pair.setCurrentIndex(max(self.host_pair.findText(obj.HostPair), 0))
        self.host_pair.currentIndexChanged.connect(self.on_host_pair)
        layout.addRow("Host pair", self.host_pair)

        for p in obj.Proxy.PARAMETERS:
            if p.kind == "bool":
                field = QtGui.QCheckBox()
                field.setChecked(bool(getattr(obj, p.name)))
                field.toggled.connect(lambda value, name=p.name: self.apply(name, bool(value)))
            elif p.kind == "integer":
                field = QtGui.QSpinBox()
                field.setRange(-1000, 1000)  # the core judges the value and names the range
                field.setValue(int(getattr(obj, p.name)))
                field.setKeyboardTracking(False)
                field.valueChanged.connect(lambda value, name=p.name: self.apply(name, int(value)))
            else:
                field = QtGui.QDoubleSpinBox()
                field.setDecimals(2)
                field.setRange(-LIMIT, LIMIT)
                field.setSingleStep(1.0)
                field.setSuffix(" °" if p.kind == "angle" else " mm")
                field.setValue(getattr(obj, p.name).Value)
                field.setKeyboardTracking(False)  # apply typed numbers on Enter or focus out
                field.valueChanged.connect(lambda value, name=p.name: self.apply(name, value))
            field.setToolTip(p.doc)
            field.setObjectName(p.name)
            self.fields[p.name] = field
            layout.addRow(p.name, field)

        self.message = QtGui.QLabel()
        self.message.setWordWrap(True)
        self.message.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)
        layout.addRow(self.message)
        # Where it stands along its host pair and what it overlaps (thesis §4.2.2), also drawn
        # on the fold while the panel is open.
        self.span = QtGui.QLabel()
        self.span.setObjectName("Span")
        self.span.setWordWrap(True)
        self.span.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)
        layout.addRow(self.span)
        self.profile = None
        if hasattr(obj, "ProfileSketch"):
            from popupwb.taskpanels.profile_picker import ProfilePicker

            self.profile = ProfilePicker(obj, changed=self.on_profile)
            layout.addRow(self.profile.group)
        self.overlay = SpanOverlay(obj)
        self.form.destroyed.connect(lambda *_: self.overlay.remove())
        self.show_status()

    # --- applying ---------------------------------------------------------------------------

    def apply(self, name, value):
        """Sets property `name`, recomputes and shows the feature's error, if any."""
        setattr(self.obj, name, value)
        self.doc.recompute()
        if self.profile is not None:
            self.profile.refresh_parts()  # the parts follow the parameters (PanelPairs)
        self.show_status()

    def on_profile(self):
        self.doc.recompute()
        self.show_status()

    def on_host_pair(self, index):
        if index >= 0:
            self.apply("HostPair", self.host_pair.itemText(index))

    def set_value(self, name, value):
        """What typing `value` into the field `name` does (scripts and the GUI smoke test)."""
        field = self.fields[name]
        if isinstance(field, QtGui.QCheckBox):
            field.setChecked(bool(value))
        elif isinstance(field, QtGui.QSpinBox):
            field.setValue(int(value))
        else:
            field.setValue(float(value))

    def show_status(self):
        if in_error(self.obj):
            self.message.setStyleSheet("color: #b00000;")
            self.message.setText(self.obj.getStatusString())
        else:
            self.message.setStyleSheet("color: #206020;")
            self.message.setText(f"{self.obj.Label}: {len(self.obj.Shape.Faces)} faces, builds")
        report = None if in_error(self.obj) else placement.span_report(self.obj)
        if report is None:
            self.span.setText("")
        else:
            text, fits = report
            self.span.setStyleSheet("color: #206020;" if fits else "color: #b06000;")
            self.span.setText(text)
        if self.profile is not None:
            self.profile.show_state()
        self.overlay.refresh()

    def span_text(self):
        return self.span.text()

    def status_text(self):
        return self.message.text()

    # --- task dialog protocol ---------------------------------------------------------------

    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)

    def accept(self):
        self.doc.commitTransaction()
        self._close()
        return True

    def reject(self):
        self.doc.abortTransaction()  # restores every property the panel changed
        self.doc.recompute()
        self._close()
        return True

    def _close(self):
        self.overlay.remove()
        gui_doc = FreeCADGui.getDocument(self.doc.Name)
        if gui_doc is not None and gui_doc.getInEdit() is not None:
            gui_doc.resetEdit()  # unsetEdit closes the dialog
        else:
            FreeCADGui.Control.closeDialog()
        FreeCAD.Console.PrintLog(f"{self.obj.Label}: task panel closed\n")
