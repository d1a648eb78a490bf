#!/usr/bin/python3
"""GUI test of PopUp_FromAnimation in the real FreeCAD GUI under Xvfb (tests/gui/gui_harness.py):
the panel opens on a hand-written BVH of a waving figure (tests/python/bvh_samples.py), the
settings go in, Design runs with the progress bar and draws the target paths against the
mechanisms' paths in the panel, a second design is cancelled from the progress dialog, and OK
builds a checked card with one feature per mechanism, linked to the animation; dragging the fold
angle moves the arm. The chain list shows a checked box per chain found once the animation is
read; unchecking the animated chain holds it still at the next design (issue 26 item 1). Screenshots: <build>/sandbox/gui_from_animation/from_animation_panel.png
(the task panel with its plot) and from_animation_card.png (the card at 120°)."""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_harness import SANDBOX, SOURCE_DIR, Checks, run_macro  # noqa: E402

sys.path.insert(0, os.path.join(SOURCE_DIR, "tests", "python"))
import bvh_samples  # noqa: E402

NAME = "gui_from_animation"

BODY = r"""
import time


def chains_test(panel, designed):
    from PySide import QtCore

    items = [panel.chain_list.item(row) for row in range(panel.chain_list.count())]
    chains = {
        "listed": [item.data(QtCore.Qt.UserRole) for item in items],
        "all_checked": all(item.checkState() == QtCore.Qt.Checked for item in items),
        "all_chosen": panel.chosen_chains() is None,
    }
    animated = [c.name for c in designed.chains if c.status == "animated"] if designed else []
    chains["animated_before"] = animated
    # The groups' preferred widths: the chains' must not be the widest (the side pane is narrow).
    from PySide import QtGui

    groups = [panel.layout.itemAt(i).widget() for i in range(panel.layout.count())]
    widths = {g.title(): g.sizeHint().width() for g in groups if isinstance(g, QtGui.QGroupBox)}
    chains["group_widths"] = widths
    if animated:
        held = animated[0]
        row = chains["listed"].index(held)
        items[row].setCheckState(QtCore.Qt.Unchecked)
        chains["chosen"] = panel.chosen_chains()
        again = panel.run_design()
        reports = {c.name: c for c in again.chains} if again else {}
        chains["held"] = held
        chains["held_mapping"] = reports[held].mapping if held in reports else None
        chains["held_reason"] = reports[held].reason if held in reports else ""
        chains["kept_unchecked"] = panel.chain_list.item(row).checkState() == QtCore.Qt.Unchecked
        panel.chain_list.item(row).setCheckState(QtCore.Qt.Checked)
        # None checked: the design is refused on the status line, no exception.
        for r in range(panel.chain_list.count()):
            panel.chain_list.item(r).setCheckState(QtCore.Qt.Unchecked)
        chains["none_checked_returns"] = panel.run_design() is not None
        chains["none_checked_status"] = panel.status.text()
        for r in range(panel.chain_list.count()):
            panel.chain_list.item(r).setCheckState(QtCore.Qt.Checked)
        panel.run_design()  # the card OK builds below animates every chain again
    result["chains_panel"] = chains


def run():
    from popupwb import progress
    from popupwb.commands.from_animation import FromAnimationCommand, open_panel
    from popupwb.taskpanels import from_animation_panel

    log_start = report_view_text()
    doc = FreeCAD.newDocument("FromAnimation")
    result["command_active"] = FromAnimationCommand().IsActive()
    open_panel(CONFIG["bvh"], doc)
    settle()
    panel = from_animation_panel.last_panel
    result["panel_open"] = panel is not None and panel.path == CONFIG["bvh"]
    result["panel_visible"] = bool(panel and panel.form.isVisible())
    panel.view.setCurrentIndex(panel.view.findText("-Z"))
    panel.up.setCurrentIndex(panel.up.findText("+Y"))
    panel.prune.setValue(0.05)
    panel.motion_weight.setValue(80.0)
    panel.depth_weight.setValue(20.0)
    panel.iterations.setValue(1500)
    panel.seed.setValue(2)
    options = panel.options()
    result["options"] = [
        list(options.view.view), list(options.view.up), options.chains.prune_fraction,
        options.motion_weight, options.depth_weight, options.iterations, options.seed,
    ]

    start = time.monotonic()
    panel.design_button.click()
    settle()
    result["design_s"] = time.monotonic() - start
    designed = panel.result
    result["designed"] = designed is not None
    result["status"] = panel.status.text()
    result["frames_max"] = panel.last_frame.maximum()
    result["chains"] = [c.name for c in designed.chains] if designed else []
    result["mechanism_names"] = [m.name for m in designed.mechanisms] if designed else []
    result["plot_size"] = list(panel.plot.full_size())
    movie = panel.movie.movie
    result["movie"] = [movie.frameCount(), *panel.movie.full_size()] if movie else []
    result["frame_boxes"] = [panel.first_frame.text(), panel.last_frame.text()]
    result["window"] = [designed.targets.first_frame, designed.targets.last_frame] if designed else []
    # FreeCAD's side pane is 260-400 px wide: the whole panel, plot included, must fit 260 px.
    result["panel_min_width"] = panel.form.minimumSizeHint().width()
    panel.form.resize(340, 900)
    settle()
    result["plot_shown_width"] = panel.plot.pixmap().width() if panel.plot.pixmap() else 0
    chains_test(panel, designed)
    panel.form.resize(460, 900)
    settle()
    panel.form.grab().save(CONFIG["panel_png"])
    count_non_white(CONFIG["panel_png"], "panel_")

    # Cancel: the dialog shows at once; Cancel is pressed while the annealing runs, after the
    # bar has moved.
    progress.SHOW_AFTER_MS = 0
    cancel = {}
    cancel_progress_later(1500, cancel)
    panel.iterations.setValue(5000000)
    start = time.monotonic()
    cancel["returned"] = panel.run_design() is not None
    cancel["seconds"] = time.monotonic() - start
    cancel["status"] = panel.status.text()
    result["cancel"] = cancel
    progress.SHOW_AFTER_MS = 500
    panel.iterations.setValue(1500)

    design = accept_panel(panel, doc)  # never designed since the cancel: OK designs, builds
    card = design.card if design else None
    result["source_animation"] = card.SourceAnimation if card else None
    # Dragging the fold angle moves the mechanisms: their shapes change between 180° and 120°.
    boxes = {}
    for angle in (180.0, 120.0):
        card.FoldAngle = angle
        doc.recompute()
        settle(100)
        boxes[angle] = [
            [round(v, 6) for v in (m.Shape.BoundBox.XMin, m.Shape.BoundBox.XMax,
                                   m.Shape.BoundBox.ZMax)]
            for m in design.mechanisms
        ]
    result["moved"] = boxes[180.0] != boxes[120.0]
    save_view_fitted(CONFIG["card_png"], "card_")
    result["log"] = report_view_text()[len(log_start):]
"""


