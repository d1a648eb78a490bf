"""GUI test of the card task panel, the progress dialog and one-line errors, in FreeCAD's GUI under
Xvfb (tests/gui/gui_harness.py).

A5 card with a box, driven as a maker does: double-click the card in the tree (the card panel
opens, not the Transform dragger), drag the fold-angle slider, play and stop, change the preset,
type a bad width, make the box too tall and check validity (findings listed; clicking one selects
the box's face), make the box fit again and make sheets; type a bad value in the box's own panel.
Then a slow card (three nested boxes of 10 panel pairs): the progress dialog appears for the validity check,
Cancel returns at once, and Make sheets cancelled adds no CuttingSheet. Saves the whole main
window with the card panel as card_panel.png (docs/images/card_panel.png is a copy).

    POPUP_SOURCE_DIR=$PWD POPUP_BUILD_DIR=$PWD/build /usr/bin/python3 tests/gui/run_gui_panel.py
"""

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_harness import Checks, run_macro  # noqa: E402

NAME = "gui_panel"

BODY = r"""
import time


def tree_double_click(obj):
    # A real double-click on the object's row in the model tree (the Model tab brought to the
    # front first, as a maker does while a task panel shows).
    tree = next(t for t in Gui.getMainWindow().findChildren(QtGui.QTreeWidget)
                if t.topLevelItemCount() and t.window() is Gui.getMainWindow())
    for tabs in Gui.getMainWindow().findChildren(QtGui.QTabWidget):
        for index in range(tabs.count()):
            if tabs.widget(index).isAncestorOf(tree):
                tabs.setCurrentIndex(index)
    Gui.updateGui()
    found = tree.findItems(obj.Label, QtCore.Qt.MatchExactly | QtCore.Qt.MatchRecursive, 0)
    item = found[0]
    tree.scrollToItem(item)
    point = tree.visualItemRect(item).center()
    viewport = tree.viewport()
    for kind in (QtCore.QEvent.MouseButtonPress, QtCore.QEvent.MouseButtonRelease,
                 QtCore.QEvent.MouseButtonDblClick, QtCore.QEvent.MouseButtonRelease):
        event = QtGui.QMouseEvent(kind, point, QtCore.Qt.LeftButton, QtCore.Qt.LeftButton,
                                  QtCore.Qt.NoModifier)
        QtGui.QApplication.sendEvent(viewport, event)
    Gui.updateGui()


def save_window(window, path):
    # The whole main window; QWidget.grab() leaves the OpenGL 3D view blank under Xvfb, so the
    # view's own off-screen rendering is painted over it.
    image = window.grab().toImage()
    viewer = window.findChild(QtGui.QMdiArea).activeSubWindow().widget()
    corner = viewer.mapTo(window, QtCore.QPoint(0, 0))
    rendered = os.path.join(CONFIG["out_dir"], "view.png")
    Gui.ActiveDocument.ActiveView.saveImage(rendered, viewer.width(), viewer.height(), "Current")
    painter = QtGui.QPainter(image)
    painter.drawImage(corner, QtGui.QImage(rendered))
    painter.end()
    image.save(path)


def new_log(since):
    settle()
    return report_view_text()[len(since):]


def click_cancel_later(ms, out):
    # Presses Cancel on the progress dialog `ms` after now (timers run inside the wait loop).
    from popupwb import progress

    def press():
        dialog = visible_progress_dialog()
        out["dialog_visible"] = bool(dialog and dialog.isVisible())
        out["dialog_label"] = dialog.labelText() if dialog else None
        out["cancel_clicked_at"] = time.monotonic()
        if dialog:
            dialog.cancel()

    QtCore.QTimer.singleShot(ms, press)


def run():
    from popupwb import progress
    from popupwb.model import card_scaffold
    from popupwb.gui import fold_player
    from popupwb.features.cutting_sheet import is_cutting_sheet
    from popupwb.taskpanels import card_panel, mechanism_panel

    window = Gui.getMainWindow()
    window.showMaximized()
    doc = FreeCAD.newDocument("PanelCard")
    Gui.runCommand("PopUp_Card")
    card = next(o for o in doc.Objects if card_scaffold.is_card(o))
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(card)
    Gui.runCommand("PopUp_BoxFold")
    box = next(o for o in doc.Objects if card_scaffold.is_mechanism(o))
    for name, value in dict(Offset=40, Width=60, DepthGround=30, DepthBackdrop=30,
                            Height=30).items():
        setattr(box, name, value)
    doc.recompute()
    Gui.Selection.clearSelection()
    settle()
    log_start = report_view_text()

    # Double-click: the card panel, in edit mode 0.
    tree_double_click(card)
    settle()
    panel = card_panel.last_panel
    result["panel_open"] = bool(Gui.Control.activeDialog()) and panel is not None \
        and panel.card is card
    in_edit = Gui.ActiveDocument.getInEdit()
    result["in_edit"] = in_edit.Object.Name if in_edit else None
    result["panel_visible"] = bool(panel and panel.form.isVisible())

    # The slider: FoldAngle and the shape follow. The pages open symmetrically: at 90° each leans
    # 45°, so the card is Depth * cos 45° high; flat open (180°) only the box stands up, Height
    # high.
    from popupwb.model.card_scaffold import assembled_shape

    result["z_at_180"] = assembled_shape(card).BoundBox.ZLength
    start = time.perf_counter()
    for degrees in range(180, 89, -5):
        panel.slider.setValue(degrees)
    result["ms_per_slider_step"] = 1000.0 * (time.perf_counter() - start) / 19
    result["fold_angle_after_slider"] = card.FoldAngle.Value
    result["z_at_90"] = assembled_shape(card).BoundBox.ZLength
    result["depth"] = card.Depth.Value
    result["box_height"] = box.Height.Value
    result["angle_label"] = panel.angle_label.text()

    # Play and stop (fast frames), back at the angle it started from.
    fold_player.STEP_MS = 5
    panel.play_button.click()
    result["playing"] = panel.playing() and panel.play_button.text() == "Stop"
    wait_until(lambda: panel.player.frames >= 5, 20000)
    result["frames_before_stop"] = panel.player.frames
    panel.play_button.click()
    frames = panel.player.frames
    settle(200)
    result["stopped"] = not panel.playing() and panel.play_button.text() == "Play"
    result["frames_after_stop"] = panel.player.frames - frames
    result["angle_after_play"] = card.FoldAngle.Value

    # Preset and a bad width typed in the panel: one line, no traceback.
    panel.preset.setCurrentIndex(panel.preset.findText("A4"))
    result["a4_size"] = [card.Width.Value, card.Depth.Value]
    result["a4_field"] = panel.size_fields["Width"].value()
    panel.preset.setCurrentIndex(panel.preset.findText("A5"))
    log = report_view_text()
    panel.size_fields["Width"].setValue(-20.0)
    result["bad_width_state"] = list(card.State)
    result["bad_width_status"] = card.getStatusString()
    result["bad_width_panel"] = panel.status_text()
    result["bad_width_log"] = new_log(log)
    panel.size_fields["Width"].setValue(148.0)
    result["width_fixed"] = "Invalid" not in card.State and card.Preset == "Custom"
    panel.preset.setCurrentIndex(panel.preset.findText("A5"))

    # A box too tall for the closed card: findings, and a click selects the offending face.
    box.Height = 70
    box.DepthGround = 70
    box.DepthBackdrop = 70
    doc.recompute()
    panel.slider.setValue(120)
    report = panel.check()
    result["valid_after_check"] = card.Valid
    result["findings"] = [panel.findings_list.item(i).text()
                          for i in range(panel.findings_list.count())]
    result["report_findings"] = len(report["diagnostics"])
    built = card_scaffold.for_card(card)
    result["box_patches"] = list(built.patches[box.Name])
    result["first_finding_patches"] = report["diagnostics"][0]["patches"]
    panel.findings_list.setCurrentRow(0)
    Gui.updateGui()
    result["selection"] = [(s.ObjectName, list(s.SubElementNames))
                           for s in Gui.Selection.getSelectionEx()]
    view = Gui.ActiveDocument.ActiveView
    view.viewIsometric()
    view.fitAll()
    settle(500)
    save_window(window, CONFIG["screenshot"])
    result["screenshot_size"] = [window.width(), window.height()]

    # Back to a valid box; Make sheets.
    box.Height = 30
    box.DepthGround = 30
    box.DepthBackdrop = 30
    doc.recompute()
    sheets = panel.make_sheets()
    result["sheet_made"] = sheets is not None and is_cutting_sheet(sheets)
    result["sheet_state"] = list(sheets.State) if sheets else None
    result["sheet_count"] = sheets.SheetCount if sheets else 0
    result["panel_message"] = panel.status_text()

    # Close keeps the angle.
    panel.slider.setValue(100)
    panel.reject()
    Gui.updateGui()
    result["closed"] = not Gui.Control.activeDialog() and Gui.ActiveDocument.getInEdit() is None
    result["angle_after_close"] = card.FoldAngle.Value
    result["panel_log"] = new_log(log_start)

    # Undo: the session after Make sheets, the sheets, the session before them.
    def sheet_count():
        return len([o for o in doc.Objects if is_cutting_sheet(o)])

    undo_steps = []
    for _ in range(3):
        doc.undo()
        doc.recompute()
        undo_steps.append([card.FoldAngle.Value, card.Preset, sheet_count()])
    result["undo_steps"] = undo_steps
    for _ in range(3):
        doc.redo()
    doc.recompute()
    result["after_redo"] = [card.FoldAngle.Value, sheet_count()]

    # A bad value typed in the box's own panel: one line, no traceback.
    tree_double_click(box)
    mpanel = mechanism_panel.last_panel
    result["mechanism_panel_open"] = mpanel is not None and mpanel.obj is box
    log = report_view_text()
    mpanel.set_value("Height", -5.0)
    result["bad_height_status"] = box.getStatusString()
    result["bad_height_state"] = list(box.State)
    result["bad_height_log"] = new_log(log)
    mpanel.reject()
    Gui.updateGui()

    # Double-clicking the card again while its panel is open: that session ends (committed), a
    # new one starts.
    tree_double_click(card)
    first = card_panel.last_panel
    first.slider.setValue(80)
    tree_double_click(card)
    second = card_panel.last_panel
    result["reopen"] = [first.finished, second is not first, bool(Gui.Control.activeDialog()),
                        card.FoldAngle.Value]
    second.reject()
    Gui.updateGui()

    # A slow card: three boxes of 10 panel pairs, each on the one below (137 patches: the check
    # takes about 2 s here, the sparse solver having made a single such box a 0.1 s check).
    import popupwb.make as make

    box.PanelPairs = 10
    box.Width = 100
    box.Offset = 20
    host = box
    for name in ("Upper", "Top"):
        host = make.make_box_fold(host, host_pair=f"{host.Label}.top", name=name)
        host.PanelPairs = 10
    doc.recompute()
    result["slow_box_state"] = sorted(
        set(s for o in doc.Objects if card_scaffold.is_mechanism(o) for s in o.State)
    )
    tree_double_click(card)
    panel = card_panel.last_panel
    shown = len(progress.shown)
    start = time.monotonic()
    report = panel.check()
    result["slow_check_s"] = time.monotonic() - start
    result["slow_check_valid"] = None if report is None else report["valid"]
    result["dialog_shown_for_slow_check"] = progress.shown[shown:]
    result["dialog_gone_after"] = visible_progress_dialog() is None

    # Cancel: a longer check (4x the samples), cancelled 1 s in.
    from popupwb import validity

    card.Valid = False
    cancel = {}
    click_cancel_later(1000, cancel)
    log = report_view_text()
    start = time.monotonic()
    cancelled = validity.run_check(card, samples=4 * 181)
    returned = time.monotonic()
    result["cancel"] = dict(cancel, returned=cancelled, total_s=returned - start,
                            after_click_s=returned - cancel.get("cancel_clicked_at", returned))
    result["cancel_log"] = new_log(log)
    result["valid_kept"] = card.Valid is False

    # Make sheets cancelled: no CuttingSheet added.
    before = len([o for o in doc.Objects if is_cutting_sheet(o)])
    cancel = {}
    click_cancel_later(700, cancel)
    made = panel.make_sheets()
    result["sheets_cancel"] = dict(cancel, made=made is not None,
                                   sheets_before=before,
                                   sheets_after=len([o for o in doc.Objects
                                                     if is_cutting_sheet(o)]))
    result["sheets_cancel_message"] = panel.status_text()
    panel.reject()
    Gui.updateGui()
    result["final_log"] = new_log(log_start)
"""


