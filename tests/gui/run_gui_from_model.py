#!/usr/bin/python3
"""GUI test of PopUp_FromModel in the real FreeCAD GUI under Xvfb (tests/gui/gui_harness.py): a
house mesh made by tools/make_models.py is selected, the command opens its panel, the settings go
in, Fit draws the fitted prisms over the model, a second fit is cancelled from the progress
dialog, and OK builds a checked card with one feature per fitted mechanism and the model linked.
Screenshots: <build>/sandbox/gui_from_model/from_model_overlay.png and from_model_card.png."""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_harness import SANDBOX, Checks, run_macro, write_model  # noqa: E402

NAME = "gui_from_model"

BODY = r"""
import time


def overlay_node():
    from popupwb.taskpanels.primitive_overlay import NODE_NAME
    root = Gui.ActiveDocument.ActiveView.getSceneGraph()
    for i in range(root.getNumChildren()):
        child = root.getChild(i)
        if child.getName() == NODE_NAME:
            return child
    return None


def run():
    import Mesh
    from popupwb import progress
    from popupwb.taskpanels import from_model_panel

    log_start = report_view_text()
    doc = FreeCAD.newDocument("FromModel")
    house = doc.addObject("Mesh::Feature", "House")
    house.Mesh = Mesh.Mesh(CONFIG["model"])
    doc.recompute()
    Gui.ActiveDocument.ActiveView.viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(house)
    from popupwb.commands.from_model import FromModelCommand
    result["command_active"] = FromModelCommand().IsActive()
    Gui.runCommand("PopUp_FromModel")
    settle()
    panel = from_model_panel.last_panel
    result["panel_open"] = panel is not None and panel.obj is house
    result["panel_visible"] = bool(panel and panel.form.isVisible())
    panel.up.setCurrentIndex(panel.up.findText("+Z"))
    panel.facing.setCurrentIndex(panel.facing.findText("-Y"))
    panel.max_mechanisms.setValue(6)
    panel.seed.setValue(2)
    options = panel.options()
    result["options"] = [list(options.up), list(options.facing), options.max_mechanisms, options.seed]

    start = time.monotonic()
    panel.fit_button.click()
    settle()
    result["fit_s"] = time.monotonic() - start
    fitted = panel.result
    result["fitted"] = fitted is not None
    result["status"] = panel.status.text()
    node = overlay_node()
    result["overlay_prisms"] = node.getNumChildren() if node is not None else -1
    result["primitives"] = len(fitted.primitives) if fitted else 0
    result["mechanism_names"] = [m.name for m in fitted.mechanisms] if fitted else []
    # The prisms sit on the model: their corners, back in model coordinates, inside its box
    # (grown by 5 % of its diagonal).
    box = house.Mesh.BoundBox
    grow = 0.05 * box.DiagonalLength
    inside = True
    for corners in panel.overlay.prisms:
        for x, y, z in corners:
            inside &= box.XMin - grow <= x <= box.XMax + grow
            inside &= box.YMin - grow <= y <= box.YMax + grow
            inside &= box.ZMin - grow <= z <= box.ZMax + grow
    result["prisms_on_model"] = bool(panel.overlay.prisms) and bool(inside)
    save_screenshot(CONFIG["overlay_png"], 1200, 900)
    count_non_white(CONFIG["overlay_png"], "overlay_")

    # Cancel: the dialog shows at once and Cancel is pressed while the fit runs.
    progress.SHOW_AFTER_MS = 0
    cancel = {}
    cancel_progress_later(1, cancel)
    panel.detail.setValue(1.0)
    cancel["returned"] = panel.fit() is not None
    cancel["status"] = panel.status.text()
    result["cancel"] = cancel
    progress.SHOW_AFTER_MS = 500
    panel.detail.setValue(0.5)

    design = accept_panel(panel, doc)  # never fitted since the cancel: OK fits, then builds
    card = design.card if design else None
    result["card"] = card.Name if card else None
    result["source_model"] = card.SourceModel.TypeId if card and card.SourceModel else None
    result["overlay_after_ok"] = overlay_node() is not None
    house.Visibility = False
    save_view_fitted(CONFIG["card_png"], "card_")
    result["log"] = report_view_text()[len(log_start):]
"""


def main():
    check = Checks(NAME)
    os.makedirs(os.path.join(SANDBOX, NAME + "_models"), exist_ok=True)
    config = {
        "model": write_model("house", os.path.join(SANDBOX, NAME + "_models", "house.stl")),
        "overlay_png": os.path.join(SANDBOX, NAME, "from_model_overlay.png"),
        "card_png": os.path.join(SANDBOX, NAME, "from_model_card.png"),
    }
    code, result, out_dir = run_macro(NAME, BODY, config, timeout=300)
    r = check.macro_ran(code, result, out_dir)
    check("the command is active with a mesh selected", r.get("command_active") is True)
    check(
        "the command opens the panel on the selected mesh",
        r.get("panel_open") is True and r.get("panel_visible") is True,
    )
    check(
        "the panel's settings reach FitOptions",
        r.get("options") == [[0.0, 0.0, 1.0], [0.0, -1.0, 0.0], 6, 2],
        r.get("options"),
    )
    check("Fit fits", r.get("fitted") is True, r.get("status"))
    check(
        "one overlay prism per fitted primitive, over the model",
        r.get("overlay_prisms") == r.get("primitives") > 0 and r.get("prisms_on_model") is True,
        f"{r.get('overlay_prisms')} drawn, {r.get('primitives')} fitted",
    )
    check(
        "the overlay screenshot shows the orange prisms",
        r.get("overlay_tinted_pixels", 0) > 1000,
        config["overlay_png"],
    )
    cancel = r.get("cancel", {})
    check(
        "Cancel in the progress dialog stops the fit: no result, the status says so",
        cancel.get("dialog_visible") is True
        and cancel.get("returned") is False
        and "cancelled" in cancel.get("status", ""),
        cancel,
    )
    check.card_built(r, "fitted")
    check("the card links the source model", r.get("source_model") == "Mesh::Feature")
    check("the overlay is gone after OK", r.get("overlay_after_ok") is False)
    check.no_traceback(r.get("log"))
    check("card screenshot saved", r.get("card_non_white_pixels", 0) > 1000, config["card_png"])
    return check.exit_code()


if __name__ == "__main__":
    sys.exit(main())
