"""FromAnimationPanel: PopUp_FromAnimation's task panel. The maker picks the frames (first: the
closed card, last: the open card), the viewpoint (the file's direction looked along and the one
that becomes up), the pruning fraction τp, the motion and depth weights of eq 6.5, the annealing
iterations and the seed, which chains to animate (a check box per chain found, filled when the
animation is read: Find chains or the first Design; an unchecked chain is held still), presses
Design, looks at the target paths against the mechanisms' paths
(drawn in the panel, the paths.png of `popup animate`) and accepts (OK builds the card) or designs
again with other settings.

Design runs popupcore.design_motion in progress.run's worker thread: the progress bar follows the
core's MotionProgress and Cancel stops the annealing at its next checkpoint. The card is built by
popupwb.motion.design_from_motion, as `popup animate` builds it, in one undo step, and checked.
"""

import io
import os

import FreeCAD
from PySide import QtCore, QtGui

from popupwb import option_fields
from popupwb.motion import motion_run
from popupwb.taskpanels.fitted_image import FittedImage
from popupwb.taskpanels.long_job_panel import AXES, LongJobPanel, axis_box, axis_named, form_group
from popupwb.taskpanels.long_job_panel import option_real_box, option_spin_box, push_button

CHAIN_ROWS_SHOWN = 5  # the chain list's height in rows: it scrolls beyond, the panel stays short

last_panel = None  # the panel opened last (scripts and the GUI tests drive it)


