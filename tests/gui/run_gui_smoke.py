"""GUI smoke test: the PopUp workbench in the real FreeCAD GUI under Xvfb.

Writes a macro that activates the workbench, loads resources/samples/demo_card.json as a Scaffold,
runs PopUp_CheckValidity, saves an isometric screenshot and writes a JSON result; runs FreeCAD on it
and checks the result. Run by ctest (gui_smoke) with /usr/bin/python3; by hand:

    /usr/bin/python3 tests/gui/run_gui_smoke.py      # POPUP_BUILD_DIR defaults to ./build

Output (macro, result.json, screenshot.png, freecad.log) stays in <build>/sandbox/gui_smoke/.
"""

import json
import os
import shutil
import subprocess
import sys
import uuid

SOURCE_DIR = os.environ.get("POPUP_SOURCE_DIR") or os.path.dirname(
    os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
)
BUILD_DIR = os.environ.get("POPUP_BUILD_DIR") or os.path.join(SOURCE_DIR, "build")
SANDBOX = os.path.join(BUILD_DIR, "sandbox")
OUT_DIR = os.path.join(SANDBOX, "gui_smoke")
# A home of its own, fresh every run: no remembered window state, and no clash with the headless
# tests that ctest runs in parallel in sandbox/home.
GUI_HOME = os.path.join(SANDBOX, "gui_home")
SAMPLE = os.path.join(SOURCE_DIR, "resources", "samples", "demo_card.json")
WORKBENCH_DIR = os.path.join(SOURCE_DIR, "Workbench")
COMMANDS = ["PopUp_LoadDesign", "PopUp_CheckValidity"]
WIDTH, HEIGHT = 800, 600

MACRO = r"""
import json
import traceback

import FreeCAD
import FreeCADGui as Gui
from PySide import QtCore, QtGui

CONFIG = json.loads(%(config)r)
result = {"errors": [], "workbench": None, "command_ran": False}


def count_non_white(path):
    image = QtGui.QImage(path)
    result["image_size"] = [image.width(), image.height()]
    non_white = tinted = 0
    for y in range(image.height()):
        for x in range(image.width()):
            rgb = image.pixel(x, y) & 0xFFFFFF
            if rgb != 0xFFFFFF:
                non_white += 1
                red, green, blue = rgb >> 16, (rgb >> 8) & 0xFF, rgb & 0xFF
                tinted += max(red, green, blue) - min(red, green, blue) > 12
    result["non_white_pixels"] = non_white
    result["tinted_pixels"] = tinted  # not grey: role colours reached the screen


def main():
    Gui.activateWorkbench("PopUpWorkbench")
    result["workbench"] = Gui.activeWorkbench().name()
    result["commands"] = [c for c in CONFIG["commands"] if c in Gui.listCommands()]
    toolbar = Gui.getMainWindow().findChild(QtGui.QToolBar, "PopUp")
    result["toolbar_actions"] = len(toolbar.actions()) if toolbar else 0

    from popupwb.make import make_scaffold
    from popupwb.commands import check_validity

    doc = FreeCAD.newDocument("GuiSmoke")
    obj = make_scaffold(doc, CONFIG["sample"], fold_angle=CONFIG["fold_angle"])
    doc.recompute()
    Gui.updateGui()
    result["object_state"] = list(obj.State)
    result["shape_valid"] = obj.Shape.isValid()
    result["faces"] = len(obj.Shape.Faces)
    result["face_colours"] = len(obj.ViewObject.DiffuseColor)
    result["icon"] = obj.ViewObject.Proxy.getIcon()

    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(obj)
    Gui.runCommand(CONFIG["check_command"])
    result["command_ran"] = len(check_validity.last_reports) == 1
    result["valid"] = obj.Valid
    result["diagnostics"] = list(obj.Diagnostics)
    Gui.Selection.clearSelection()

    view = Gui.ActiveDocument.ActiveView
    view.viewIsometric()
    view.fitAll()
    Gui.updateGui()
    view.saveImage(CONFIG["png"], CONFIG["width"], CONFIG["height"], "White")
    count_non_white(CONFIG["png"])
    FreeCAD.closeDocument(doc.Name)

    # PopUp_LoadDesign past its file dialog: one undoable transaction.
    from popupwb.commands import load_design

    doc = FreeCAD.newDocument("GuiSmokeLoad")
    loaded = load_design.load(CONFIG["sample"])
    result["loaded"] = loaded is not None and loaded.Document == doc and loaded.Shape.isValid()
    doc.undo()
    result["load_undone"] = doc.Objects == []
    FreeCAD.closeDocument(doc.Name)


try:
    main()
except Exception:
    result["errors"].append(traceback.format_exc())
finally:
    with open(CONFIG["result"], "w") as stream:
        json.dump(result, stream, indent=1)
    QtCore.QTimer.singleShot(0, Gui.getMainWindow().close)
"""


