"""CardPanel: the card's task panel (double-click the card): fold angle, animation, paper and size,
validity check with clickable findings, cutting sheets.

The fold-angle slider recomputes at every step (tens of ms per angle), so the 3D view follows the
hand. Play runs PopUp_Animate's fold player (gui/fold_player.py) at the chosen speed; it ends on
the angle it started from. Check validity runs popupwb.validity.run_check and lists the findings;
clicking one selects the patches it is about (or the mechanism a design error names). Make sheets
is the PopUp_CuttingSheet command's action (gui/add_cutting_sheet.py).

Undo: the panel's changes are one transaction, committed when it closes. Make sheets is an undo
step of its own, as the command is: the panel commits what it did so far, adds the sheets, and
opens a new transaction for the rest. Close keeps every change, the fold angle too (the angle is
where the maker left it to look at; Ctrl+Z takes the session back).
"""

import FreeCADGui
from PySide import QtCore, QtGui

from popupwb.model import card_scaffold
from popupwb.gui import fold_player
from popupwb.gui.add_cutting_sheet import add_cutting_sheet
from popupwb.taskpanels.mechanism_panel import in_error

SPEEDS = (("Slow", 1.5), ("Normal", 3.0), ("Fast", 6.0))  # degrees per frame of PopUp_Animate
DEFAULT_SPEED = "Normal"
LIMIT = 1.0e5  # mm: wide enough for any card, the card judges the real range
STATUS_MS = 100  # how often the panel follows the animation and the card's state

last_panel = None  # the panel opened last (scripts and the GUI tests drive it)


def finish_panel_of(card):
    """Ends the session of the open panel of `card`, if any (the view provider's unsetEdit)."""
    if last_panel is not None and last_panel.card is card:
        last_panel.finish()


