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

from popupwb import option_fields
from popupwb.fitting import fit_run
from popupwb.taskpanels.long_job_panel import AXES, LongJobPanel, axis_box, form_group
from popupwb.taskpanels.long_job_panel import option_spin_box, push_button, real_box
from popupwb.taskpanels.primitive_overlay import PrimitiveOverlay

AUTOMATIC = "Automatic"

last_panel = None  # the panel opened last (scripts and the GUI tests drive it)


class FromModelPanel(LongJobPanel):
    def __init__(self, obj, card_size=None, model=None, source_file=None):
        global last_panel
        last_panel = self
        super().__init__(obj.Document)
        self.obj = obj
        self.card_size = card_size
        self.overlay = PrimitiveOverlay(self.doc)
        self.model = None  # the cleaned ModelMesh, made at the first fit
        self.repairs = {}
        self.source_file = source_file
        if model is not None:
            self.model, self.repairs = fit_run.clean_model(model)
        self._make_form(
            f"Pop-up from {obj.Label}",
            "PopUpFromModelPanel",
            [self._alignment_group(), self._fit_group()],
            "FitStatus",
            "Press Fit to see the prisms fitted to the model.",
        )

    # --- widgets ----------------------------------------------------------------------------

    def _axis_box(self, name, tip):
        return axis_box(name, tip, AUTOMATIC, first=[AUTOMATIC])

    def _alignment_group(self):
        core = option_fields.fields("FitOptions")  # the docs: the core's (Automatic: unset)
        self.up = self._axis_box("UpAxis", core["up"].doc)
        self.facing = self._axis_box("FacingAxis", core["facing"].doc)
        return form_group("Alignment", [("Up", self.up), ("Facing", self.facing)])

    def _fit_group(self):
        core = option_fields.fields("FitOptions")  # ranges, defaults and docs: the core's
        self.max_mechanisms = option_spin_box("MaxMechanisms", core["max_mechanisms"])
        self.detail = real_box(
            "Detail",
            0.0,
            1.0,
            fit_run.DEFAULT_DETAIL,
            0.1,
            "0 coarse (few large prisms) to 1 fine (smaller prisms too)",
            decimals=2,
        )
        self.seed = option_spin_box("Seed", core["seed"])
        self.fit_button = push_button("Fit", "FitButton", self.fit)
        return form_group(
            "Fit",
            [
                ("Maximum mechanisms", self.max_mechanisms),
                ("Detail", self.detail),
                ("Seed", self.seed),
                self.fit_button,
            ],
        )

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
        from popupwb.core import popupcore
        from popupwb.model.model_source import model_of_object

        self.result = None
        self.overlay.remove()
        label = f"{self.obj.Label}: fitting a pop-up"

        def job():
            options = self.options()
            if self.model is None:
                self.model, self.repairs = fit_run.clean_model(model_of_object(self.obj))
            return self._run_core(label, popupcore.fit_design, self.model, options)

        self.result = self._attempt(label, job)
        if self.result is None:
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

    # --- task dialog protocol ---------------------------------------------------------------

    def accept(self):
        if self.result is None and self.fit() is None:
            return False  # keep the panel open: the status line says what went wrong
        if not self.result.mechanisms:
            self._say(f"{self.obj.Label}: no mechanism was fitted; try a finer detail", True)
            return False
        from popupwb.fitting.design_from_fit import build_design

        return self._build_card(
            self.obj.Label,
            lambda: build_design(self.doc, self.result, self.model, source_file=self.source_file),
        )

    def _remove_preview(self):
        self.overlay.remove()
