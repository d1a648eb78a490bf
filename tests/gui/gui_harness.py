"""Runs a macro in the real FreeCAD GUI under Xvfb and returns what it wrote. Shared by the GUI
tests in tests/gui/ (each a ctest entry run with /usr/bin/python3).

A test passes its macro body and a config dict; the body runs after PRELUDE, which defines
`CONFIG`, `result` (a dict the body fills in) and helpers: count_non_white, report_view_text,
wait_until, settle, save_screenshot, save_view_fitted, visible_progress_dialog,
cancel_progress_later, accept_panel. The harness
writes `result` to JSON when the body ends or raises (the traceback goes to result["errors"]) and
quits FreeCAD. Checks prints the test's PASS/FAIL lines, with the checks every test makes of the
run itself (macro_ran, no_traceback) and of a card a panel built (card_built).
"""

import importlib.util
import json
import os
import shutil
import subprocess
import sys

SOURCE_DIR = os.environ.get("POPUP_SOURCE_DIR") or os.path.dirname(
    os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
)
BUILD_DIR = os.environ.get("POPUP_BUILD_DIR") or os.path.join(SOURCE_DIR, "build")
SANDBOX = os.path.join(BUILD_DIR, "sandbox")
WORKBENCH_DIR = os.path.join(SOURCE_DIR, "Workbench")
sys.path.append(WORKBENCH_DIR)
from popupwb import freecad_version  # noqa: E402  (importable before FreeCAD)

WIDTH, HEIGHT = 800, 600

PRELUDE = r"""
import json
import os
import re
import traceback

import FreeCAD
import FreeCADGui as Gui
from PySide import QtCore, QtGui

CONFIG = json.loads(%(config)r)
result = {"errors": []}


def count_non_white(path, prefix="", target=None):
    target = result if target is None else target
    image = QtGui.QImage(path)
    target[prefix + "image_size"] = [image.width(), image.height()]
    non_white = tinted = 0
    for y in range(image.height()):
        for x in range(image.width()):
            rgb = image.pixel(x, y) & 0xFFFFFF
            if rgb != 0xFFFFFF:
                non_white += 1
                red, green, blue = rgb >> 16, (rgb >> 8) & 0xFF, rgb & 0xFF
                tinted += max(red, green, blue) - min(red, green, blue) > 12
    target[prefix + "non_white_pixels"] = non_white
    target[prefix + "tinted_pixels"] = tinted  # not grey: role colours reached the screen


def report_view_text():
    window = Gui.getMainWindow()
    dock = window.findChild(QtGui.QDockWidget, "Report view")
    widget = dock.widget() if dock else None
    return widget.toPlainText() if hasattr(widget, "toPlainText") else ""


def wait_until(condition, timeout_ms=60000):
    # Runs the event loop (timers, repaints) until condition() or the timeout; True if met.
    timer = QtCore.QElapsedTimer()
    timer.start()
    while not condition():
        if timer.elapsed() > timeout_ms:
            return False
        QtCore.QCoreApplication.processEvents(QtCore.QEventLoop.AllEvents, 50)
    return True


def settle(ms=300):
    wait_until(lambda: False, ms)  # the report view appends queued messages on events


def save_screenshot(path, width=%(width)d, height=%(height)d):
    view = Gui.ActiveDocument.ActiveView
    view.saveImage(path, width, height, "White")
    return path


def visible_progress_dialog():
    from popupwb import progress

    found = [d for d in Gui.getMainWindow().findChildren(QtGui.QProgressDialog)
             if d.objectName() == progress.DIALOG_NAME and d.isVisible()]
    return found[0] if found else None


def cancel_progress_later(ms, record):
    # Presses Cancel on PopUp's progress dialog `ms` after now (timers run inside the wait loop
    # and the long job's own event loop); `record` gets whether the dialog was up and its bar.
    def press():
        dialog = visible_progress_dialog()
        record["dialog_visible"] = dialog is not None
        if dialog is not None:
            record["bar"] = [dialog.value(), dialog.maximum()]
            dialog.cancel()

    QtCore.QTimer.singleShot(ms, press)


def accept_panel(panel, doc):
    # Presses OK on a panel that builds a card (taskpanels/long_job_panel.py); `result` gets
    # whether it was accepted, the features' labels, the card's verdict and what is in error
    # (Checks.card_built reads them). Returns the design OK built, or None.
    ok = panel.accept()
    settle()
    design = panel.design
    card = design.card if design else None
    result["accepted"] = bool(ok)
    result["labels"] = [m.Label for m in design.mechanisms] if design else []
    result["validity"] = card.Validity if card else None
    result["invalid"] = [o.Label for o in doc.Objects if "Invalid" in o.State]
    return design


def save_view_fitted(path, prefix, width=1200, height=900):
    # The whole document seen from the isometric view, saved and its pixels counted.
    Gui.ActiveDocument.ActiveView.viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    settle()
    save_screenshot(path, width, height)
    count_non_white(path, prefix)
"""

