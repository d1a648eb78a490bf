"""ProfilePicker: the group of widgets that puts a Sketcher sketch on a principal part of a
mechanism as its profile (docs/DESIGN.md, Profiles): a Sketch combo (the document's sketches, or
none), a Part combo (the parts the mechanism has now: riser, tread, TG, FL...) and a Mode combo
(Clip or Scale), with a line under them saying what the outline covers or why it is refused.

The picker only changes properties, through editing.set_profile_sketch, which refuses a sketch
without a closed outline in one line naming it; the panel that holds it (MechanismPanel,
ProfilePanel) owns the undo transaction and the recompute.
"""

import FreeCAD
from PySide import QtCore, QtGui

from popupwb.model import profile_storage
from popupwb.profiles import editing

NO_SKETCH = "(none)"
ERROR_STYLE = "color: #b00000;"
OK_STYLE = "color: #206020;"


class ProfilePicker:
    """Widgets choosing obj's ProfileSketch, ProfilePart and ProfileMode. `changed()` is called
    after every change the picker applied (the holder recomputes and shows the result)."""

    def __init__(self, obj, sketch=None, changed=None):
        self.obj = obj
        self.changed = changed or (lambda: None)
        self.error = None  # the last refusal, one line
        self.group = QtGui.QGroupBox("Profile")
        self.group.setObjectName("ProfilePicker")
        form = QtGui.QFormLayout(self.group)

        self.sketch = QtGui.QComboBox()
        self.sketch.setObjectName("ProfileSketch")
        self.sketch.setToolTip(
            "A Sketcher sketch whose closed outline the part takes: its x runs along the part's "
            "base fold from the fold's middle, its y away from the fold (mm)"
        )
        self.sketch.addItem(NO_SKETCH, "")
        for candidate in editing.sketches_of(obj.Document):
            self.sketch.addItem(candidate.Label, candidate.Name)
        chosen = sketch or getattr(obj, "ProfileSketch", None)
        if chosen is not None:
            self.sketch.setCurrentIndex(max(self.sketch.findData(chosen.Name), 0))

        self.part = QtGui.QComboBox()
        self.part.setObjectName("ProfilePart")
        self.part.setToolTip("The principal part of the mechanism the outline is cut into")
        self.refresh_parts()

        self.mode = QtGui.QComboBox()
        self.mode.setObjectName("ProfileMode")
        self.mode.addItems(profile_storage.MODES)
        self.mode.setCurrentIndex(max(self.mode.findText(obj.ProfileMode), 0))
        self.mode.setToolTip(
            "After a dimension edit: Clip keeps the outline in mm and clips it to the part, "
            "Scale scales it with the part"
        )

        self.message = QtGui.QLabel()
        self.message.setObjectName("ProfileMessage")
        self.message.setWordWrap(True)
        self.message.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)

        form.addRow("Sketch", self.sketch)
        form.addRow("Part", self.part)
        form.addRow("Mode", self.mode)
        form.addRow(self.message)
        self.sketch.currentIndexChanged.connect(lambda *_: self.apply())
        self.part.currentIndexChanged.connect(lambda *_: self.apply())
        self.mode.currentIndexChanged.connect(lambda *_: self.apply())
        self.show_state()

    # --- reading the widgets ----------------------------------------------------------------

    def chosen_sketch(self):
        name = self.sketch.itemData(self.sketch.currentIndex())
        return self.obj.Document.getObject(name) if name else None

    def refresh_parts(self):
        """Fills the Part combo with the mechanism's parts now (they follow its parameters)."""
        try:
            sizes = editing.profile_parts(self.obj)
        except ValueError:
            sizes = {}
        current = self.part.currentText() or getattr(self.obj, "ProfilePart", "")
        blocked = self.part.blockSignals(True)
        self.part.clear()
        for name, (w, h) in sorted(sizes.items()):
            self.part.addItem(name, name)
            self.part.setItemData(
                self.part.count() - 1, f"{w:.1f} × {h:.1f} mm", QtCore.Qt.ToolTipRole
            )
        index = self.part.findText(current)
        if index < 0 and sizes:
            index = self._largest(sizes)
        self.part.setCurrentIndex(index)
        self.part.blockSignals(blocked)

    def _largest(self, sizes):
        name = max(sorted(sizes), key=lambda n: sizes[n][0] * sizes[n][1])
        return self.part.findText(name)

    # --- applying ---------------------------------------------------------------------------

    def choose(self, sketch, part=None, mode=None):
        """What picking `sketch` (None: no sketch), `part` and `mode` (None: as they are) in the
        combos does (scripts and the GUI tests); returns the refusal or None."""
        blocked = [w.blockSignals(True) for w in (self.sketch, self.part, self.mode)]
        try:
            self.sketch.setCurrentIndex(self.sketch.findData(sketch.Name if sketch else ""))
            if part is not None:
                self.part.setCurrentIndex(self.part.findText(part))
            if mode is not None:
                self.mode.setCurrentIndex(self.mode.findText(mode))
        finally:
            for widget, was in zip((self.sketch, self.part, self.mode), blocked):
                widget.blockSignals(was)
        return self.apply()

    def apply(self):
        """Sets the profile properties from the widgets; a refusal (open wire, unknown part) is
        shown in one line and printed to the report view, and nothing is changed. Returns the
        refusal or None."""
        sketch = self.chosen_sketch()
        self.error = None
        try:
            if sketch is None:
                if getattr(self.obj, "ProfileSketch", None) is not None:
                    editing.clear_profile_sketch(self.obj)
            else:
                editing.set_profile_sketch(
                    self.obj, sketch, self.part.currentText(), self.mode.currentText()
                )
        except ValueError as error:
            self.error = str(error)
            FreeCAD.Console.PrintError(f"{self.error}\n")
        self.changed()
        self.show_state()
        return self.error

    def show_state(self):
        """The refusal in red, else what the outline covers."""
        if self.error:
            self.message.setStyleSheet(ERROR_STYLE)
            self.message.setText(self.error)
            return
        sketch = getattr(self.obj, "ProfileSketch", None)
        if sketch is None:
            self.message.setStyleSheet("")
            self.message.setText("No sketch: the parts keep the outline their mechanism gives.")
            return
        try:
            outer, holes = profile_storage.sketch_loops(self.obj, sketch)
        except ValueError as error:  # the sketch was edited since it was picked
            self.message.setStyleSheet(ERROR_STYLE)
            self.message.setText(str(error))
            return
        self.message.setStyleSheet(OK_STYLE)
        self.message.setText(
            f"{sketch.Label} on {self.obj.ProfilePart} ({self.obj.ProfileMode}): outline "
            f"{editing.outline_area(outer, holes):.1f} mm², {len(holes)} hole(s)"
        )

    def text(self):
        return self.message.text()