def main():
    check = Checks(NAME)
    folder = os.path.join(SANDBOX, NAME + "_data")
    os.makedirs(folder, exist_ok=True)
    config = {
        "bvh": bvh_samples.write_bvh(os.path.join(folder, "wave.bvh")),
        "panel_png": os.path.join(SANDBOX, NAME, "from_animation_panel.png"),
        "card_png": os.path.join(SANDBOX, NAME, "from_animation_card.png"),
    }
    code, result, out_dir = run_macro(NAME, BODY, config, timeout=400)
    r = check.macro_ran(code, result, out_dir)
    check("the command is active", r.get("command_active") is True)
    check(
        "the panel opens on the animation",
        r.get("panel_open") is True and r.get("panel_visible") is True,
    )
    check(
        "the panel's settings reach MotionOptions",
        r.get("options") == [[0.0, 0.0, -1.0], [0.0, 1.0, 0.0], 0.05, 80.0, 20.0, 1500, 2],
        r.get("options"),
    )
    check("Design designs", r.get("designed") is True, r.get("status"))
    check(
        "the status says the reach floor next to the error",
        "no design on this card under" in r.get("status", ""),
        r.get("status"),
    )
    check(
        "the frame range follows the file",
        r.get("frames_max") == bvh_samples.FRAMES - 1,
        r.get("frames_max"),
    )
    check(
        "the paths plot is in the panel",
        r.get("plot_size", [0, 0])[0] >= 300 and r.get("panel_tinted_pixels", 0) > 300,
        r.get("plot_size"),
    )
    check(
        "the panel plays the card opening beside the character (motion.gif's 37 frames)",
        r.get("movie", [0])[0] == 37 and r["movie"][1] == 960,
        r.get("movie"),
    )
    check(
        "the panel fits a 260 px side pane, its plot scaled to it",
        0 < r.get("panel_min_width", 10**6) <= 260 and 150 < r.get("plot_shown_width", 0) <= 340,
        [r.get("panel_min_width"), r.get("plot_shown_width")],
    )
    window = r.get("window") or [None, None]
    frame_boxes = r.get("frame_boxes") or ["", ""]
    check(
        "the frame boxes show the frames the card shows",
        frame_boxes[1] in (f"auto: {window[1]}", "last")
        and (frame_boxes[1] == "last" or frame_boxes[0] == f"auto: {window[0]}"),
        [frame_boxes, window],
    )
    cancel = r.get("cancel", {})
    bar = cancel.get("bar", [0, 0])
    check(
        "the progress bar follows the annealing and Cancel stops it: no result, status says so",
        cancel.get("dialog_visible") is True
        and bar[1] == 1000
        and 0 < bar[0] < 1000
        and cancel.get("returned") is False
        and "cancelled" in cancel.get("status", ""),
        cancel,
    )
    check.card_built(r, "designed")
    check(
        "the card links the animation",
        r.get("source_animation") == config["bvh"],
        r.get("source_animation"),
    )
    check("dragging the fold angle moves the mechanisms", r.get("moved") is True)
    chains = r.get("chains_panel", {})
    check(
        "the chain list has a checked box per chain found, all animating",
        chains.get("listed") == r.get("chains")
        and chains.get("all_checked") is True
        and chains.get("all_chosen") is True,
        chains,
    )
    check(
        "unchecking the animated chain holds it still, the report saying the maker chose so",
        chains.get("animated_before")
        and chains.get("chosen") == [c for c in chains["listed"] if c != chains.get("held")]
        and chains.get("held_mapping") == "stationary"
        and "the maker did not choose it" in chains.get("held_reason", "")
        and chains.get("kept_unchecked") is True,
        chains,
    )
    check(
        "no chain checked: Design says so on the status line",
        chains.get("none_checked_returns") is False
        and "check at least one chain" in chains.get("none_checked_status", ""),
        chains,
    )
    widths = dict(chains.get("group_widths", {}))
    chain_width = widths.pop("Chains to animate", None)
    check(
        "the chain list does not widen the panel",
        chain_width is not None and widths and chain_width <= max(widths.values()),
        chains.get("group_widths"),
    )
    check.no_traceback(r.get("log"))
    check("card screenshot saved", r.get("card_non_white_pixels", 0) > 1000, config["card_png"])
    return check.exit_code()


if __name__ == "__main__":
    sys.exit(main())