def install_mod(home):
    mod_dir = os.path.join(home, "Mod")
    os.makedirs(mod_dir, exist_ok=True)
    link = os.path.join(mod_dir, "PopUp")
    temporary = f"{link}.{uuid.uuid4().hex}"
    os.symlink(WORKBENCH_DIR, temporary)
    os.replace(temporary, link)


def run_freecad():
    """Writes the macro, runs the GUI on it, returns (exit code, result dict or None)."""
    shutil.rmtree(OUT_DIR, ignore_errors=True)
    shutil.rmtree(GUI_HOME, ignore_errors=True)
    os.makedirs(OUT_DIR)
    install_mod(GUI_HOME)
    config = {
        "sample": SAMPLE,
        "fold_angle": 120.0,
        "check_command": "PopUp_CheckValidity",
        "commands": COMMANDS,
        "png": os.path.join(OUT_DIR, "screenshot.png"),
        "result": os.path.join(OUT_DIR, "result.json"),
        "width": WIDTH,
        "height": HEIGHT,
    }
    macro = os.path.join(OUT_DIR, "gui_smoke.FCMacro")
    with open(macro, "w") as stream:
        stream.write(MACRO % {"config": json.dumps(config)})
    env = dict(os.environ)
    env.update(
        QTWEBENGINE_DISABLE_SANDBOX="1",  # the GUI aborts as root without it
        FREECAD_USER_HOME=GUI_HOME,
        HOME=GUI_HOME,
        POPUP_BUILD_DIR=BUILD_DIR,  # the GUI clears PYTHONPATH; popupwb.core looks here
    )
    command = ["timeout", "180", "xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", "freecad"]
    with open(os.path.join(OUT_DIR, "freecad.log"), "w") as log:
        code = subprocess.call(command + [macro], env=env, stdout=log, stderr=subprocess.STDOUT)
    try:
        with open(config["result"]) as stream:
            return code, json.load(stream)
    except (OSError, ValueError):
        return code, None


def main():
    checks = []

    def check(name, ok, detail=""):
        checks.append(ok)
        print(f"{'PASS' if ok else 'FAIL'}  {name}" + (f"  ({detail})" if detail else ""))

    for command in COMMANDS + ["PopUp_Workbench", "PopUp_Scaffold"]:
        icon = os.path.join(WORKBENCH_DIR, "popupwb", "resources", "icons", command + ".svg")
        check(f"icon {command}.svg exists", os.path.isfile(icon))
    check("sample design exists", os.path.isfile(SAMPLE), SAMPLE)

    code, result = run_freecad()
    log = os.path.join(OUT_DIR, "freecad.log")
    check("FreeCAD exited 0", code == 0, f"exit {code}, log {log}")
    check("macro wrote its result", result is not None, os.path.join(OUT_DIR, "result.json"))
    result = result or {}
    errors = result.get("errors", ["no result"])
    check("macro raised nothing", not errors, "\n".join(errors))
    check(
        "PopUp workbench active",
        result.get("workbench") == "PopUpWorkbench",
        result.get("workbench"),
    )
    check("commands registered", result.get("commands") == COMMANDS, result.get("commands"))
    check("toolbar has the commands", result.get("toolbar_actions", 0) >= len(COMMANDS))
    check(
        "scaffold recomputed to a valid shape",
        result.get("shape_valid") is True and "Invalid" not in result.get("object_state", []),
        result.get("object_state"),
    )
    check(
        "faces coloured by role",
        result.get("faces", 0) > 0 and result.get("face_colours") == result.get("faces"),
        f"{result.get('face_colours')} colours for {result.get('faces')} faces",
    )
    check("PopUp_CheckValidity ran", result.get("command_ran") is True)
    check("PopUp_LoadDesign loads the file", result.get("loaded") is True)
    check("PopUp_LoadDesign is one undo step", result.get("load_undone") is True)
    check("demo card reported valid", result.get("valid") is True, result.get("diagnostics"))
    pixels = result.get("non_white_pixels", 0)
    check(
        "screenshot shows the card",
        result.get("image_size") == [WIDTH, HEIGHT]
        and pixels > 0.02 * WIDTH * HEIGHT
        and result.get("tinted_pixels", 0) > 0.005 * WIDTH * HEIGHT,
        f"{pixels} non-white pixels, {result.get('tinted_pixels')} in colour, "
        + os.path.join(OUT_DIR, "screenshot.png"),
    )
    failed = checks.count(False)
    print(f"gui_smoke: {len(checks) - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