def main():
    check = Checks(NAME)
    config = {}
    from gui_harness import SANDBOX

    config["screenshot"] = os.path.join(SANDBOX, NAME, "card_panel.png")
    code, result, out_dir = run_macro(NAME, BODY, config, timeout=400)
    r = check.macro_ran(code, result, out_dir)
    check("macro wrote its result", result is not None)

    check("double-click on the card opens the card panel", r.get("panel_open") is True)
    check(
        "the card is in edit (mode 0), the panel shown",
        r.get("in_edit") == "Card" and r.get("panel_visible") is True,
        r.get("in_edit"),
    )
    check(
        "the slider sets FoldAngle",
        r.get("fold_angle_after_slider") == 90.0,
        r.get("fold_angle_after_slider"),
    )
    depth, z90, z180 = r.get("depth", 0), r.get("z_at_90", 0), r.get("z_at_180", 0)
    check(
        "the shape follows: pages at 45° at 90° (height Depth cos 45°), flat at 180° (box only)",
        abs(z90 - depth * math.sqrt(0.5)) < 0.5 and abs(z180 - r.get("box_height", -1)) < 0.5,
        f"z at 90° {z90:.2f} (Depth {depth}), z at 180° {z180:.2f}",
    )
    check(
        "slider steps recompute live",
        r.get("ms_per_slider_step", 1e9) < 500,
        f"{r.get('ms_per_slider_step', 0):.0f} ms per step",
    )
    check("the angle label follows", r.get("angle_label") == "90°", r.get("angle_label"))
    check(
        "Play runs",
        r.get("playing") is True and r.get("frames_before_stop", 0) >= 5,
        f"{r.get('frames_before_stop')} frames",
    )
    check(
        "Stop stops (no frame after it) and restores the angle",
        r.get("stopped") is True
        and r.get("frames_after_stop") == 0
        and r.get("angle_after_play") == 90.0,
        f"angle {r.get('angle_after_play')}",
    )
    check(
        "preset A4 sets 210 x 148.5 mm and the fields follow",
        r.get("a4_size") == [210.0, 148.5] and r.get("a4_field") == 210.0,
        r.get("a4_size"),
    )
    check(
        "a bad width puts the card in error, named in the panel",
        "Invalid" in r.get("bad_width_state", [])
        and r.get("bad_width_status", "").startswith("Card: Width = -20 mm")
        and r.get("bad_width_panel") == r.get("bad_width_status"),
        r.get("bad_width_status"),
    )
    check(
        "a bad width: one line in the report view, no traceback",
        "Traceback" not in r.get("bad_width_log", "x")
        and r.get("bad_width_status", "?") in r.get("bad_width_log", ""),
        r.get("bad_width_log"),
    )
    check("a typed size makes the preset Custom", r.get("width_fixed") is True)
    box_patches = set(r.get("box_patches", []))
    check(
        "Check validity lists the findings",
        r.get("valid_after_check") is False
        and r.get("findings")
        and len(r.get("findings")) == r.get("report_findings"),
        r.get("findings"),
    )
    first = r.get("first_finding_patches") or [-1]
    selection = r.get("selection") or []
    check(
        "clicking a finding selects its patch's face in the box",
        first[0] in box_patches
        and len(selection) == 1
        and selection[0][0] == "BoxFold"
        and selection[0][1] == [f"Face{sorted(box_patches).index(first[0]) + 1}"],
        f"{selection}, patch {first}",
    )
    check(
        "Make sheets adds a CuttingSheet that lays out",
        r.get("sheet_made") is True
        and "Invalid" not in (r.get("sheet_state") or ["Invalid"])
        and r.get("sheet_count", 0) >= 1,
        r.get("panel_message"),
    )
    check(
        "Close leaves the fold angle where it was put",
        r.get("closed") is True and r.get("angle_after_close") == 100.0,
        r.get("angle_after_close"),
    )
    check(
        "undo: the session after Make sheets, the sheets, the session before them",
        r.get("undo_steps") == [[120.0, "A5", 1], [120.0, "A5", 0], [180.0, "A5", 0]]
        and r.get("after_redo") == [100.0, 1],
        f"{r.get('undo_steps')}, {r.get('after_redo')}",
    )
    check(
        "double-click while open: the session ends committed, a new panel opens",
        r.get("reopen") == [True, True, True, 80.0],
        r.get("reopen"),
    )
    check.no_traceback(
        r.get("panel_log"), "no traceback in the report view during the card panel session"
    )
    check(
        "a bad value in the mechanism panel: box in error, one line, no traceback",
        r.get("mechanism_panel_open") is True
        and "Invalid" in r.get("bad_height_state", [])
        and r.get("bad_height_status", "").startswith("BoxFold: Height = -5 mm")
        and "Traceback" not in r.get("bad_height_log", "Traceback")
        and r.get("bad_height_status", "?") in r.get("bad_height_log", ""),
        r.get("bad_height_log"),
    )
    check(
        "the slow card builds",
        "Invalid" not in r.get("slow_box_state", ["Invalid"]),
        r.get("slow_box_state"),
    )
    check(
        "a check over 0.5 s shows the progress dialog, gone after",
        r.get("slow_check_s", 0) > 0.5
        and r.get("dialog_shown_for_slow_check") == ["Card: checking validity"]
        and r.get("dialog_gone_after") is True,
        f"{r.get('slow_check_s', 0):.2f} s, {r.get('dialog_shown_for_slow_check')}",
    )
    cancel = r.get("cancel", {})
    check(
        "Cancel: the dialog was up, the check stops with no verdict",
        cancel.get("dialog_visible") is True and cancel.get("returned") is None
        # The core stops at its next checkpoint: long before the 4x-sample check would end.
        and cancel.get("total_s", 99) < 2 * r.get("slow_check_s", 0)
        and r.get("valid_kept") is True
        and "cancelled by the user" in r.get("cancel_log", ""),
        f"returned {cancel.get('after_click_s', 0):.3f} s after the click, "
        f"{cancel.get('total_s', 0):.2f} s in all (an uncancelled check of 181 samples took "
        f"{r.get('slow_check_s', 0):.2f} s)",
    )
    sheets_cancel = r.get("sheets_cancel", {})
    check(
        "Make sheets cancelled adds no CuttingSheet",
        sheets_cancel.get("dialog_visible") is True
        and sheets_cancel.get("made") is False
        and sheets_cancel.get("sheets_after") == sheets_cancel.get("sheets_before"),
        f"{sheets_cancel}, {r.get('sheets_cancel_message')}",
    )
    check.no_traceback(r.get("final_log"), "no traceback in the report view at all")
    check(
        "card panel screenshot saved",
        os.path.isfile(config["screenshot"]) and r.get("screenshot_size", [0, 0])[0] >= 1000,
        config["screenshot"],
    )
    return check.exit_code()


if __name__ == "__main__":
    sys.exit(main())
