"""FromModelPanel: PopUp_FromModel's task panel. The maker sets the alignment (up axis, facing),
the largest number of mechanisms, the detail level and the seed, presses Fit, looks at the fitted
prisms drawn over the model (taskpanels/primitive_overlay.py) and accepts (OK builds the card) or
fits again with other settings.

Fit runs popupcore.fit_design in progress.run's worker thread with a Cancel button (the core stops
at its next checkpoint). OK on a panel never fitted fits first. The card is built by
popupwb.fitting.design_from_fit, as `popup fit` builds it, in one undo step, and checked.

Opened on a model file (`model` read by popupcore.load_model, `source_file` its path), the card
keeps the file as its SourceFile, as `popup fit` does, so its texture and colours print as the
cutting sheets' artwork.
"""

import FreeCAD
import FreeCADGui
from PySide import QtGui

from popupwb.fitting import fit_run
from popupwb.taskpanels.primitive_overlay import PrimitiveOverlay

AUTOMATIC = "Automatic"
AXES = {
    "+X": (1.0, 0.0, 0.0),
    "-X": (-1.0, 0.0, 0.0),
    "+Y": (0.0, 1.0, 0.0),
    "-Y": (0.0, -1.0, 0.0),
    "+Z": (0.0, 0.0, 1.0),
    "-Z": (0.0, 0.0, -1.0),
}
MAX_SEED = 2**31 - 1

last_panel = None  # the panel opened last (scripts and the GUI tests drive it)