class FromAnimationPanel(LongJobPanel):
    def __init__(self, path, doc, card_size=None):
        global last_panel
        last_panel = self
        super().__init__(doc)
        self.path = path
        self.card_size = card_size
        self.animation = None  # the popupcore.Animation, read at the first design
        self.plot_png = None  # bytes of the paths plot of the last design
        self._make_form(
            f"Pop-up from {os.path.basename(path)}",
            "PopUpFromAnimationPanel",
            [self._animation_group(), self._chains_group(), self._design_group()],
            "DesignStatus",
            "Press Design to map the character's limbs to mechanisms.",
        )
        self.plot = FittedImage(
            "PathsPlot",
            "Solid: each end effector's target path on the card; dashed: its mechanism's point",
        )
        self.layout.addWidget(self.plot)
        self.movie = FittedImage(
            "MotionMovie",
            "The card opening as it will be printed, beside the character at the same moment",
        )
        self.layout.insertWidget(self.layout.indexOf(self.plot), self.movie)

    # --- widgets ----------------------------------------------------------------------------

    def _animation_group(self):
        from popupwb.core import popupcore

        core = option_fields.fields("MotionOptions")  # ranges, defaults and docs: the core's
        self.file_label = QtGui.QLabel(os.path.basename(self.path))
        self.file_label.setToolTip(self.path)
        # Up to the animation's own frames once it is read (_load).
        self.first_frame = option_spin_box("FirstFrame", core["first_frame"])
        self.last_frame = option_spin_box("LastFrame", core["last_frame"], special="last")
        default = popupcore.MotionView()
        self.view = axis_box("ViewAxis", core["view"].doc, axis_named(default.view))
        self.up = axis_box("UpAxis", core["up"].doc, axis_named(default.up))
        return form_group(
            "Animation",
            [
                ("File", self.file_label),
                ("First frame", self.first_frame),
                ("Last frame", self.last_frame),
                ("View along", self.view),
                ("Up", self.up),
            ],
        )

    def _chains_group(self):
        """The chains found, one checkable row each (all checked: all animate); narrow: a list
        that scrolls, as wide as the panel lets it be."""
        self.chain_list = QtGui.QListWidget()
        self.chain_list.setObjectName("ChainList")
        self.chain_list.setToolTip(
            "Checked chains are animated; an unchecked chain is held still (its floating layer or "
            "its part printed on the page)"
        )
        rows = CHAIN_ROWS_SHOWN * self.chain_list.fontMetrics().height() + 8
        self.chain_list.setMaximumHeight(rows)
        self.chain_list.setSizePolicy(QtGui.QSizePolicy.Ignored, QtGui.QSizePolicy.Preferred)
        self.find_chains_button = push_button("Find chains", "FindChainsButton", self.find_chains)
        return form_group("Chains to animate", [self.chain_list, self.find_chains_button])

    def _design_group(self):
        core = option_fields.fields("MotionOptions")
        self.prune = option_real_box("Pruning", core["prune_fraction"], 0.01)
        self.motion_weight = option_real_box("MotionWeight", core["motion_weight"], 5.0)
        self.depth_weight = option_real_box("DepthWeight", core["depth_weight"], 5.0)
        self.iterations = option_spin_box(
            "Iterations", core["iterations"], low=motion_run.MIN_ITERATIONS
        )
        self.seed = option_spin_box("Seed", core["seed"])
        self.design_button = push_button("Design", "DesignButton", self.run_design)
        return form_group(
            "Design",
            [
                ("Pruning τp", self.prune),
                ("Motion weight", self.motion_weight),
                ("Depth weight", self.depth_weight),
                ("Iterations", self.iterations),
                ("Seed", self.seed),
                self.design_button,
            ],
        )

    # --- designing --------------------------------------------------------------------------

    def options(self, with_chains=True):
        """popupcore.MotionOptions from the widgets; ValueError when chains are listed and none
        is checked. Without `with_chains`, every chain animates (the list is not read)."""
        last = self.last_frame.value()
        return motion_run.motion_options(
            seed=self.seed.value(),
            iterations=self.iterations.value(),
            first_frame=self.first_frame.value(),
            last_frame=None if last < 0 else last,
            view=AXES[self.view.currentText()],
            up=AXES[self.up.currentText()],
            card_size=self.card_size,
            prune_fraction=self.prune.value(),
            motion_weight=self.motion_weight.value(),
            depth_weight=self.depth_weight.value(),
            animate_only=self.chosen_chains() if with_chains else None,
        )

    # --- the chains --------------------------------------------------------------------------

    def chosen_chains(self):
        """The checked chains' names; None when all are checked (or none listed yet): all
        animate. ValueError when none is checked."""
        items = [self.chain_list.item(row) for row in range(self.chain_list.count())]
        checked = [item.data(QtCore.Qt.UserRole) for item in items if _checked(item)]
        if items and not checked:
            raise ValueError("Chains to animate: check at least one chain")
        return None if len(checked) == len(items) else checked

    def find_chains(self):
        """Reads the animation (once) and lists its chains with the current settings; a chain
        listed before keeps its check, a new one is checked. Returns the ChainFound list, or None
        (the status line says why)."""
        from popupwb import progress

        label = f"{os.path.basename(self.path)}: finding the chains"

        def job():
            animation = self._load()
            return progress.run(
                label, motion_run.chains_found, animation, self.options(with_chains=False)
            )

        chains = self._attempt(label, job)
        if chains is not None:
            self._list_chains(chains)
        return chains

    def _list_chains(self, chains):
        unchecked = {
            item.data(QtCore.Qt.UserRole)
            for item in (self.chain_list.item(row) for row in range(self.chain_list.count()))
            if not _checked(item)
        }
        self.chain_list.clear()
        for chain in chains:
            text = chain.name if chain.moving else f"{chain.name} (still)"
            item = QtGui.QListWidgetItem(text)
            item.setData(QtCore.Qt.UserRole, chain.name)
            item.setToolTip(motion_run.chain_line(chain))
            item.setFlags(item.flags() | QtCore.Qt.ItemIsUserCheckable)
            state = QtCore.Qt.Unchecked if chain.name in unchecked else QtCore.Qt.Checked
            item.setCheckState(state)
            self.chain_list.addItem(item)

    def _load(self):
        from popupwb import progress

        if self.animation is None:
            label = f"{os.path.basename(self.path)}: reading"
            self.animation, what = progress.run(label, motion_run.read_animation, self.path)
            self.first_frame.setMaximum(self.animation.frames - 2)
            self.last_frame.setMaximum(self.animation.frames - 1)
            FreeCAD.Console.PrintMessage(what + "\n")
        return self.animation

    def run_design(self):
        """Designs with the current settings and plots the paths; returns the MotionResult or
        None (cancelled, or no design: the status line says why)."""
        from popupwb import progress
        from popupwb.core import popupcore

        self.result = None
        self.plot_png = None
        self.plot.clear()
        self.movie.clear()
        label = f"{os.path.basename(self.path)}: designing an animated pop-up"

        def job():
            animation = self._load()
            # Listed again with the current settings (pruning changes the chains), checks kept.
            chains = progress.run(label, motion_run.chains_found, animation, self.options(False))
            self._list_chains(chains)
            options = self.options()
            meter = popupcore.MotionProgress()
            return self._run_core(
                label,
                popupcore.design_motion,
                animation,
                options,
                progress=meter,
                fraction=lambda: meter.value,
            )

        self.result = self._attempt(label, job)
        if self.result is None:
            return None
        self._show_window(self.result.targets)
        self._show_movie(label)
        self._show_plot()
        self._say(self.summary())
        return self.result

    def _show_window(self, targets):
        """The frames the core chose, in the frame boxes while they are left at their automatic
        values (first 0, last "last"): "auto: 370" and "auto: 431"; the boxes' values stay, so
        the next Design chooses again."""
        chosen = bool(targets.window["chosen"])
        self.first_frame.setSpecialValueText(f"auto: {targets.first_frame}" if chosen else "")
        self.last_frame.setSpecialValueText(f"auto: {targets.last_frame}" if chosen else "last")

    def _show_movie(self, label):
        """motion.gif of `popup animate`, written to a temporary file and played in the panel;
        a design that locks has none (the status line says why the design is not valid)."""
        import tempfile

        from popupwb import progress
        from popupwb.motion.motion_movie import MovieError, write_result_movie

        self.movie.clear()
        path = os.path.join(tempfile.mkdtemp(prefix="popup-motion-"), "motion.gif")
        up = AXES[self.up.currentText()]
        try:
            progress.run(label, write_result_movie, path, self.result, self.animation, up)
        except (MovieError, progress.Cancelled):  # the design stays; only its picture is skipped
            return
        self.movie.set_movie(path)

    def _show_plot(self):
        from popupwb.motion.paths_plot import write_paths_plot

        buffer = io.BytesIO()
        write_paths_plot(
            buffer,
            self.result.chains,
            self.result.card.width,
            self.result.card.depth,
            title=os.path.basename(self.path),
            narrow=True,
        )
        self.plot_png = buffer.getvalue()
        self.plot.set_png(self.plot_png)

    def summary(self):
        result = self.result
        chains = ", ".join(f"{c.name} {c.mapping} ({c.status})" for c in result.chains)
        verdict = "valid" if result.valid else "NOT valid"
        shown = motion_run.frames_shown(result.targets, "First and Last frame")
        return (
            (f"{shown[0].upper()}{shown[1:]}; " if shown else "")
            + f"{len(result.chains)} chain(s) on {len(result.mechanisms)} mechanism(s)"
            f"{': ' + chains if chains else ''}; weighted motion error "
            f"{result.weighted_error:.3f} (no design on this card under "
            f"{result.weighted_floor:.3f}); {verdict}. OK builds the card."
        )

    # --- task dialog protocol ---------------------------------------------------------------

    def accept(self):
        if self.result is None and self.run_design() is None:
            return False  # keep the panel open: the status line says what went wrong
        from popupwb.motion.design_from_motion import build_design

        return self._build_card(
            os.path.basename(self.path),
            lambda: build_design(self.doc, self.result, self.animation, self.path),
        )


def _checked(item):
    return item.checkState() == QtCore.Qt.Checked