class CardPanel:
    """Task dialog of one PopUpCard (FreeCADGui.Control.showDialog(CardPanel(card)))."""

    def __init__(self, card):
        global last_panel
        last_panel = self
        self.card = card
        self.doc = card.Document
        self.player = None
        self.finished = False
        self.findings = []  # [(diagnostic dict, [(object name, face index or None)])]
        self.doc.openTransaction(f"Edit {card.Label}")

        self.form = QtGui.QWidget()
        self.form.setWindowTitle(card.Label)
        self.form.setObjectName("PopUpCardPanel")
        layout = QtGui.QVBoxLayout(self.form)
        layout.addWidget(self._fold_group())
        layout.addWidget(self._paper_group())
        layout.addWidget(self._check_group())
        layout.addWidget(self._sheets_group())

        self.timer = QtCore.QTimer(self.form)  # dies with the panel
        self.timer.setInterval(STATUS_MS)
        self.timer.timeout.connect(self._follow)
        self.timer.start()
        self._follow()

    # --- widgets ----------------------------------------------------------------------------

    def _fold_group(self):
        group = QtGui.QGroupBox("Fold angle")
        box = QtGui.QVBoxLayout(group)
        row = QtGui.QHBoxLayout()
        self.slider = QtGui.QSlider(QtCore.Qt.Horizontal)
        self.slider.setObjectName("FoldAngleSlider")
        self.slider.setRange(0, 180)
        self.slider.setValue(int(round(self.card.FoldAngle.Value)))
        self.slider.setToolTip("Opening angle of the card: 0° closed, 180° flat open")
        self.slider.valueChanged.connect(self.set_fold_angle)
        self.angle_label = QtGui.QLabel()
        self.angle_label.setMinimumWidth(36)
        self.angle_label.setAlignment(QtCore.Qt.AlignRight | QtCore.Qt.AlignVCenter)
        row.addWidget(self.slider, 1)
        row.addWidget(self.angle_label)
        box.addLayout(row)

        row = QtGui.QHBoxLayout()
        self.play_button = QtGui.QPushButton("Play")
        self.play_button.setObjectName("PlayButton")
        self.play_button.setToolTip("Close the card and open it again (press again to stop)")
        self.play_button.clicked.connect(self.toggle_play)
        self.speed = QtGui.QComboBox()
        self.speed.setObjectName("Speed")
        self.speed.addItems([name for name, _ in SPEEDS])
        self.speed.setCurrentIndex([name for name, _ in SPEEDS].index(DEFAULT_SPEED))
        self.speed.setToolTip("Animation speed (takes effect at the next Play)")
        row.addWidget(self.play_button)
        row.addStretch(1)
        row.addWidget(QtGui.QLabel("Speed"))
        row.addWidget(self.speed)
        box.addLayout(row)
        return group

    def _paper_group(self):
        from popupwb.features.card_feature import PRESET_NAMES

        group = QtGui.QGroupBox("Paper")
        form = QtGui.QFormLayout(group)
        self.preset = QtGui.QComboBox()
        self.preset.setObjectName("Preset")
        self.preset.addItems(PRESET_NAMES)
        self.preset.setCurrentIndex(max(self.preset.findText(self.card.Preset), 0))
        self.preset.setToolTip("Paper folded in half across its long side; Custom keeps the size")
        self.preset.currentIndexChanged.connect(self.on_preset)
        form.addRow("Preset", self.preset)
        self.size_fields = {}
        for name, tip in (
            ("Width", "Length of the central fold (a size of one's own makes the preset Custom)"),
            ("Depth", "Depth of each page, from the fold"),
        ):
            field = QtGui.QDoubleSpinBox()
            field.setObjectName(name)
            field.setDecimals(2)
            field.setRange(-LIMIT, LIMIT)  # the card judges the value and names its range
            field.setSuffix(" mm")
            field.setKeyboardTracking(False)  # apply typed numbers on Enter or focus out
            field.setToolTip(tip)
            field.valueChanged.connect(lambda value, name=name: self.set_size(name, value))
            self.size_fields[name] = field
            form.addRow(name, field)
        return group

    def _check_group(self):
        group = QtGui.QGroupBox("Validity")
        box = QtGui.QVBoxLayout(group)
        self.check_button = QtGui.QPushButton("Check validity")
        self.check_button.setObjectName("CheckButton")
        self.check_button.setToolTip(
            "Fold the card from open to closed: foldable, stable, no intersections, enclosed"
        )
        self.check_button.clicked.connect(self.check)
        self.verdict = QtGui.QLabel()
        self.verdict.setWordWrap(True)
        self.findings_list = QtGui.QListWidget()
        self.findings_list.setObjectName("Findings")
        self.findings_list.setWordWrap(True)
        self.findings_list.setToolTip("Click a finding to select the patches it is about")
        self.findings_list.setMinimumHeight(160)
        self.findings_list.currentRowChanged.connect(self.select_finding)
        box.addWidget(self.check_button)
        box.addWidget(self.verdict)
        box.addWidget(self.findings_list)
        return group

    def _sheets_group(self):
        group = QtGui.QGroupBox("Sheets")
        box = QtGui.QVBoxLayout(group)
        self.sheets_button = QtGui.QPushButton("Make sheets")
        self.sheets_button.setObjectName("SheetsButton")
        self.sheets_button.setToolTip(
            "Lay the card out flat on sheets of paper (PopUp_CuttingSheet)"
        )
        self.sheets_button.clicked.connect(self.make_sheets)
        self.message = QtGui.QLabel()
        self.message.setObjectName("Message")
        self.message.setWordWrap(True)
        self.message.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)
        box.addWidget(self.sheets_button)
        box.addWidget(self.message)
        return group

    # --- fold angle and animation -----------------------------------------------------------

    def set_fold_angle(self, degrees):
        """What moving the slider to `degrees` does: the card folds there at once."""
        if self.playing():
            return  # the player drives the angle; the slider only follows it
        self.card.FoldAngle = float(degrees)
        self.doc.recompute()
        self._follow()

    def playing(self):
        return self.player is not None and self.player.running()

    def toggle_play(self):
        """Play, or Stop when playing (the card returns to the angle it started from)."""
        if self.playing():
            fold_player.stop()
        else:
            step = dict(SPEEDS)[self.speed.currentText()]
            self.player = fold_player.play(self.card, step=step)
        self._follow()

    def stop_play(self):
        if self.playing():
            fold_player.stop()

    # --- paper ------------------------------------------------------------------------------

    def on_preset(self, index):
        if index < 0:
            return
        name = self.preset.itemText(index)
        if self.card.Preset != name:
            self.card.Preset = name
            self.doc.recompute()
        self._follow()

    def set_size(self, name, value):
        """What typing `value` (mm) into the Width or Depth field does."""
        if abs(getattr(self.card, name).Value - value) > 1e-9:
            setattr(self.card, name, value)
            self.doc.recompute()
        self._follow()

    # --- validity ---------------------------------------------------------------------------

    def check(self):
        """Runs the validity check and lists its findings; returns the report (None when the user
        cancelled it)."""
        from popupwb.validity.check import run_check
        from popupwb.validity.report_text import format_diagnostic, format_report

        self.stop_play()
        report = run_check(self.card)
        if report is None:
            self.verdict.setText("Check cancelled: the last verdict stands")
            return None
        built = card_scaffold.for_card(self.card)
        self.findings = [(d, self._targets(d, built)) for d in report["diagnostics"]]
        self.findings_list.blockSignals(True)
        self.findings_list.clear()
        for diagnostic, targets in self.findings:
            item = QtGui.QListWidgetItem(format_diagnostic(diagnostic))
            if not targets:
                item.setToolTip("Nothing to select: the finding is about the whole card")
            self.findings_list.addItem(item)
        self.findings_list.setCurrentRow(-1)
        self.findings_list.blockSignals(False)
        summary = format_report(report).splitlines()[0]
        count = len(report["diagnostics"])
        self.verdict.setText(f"{summary} ({count} finding{'' if count == 1 else 's'})")
        self.verdict.setStyleSheet("color: #206020;" if report["valid"] else "color: #b00000;")
        return report

    def _targets(self, diagnostic, built):
        """[(object name, face index or None)] of what a finding is about: the face of each patch
        it names in the object showing it, or the mechanism a design error names."""
        targets = []
        for patch_id in diagnostic.get("patches") or []:
            owner = built.patch_owner(int(patch_id))
            if owner is not None:
                targets.append((owner, _face_index(self.doc.getObject(owner), built, patch_id)))
        if not targets and diagnostic.get("code") == "design_error":
            for name, message in built.errors.items():
                if message == diagnostic.get("message"):
                    targets.append((name, None))
        return targets

    def select_finding(self, row):
        """What clicking finding `row` does: selects its patches (faces) or its mechanism."""
        FreeCADGui.Selection.clearSelection()
        if not 0 <= row < len(self.findings):
            return []
        selected = []
        for name, face in self.findings[row][1]:
            obj = self.doc.getObject(name)
            if obj is None:
                continue
            if face is None:
                FreeCADGui.Selection.addSelection(obj)
            else:
                FreeCADGui.Selection.addSelection(obj, f"Face{face}")
            selected.append(name)
        return selected

    # --- sheets -----------------------------------------------------------------------------

    def make_sheets(self):
        """PopUp_CuttingSheet on this card, an undo step of its own; returns the CuttingSheet."""
        self.stop_play()
        self.doc.commitTransaction()
        try:
            sheet = add_cutting_sheet(self.card)
        finally:
            self.doc.openTransaction(f"Edit {self.card.Label}")
        if sheet is None:
            self.message.setText("No sheets made: see the report view")
        elif in_error(sheet):
            self.message.setText(sheet.getStatusString())
        else:
            self.message.setText(
                f"{sheet.Label}: {sheet.SheetCount} sheet(s), {sheet.PieceCount} pieces, "
                f"{sheet.TabCount} tabs"
            )
        self._follow()
        return sheet

    # --- state ------------------------------------------------------------------------------

    def _follow(self):
        """Shows the card's angle, size and error, and the play state."""
        try:
            angle = self.card.FoldAngle.Value
        except (ReferenceError, RuntimeError):  # the card was deleted under the panel
            self.timer.stop()
            return
        self.slider.blockSignals(True)
        self.slider.setValue(int(round(angle)))
        self.slider.blockSignals(False)
        self.angle_label.setText(f"{angle:.0f}°")
        self.play_button.setText("Stop" if self.playing() else "Play")
        self.slider.setEnabled(not self.playing())
        for name, field in self.size_fields.items():
            if not field.hasFocus():  # never overwrite what the maker is typing
                field.blockSignals(True)
                field.setValue(getattr(self.card, name).Value)
                field.blockSignals(False)
        self.preset.blockSignals(True)
        self.preset.setCurrentIndex(max(self.preset.findText(self.card.Preset), 0))
        self.preset.blockSignals(False)
        if in_error(self.card):
            self.message.setStyleSheet("color: #b00000;")
            self.message.setText(self.card.getStatusString())
        elif self.message.styleSheet():
            self.message.setStyleSheet("")
            self.message.setText("")

    def status_text(self):
        return self.message.text()

    # --- task dialog protocol ---------------------------------------------------------------

    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Close)

    def accept(self):
        return self._close()

    def reject(self):
        return self._close()

    def finish(self):
        """Ends the session once: stops the animation and the timer, commits the transaction
        (Close keeps the session's changes, fold angle included). Also run when FreeCAD ends the
        edit itself (unsetEdit: another double-click, the document closing)."""
        if self.finished:
            return
        self.finished = True
        self.timer.stop()
        try:
            self.stop_play()
            self.doc.commitTransaction()
        except (ReferenceError, RuntimeError):  # the card or its document is gone
            pass

    def _close(self):
        self.finish()
        gui_doc = FreeCADGui.getDocument(self.doc.Name)
        if gui_doc is not None and gui_doc.getInEdit() is not None:
            gui_doc.resetEdit()  # unsetEdit closes the dialog
        else:
            FreeCADGui.Control.closeDialog()
        return True


def _face_index(obj, built, patch_id):
    """1-based index of patch `patch_id`'s face in `obj`'s shape (its patches as faces in patch
    order), None when the shape is not one face per patch (thickened into solids)."""
    faces = len(obj.Shape.Faces) if obj is not None and not obj.Shape.isNull() else 0
    own = built.patches.get(obj.Name, []) if obj is not None else []
    if patch_id in own and faces == len(own):
        return own.index(patch_id) + 1
    if card_scaffold.is_card(obj) and faces == len(built.scaffold.patches):
        return int(patch_id) + 1  # the card showing every patch
    return None