EPILOGUE = r"""

def _write_result():
    with open(CONFIG["result"], "w") as stream:
        json.dump(result, stream, indent=1, default=str)


try:
    Gui.activateWorkbench("PopUpWorkbench")
    run()
except Exception:
    result["errors"].append(traceback.format_exc())
_write_result()
# Closed without saving: an open modified document would stop the quit at "Save changes?".
for _name in list(FreeCAD.listDocuments()):
    FreeCAD.closeDocument(_name)
QtCore.QTimer.singleShot(0, Gui.getMainWindow().close)
"""


def install_mod(home):
    """Links the source tree's Workbench into the user Mod folder FreeCAD uses with `home`
    (versioned from 1.1 on; atomically: tests run in parallel)."""
    env = dict(os.environ, FREECAD_USER_HOME=home, HOME=home)
    freecad_version.link_into(freecad_version.user_mod_dir_for(env), WORKBENCH_DIR)


def run_freecad(name, macro_text, timeout=180):
    """Runs FreeCAD's GUI under Xvfb on `macro_text` (already complete) with a fresh home of its
    own in <build>/sandbox/<name>_home; the log goes to <build>/sandbox/<name>/freecad.log.
    Returns the exit code."""
    out_dir = os.path.join(SANDBOX, name)
    home = os.path.join(SANDBOX, name + "_home")
    shutil.rmtree(home, ignore_errors=True)
    install_mod(home)
    macro = os.path.join(out_dir, name + ".FCMacro")
    with open(macro, "w") as stream:
        stream.write(macro_text)
    env = dict(os.environ)
    env.update(
        QTWEBENGINE_DISABLE_SANDBOX="1",  # the GUI aborts as root without it
        FREECAD_USER_HOME=home,
        HOME=home,
        POPUP_BUILD_DIR=BUILD_DIR,  # the GUI clears PYTHONPATH; popupwb.core looks here
    )
    command = ["timeout", str(timeout), "xvfb-run", "-a", "-s", "-screen 0 1280x1024x24"]
    with open(os.path.join(out_dir, "freecad.log"), "w") as log:
        return subprocess.call(
            command + ["freecad", macro], env=env, stdout=log, stderr=subprocess.STDOUT
        )


def run_macro(name, body, config=None, timeout=180):
    """Runs `body` (Python source defining `run()`, which fills in `result`) in the GUI after the
    PRELUDE. Output goes to <build>/sandbox/<name>/ (emptied first); config gains "out_dir" and
    "result". Returns (exit code, result dict or None, out_dir)."""
    out_dir = os.path.join(SANDBOX, name)
    shutil.rmtree(out_dir, ignore_errors=True)
    os.makedirs(out_dir)
    config = dict(config or {})
    config.update(out_dir=out_dir, result=os.path.join(out_dir, "result.json"))
    prelude = PRELUDE % {"config": json.dumps(config), "width": WIDTH, "height": HEIGHT}
    code = run_freecad(name, prelude + body + EPILOGUE, timeout)
    try:
        with open(config["result"]) as stream:
            return code, json.load(stream), out_dir
    except (OSError, ValueError):
        return code, None, out_dir


def make_models():
    """tools/make_models.py, the writer of the test models, as a module."""
    spec = importlib.util.spec_from_file_location(
        "make_models", os.path.join(SOURCE_DIR, "tools", "make_models.py")
    )
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def write_model(name, path):
    """make_models' model `name` written to `path` (its extension chooses the format)."""
    return make_models().write_model(name, path)


class Checks:
    """PASS/FAIL lines for a GUI test; exit_code() is 1 when any failed."""

    def __init__(self, name):
        self.name = name
        self.results = []

    def __call__(self, what, ok, detail=""):
        self.results.append(bool(ok))
        print(f"{'PASS' if ok else 'FAIL'}  {what}" + (f"  ({detail})" if detail else ""))

    def macro_ran(self, code, result, out_dir):
        """FreeCAD quit cleanly and the macro raised nothing; returns the result ({} if none)."""
        self("FreeCAD exited 0", code == 0, f"exit {code}, log {out_dir}/freecad.log")
        r = result or {}
        errors = r.get("errors", ["no result"])
        self("macro raised nothing", not errors, "\n".join(errors))
        return r

    def no_traceback(self, log, what="no traceback in the report view", shown=None):
        """`log` (None: nothing was read, a failure) holds no traceback; `shown` is its part
        printed with the line (default: all of it)."""
        self(what, "Traceback" not in (log if log is not None else "Traceback"), shown or log)

    def card_built(self, r, how):
        """What accept_panel recorded: OK built a checked, valid card with one feature per
        mechanism, labelled as the job (`how`: fitted, designed) named them; nothing in error."""
        self(
            f"OK builds the card: one feature per mechanism, named as {how}",
            r.get("accepted") is True
            and r.get("labels")
            and r.get("labels") == r.get("mechanism_names"),
            f"{r.get('labels')} vs {r.get('mechanism_names')}",
        )
        self("the card is checked valid", r.get("validity") == "Valid", r.get("validity"))
        self("nothing in error", r.get("invalid") == [], r.get("invalid"))

    def exit_code(self):
        failed = self.results.count(False)
        print(f"{self.name}: {len(self.results) - failed} passed, {failed} failed")
        return 1 if failed else 0