class FromModelPanel:
    def __init__(self, obj, card_size=None, model=None, source_file=None):
        global last_panel
        last_panel = self
        self.obj = obj
        self.doc = obj.Document
        self.card_size = card_size
        self.overlay = PrimitiveOverlay(self.doc)
        self.model = None  # the cleaned ModelMesh, made at the first fit
        self.repairs = {}
        self.source_file = source_file
        if model is not None:
            self.model, self.repairs = fit_run.clean_model(model)
        self.result = None
        self.design = None  # the FittedDesign OK built

        self.form = QtGui.QWidget()
        self.form.setWindowTitle(f"Pop-up from {obj.Label}")
        self.form.setObjectName("PopUpFromModelPanel")
        layout = QtGui.QVBoxLayout(self.form)
        layout.addWidget(self._alignment_group())
        layout.addWidget(self._fit_group())
        self.status = QtGui.QLabel("Press Fit to see the prisms fitted to the model.")
        self.status.setObjectName("FitStatus")
        self.status.setWordWrap(True)
        layout.addWidget(self.status)

    # --- widgets ----------------------------------------------------------------------------

    def _axis_box(self, name, tip, default=AUTOMATIC):
        box = QtGui.QComboBox()
        box.setObjectName(name)
        box.addItems([AUTOMATIC] + list(AXES))
        box.setCurrentIndex(box.findText(default))
        box.setToolTip(tip)
        return box

    def _alignment_group(self):
        group = QtGui.QGroupBox("Alignment")
        form = QtGui.QFormLayout(group)
        self.up = self._axis_box(
            "UpAxis", "Model axis that becomes up on the open card (Automatic: from its normals)"
        )
        self.facing = self._axis_box(
            "FacingAxis", "Model axis that faces the viewer of the open card (Automatic: PCA)"
        )
        form.addRow("Up", self.up)
        form.addRow("Facing", self.facing)
        return group

    def _fit_group(self):
        group = QtGui.QGroupBox("Fit")
        form = QtGui.QFormLayout(group)
        self.max_mechanisms = QtGui.QSpinBox()
        self.max_mechanisms.setObjectName("MaxMechanisms")
        self.max_mechanisms.setRange(1, fit_run.MAX_MECHANISMS)
        self.max_mechanisms.setValue(8)
        self.detail = QtGui.QDoubleSpinBox()
        self.detail.setObjectName("Detail")
        self.detail.setRange(0.0, 1.0)
        self.detail.setSingleStep(0.1)
        self.detail.setValue(fit_run.DEFAULT_DETAIL)
        self.detail.setToolTip("0 coarse (few large prisms) to 1 fine (smaller prisms too)")
        self.seed = QtGui.QSpinBox()
        self.seed.setObjectName("Seed")
        self.seed.setRange(0, MAX_SEED)
        self.seed.setValue(1)
        self.seed.setToolTip("Same seed, same design; another seed tries other samples")
        self.fit_button = QtGui.QPushButton("Fit")
        self.fit_button.setObjectName("FitButton")
        self.fit_button.clicked.connect(self.fit)
        form.addRow("Maximum mechanisms", self.max_mechanisms)
        form.addRow("Detail", self.detail)
        form.addRow("Seed", self.seed)
        form.addRow(self.fit_button)
        return group

    # --- fitting ----------------------------------------------------------------------------

    def options(self):
        """popupcore.FitOptions from the widgets."""
        up, facing = self.up.currentText(), self.facing.currentText()
        return fit_run.fit_options(
            max_mechanisms=self.max_mechanisms.value(),
            seed=self.seed.value(),
            up=AXES.get(up),
            facing=AXES.get(facing),
            detail=self.detail.value(),
            card_size=self.card_size,
        )

    def fit(self):
        """Fits with the current settings and draws the prisms; returns the FitResult or None
        (cancelled, or no design: the status line says why)."""
        from popupwb import progress
        from popupwb.core import popupcore
        from popupwb.fitting.model_source import model_of_object

        self.result = None
        self.overlay.remove()
        label = f"{self.obj.Label}: fitting a pop-up"
        try:
            options = self.options()
            if self.model is None:
                self.model, self.repairs = fit_run.clean_model(model_of_object(self.obj))
            self.result = progress.run(
                label, popupcore.fit_design, self.model, options, cancel=progress.CANCEL_FLAG
            )
        except progress.Cancelled:
            self._say(f"{label}: cancelled")
            return None
        except ValueError as error:  # DesignError: no design, or an unusable model or option
            self._say(f"{label}: {error}", error=True)
            return None
        self.overlay.show(self.result.primitives, self.result.model_to_card)
        self._say(self.summary())
        return self.result

    def summary(self):
        result = self.result
        kinds = ", ".join(f"{m.name} {m.type.replace('_', ' ')}" for m in result.mechanisms)
        verdict = "valid" if result.valid else "NOT valid"
        return (
            f"{len(result.primitives)} prism(s), {len(result.mechanisms)} mechanism(s)"
            f"{': ' + kinds if kinds else ''}; coverage {result.coverage:.0%}; {verdict}. "
            "OK builds the card."
        )

    def _say(self, text, error=False):
        self.status.setText(text)
        (FreeCAD.Console.PrintError if error else FreeCAD.Console.PrintMessage)(text + "\n")

    # --- task dialog protocol ---------------------------------------------------------------

    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)

    def accept(self):
        if self.result is None and self.fit() is None:
            return False  # keep the panel open: the status line says what went wrong
        if not self.result.mechanisms:
            self._say(f"{self.obj.Label}: no mechanism was fitted; try a finer detail", True)
            return False
        from popupwb import validity
        from popupwb.fitting.design_from_fit import build_design

        self.doc.openTransaction(f"Pop-up from {self.obj.Label}")
        try:
            self.design = build_design(
                self.doc, self.result, self.model, source_file=self.source_file
            )
        except ValueError as error:
            self.doc.abortTransaction()
            self._say(f"{self.obj.Label}: {error}", error=True)
            return False
        self.doc.commitTransaction()
        validity.run_check(self.design.card)
        self._close()
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(self.design.card)
        return True

    def reject(self):
        self._close()
        return True

    def _close(self):
        self.overlay.remove()
        FreeCADGui.Control.closeDialog()
