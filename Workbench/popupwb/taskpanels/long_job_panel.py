"""LongJobPanel: what the task panels that run one long core call and then build a card share
(FromModelPanel's fit, FromAnimationPanel's motion design): the form with its status line, the
widgets for axes, whole numbers and reals, the job run in progress.run's worker thread with Cancel
(a cancelled or failed job leaves the reason on the status line, never an exception), and OK's
build of the card in one undo step, checked and selected.

A subclass makes its groups (form_group), runs its job through `_attempt` and builds through `_build_card`;
`_remove_preview` is where it takes its drawing off the 3D view.
"""

import FreeCAD
import FreeCADGui
from PySide import QtGui

AXES = {
    "+X": (1.0, 0.0, 0.0),
    "-X": (-1.0, 0.0, 0.0),
    "+Y": (0.0, 1.0, 0.0),
    "-Y": (0.0, -1.0, 0.0),
    "+Z": (0.0, 0.0, 1.0),
    "-Z": (0.0, 0.0, -1.0),
}
SPIN_BOX_MAX = 2**31 - 1  # a QSpinBox holds a signed 32-bit int


def axis_box(name, tip, default, first=()):
    """A combo box of the six axis directions (after the `first` items), `default` selected."""
    box = QtGui.QComboBox()
    box.setObjectName(name)
    box.addItems(list(first) + list(AXES))
    box.setCurrentIndex(box.findText(default))
    box.setToolTip(tip)
    return box


def axis_named(direction):
    """The AXES name of a direction ("-Z" for (0, 0, -1))."""
    return next(name for name, axis in AXES.items() if axis == tuple(float(v) for v in direction))


def spin_box(name, low, high, value, tip=None, special=None):
    """A whole-number box; `special` is shown instead of its lowest value."""
    box = QtGui.QSpinBox()
    box.setObjectName(name)
    box.setRange(low, high)
    box.setValue(value)
    if tip is not None:
        box.setToolTip(tip)
    if special:
        box.setSpecialValueText(special)
    return box


def option_spin_box(name, field, low=None, special=None):
    """A whole-number box for a core option (popupwb.option_fields): its range (from `low` when
    the panel asks for more), as far as a QSpinBox holds, at its default, its doc as the tip."""
    low = field.min if low is None else low
    high = min(field.max, SPIN_BOX_MAX)
    return spin_box(name, int(low), int(high), int(field.default), _tip(field.doc), special)


def option_real_box(name, field, step, decimals=3):
    """A real-number box for a core option: its range, at its default, its doc as the tip."""
    return real_box(
        name, field.min, field.max, field.default, step, _tip(field.doc), decimals=decimals
    )


def _tip(doc):
    return doc[:1].upper() + doc[1:]


def real_box(name, low, high, value, step, tip, decimals=3):
    box = QtGui.QDoubleSpinBox()
    box.setObjectName(name)
    box.setRange(low, high)
    box.setDecimals(decimals)
    box.setSingleStep(step)
    box.setValue(value)
    box.setToolTip(tip)
    return box


def push_button(text, name, slot):
    button = QtGui.QPushButton(text)
    button.setObjectName(name)
    button.clicked.connect(slot)
    return button


# The narrowest a field may get: a spin box's own minimum is the width of its largest value
# (10 digits for the iterations), which pushed the panel past FreeCAD's side pane (about 260 px).
FIELD_MIN_WIDTH_PX = 60


def form_group(title, rows):
    """A group box of rows: (label, widget) pairs, and widgets alone that take the whole row; the
    fields may narrow to FIELD_MIN_WIDTH_PX so the panel fits the side pane."""
    group = QtGui.QGroupBox(title)
    form = QtGui.QFormLayout(group)
    form.setFieldGrowthPolicy(QtGui.QFormLayout.AllNonFixedFieldsGrow)
    for row in rows:
        if isinstance(row, tuple):
            row[1].setMinimumWidth(FIELD_MIN_WIDTH_PX)
            form.addRow(*row)
        else:
            form.addRow(row)
    return group


class LongJobPanel:
    def __init__(self, doc):
        self.doc = doc
        self.result = None  # what the last job returned
        self.design = None  # what OK built

    def _make_form(self, title, name, groups, status_name, hint):
        """The form: the groups one under another, then the status line saying `hint`."""
        self.form = QtGui.QWidget()
        self.form.setWindowTitle(title)
        self.form.setObjectName(name)
        self.layout = QtGui.QVBoxLayout(self.form)
        for group in groups:
            self.layout.addWidget(group)
        self.status = QtGui.QLabel(hint)
        self.status.setObjectName(status_name)
        self.status.setWordWrap(True)
        self.layout.addWidget(self.status)

    def _run_core(self, label, function, *args, **kwargs):
        """function(*args) in progress.run's worker thread, stopped by its Cancel button."""
        from popupwb import progress

        return progress.run(label, function, *args, cancel=progress.CANCEL_FLAG, **kwargs)

    def _attempt(self, label, job):
        """job()'s value, or None when it was cancelled or found no design (the status line then
        says so, prefixed with `label`)."""
        from popupwb import progress

        try:
            return job()
        except progress.Cancelled:
            self._say(f"{label}: cancelled")
            return None
        except ValueError as error:  # DesignError: no design, or an unusable input or option
            self._say(f"{label}: {error}", error=True)
            return None

    def _say(self, text, error=False):
        self.status.setText(text)
        (FreeCAD.Console.PrintError if error else FreeCAD.Console.PrintMessage)(text + "\n")

    def _build_card(self, name, build):
        """OK's build: build() in one undo step named after `name`, the card checked, the panel
        closed and the card selected. False keeps the panel open (the status line says why)."""
        from popupwb.validity.check import run_check

        self.doc.openTransaction(f"Pop-up from {name}")
        try:
            self.design = build()
        except ValueError as error:
            self.doc.abortTransaction()
            self._say(f"{name}: {error}", error=True)
            return False
        self.doc.commitTransaction()
        run_check(self.design.card)
        self._close()
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(self.design.card)
        return True

    def _remove_preview(self):
        """Takes the panel's drawing off the 3D view; a panel that draws there overrides it."""

    # --- task dialog protocol ---------------------------------------------------------------

    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)

    def reject(self):
        self._close()
        return True

    def _close(self):
        self._remove_preview()
        FreeCADGui.Control.closeDialog()
