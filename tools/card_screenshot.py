"""A FreeCAD GUI macro: the workbench with a card, as a maker sees it, in two pictures.

Opens POPUP_SHOT_CARD (a .FCStd holding a PopUpCard), switches to the PopUp workbench, poses the
card at POPUP_SHOT_ANGLE degrees (default 110), checks its validity, and writes into
POPUP_SHOT_OUT: window.png (the whole main window: toolbars, tree, panel) and view.png (the 3D
view), with result.json (FreeCAD and Qt versions, the verdict, the workbench's commands). Used
to look at PopUp on each platform (README "Platforms"):

    xvfb-run -a -s "-screen 0 1280x1024x24" freecad tools/card_screenshot.py
"""

import json
import os
import traceback

import FreeCAD
import FreeCADGui as Gui
from PySide import QtCore, QtGui

OUT = os.environ.get("POPUP_SHOT_OUT", os.getcwd())
RESULT = {"errors": []}


def save_window(view, path):
    """The main window with the 3D view drawn in (a window grab leaves OpenGL views blank)."""
    window = Gui.getMainWindow()
    area = window.findChild(QtGui.QMdiArea).currentSubWindow().widget()
    corner = area.mapTo(window, QtCore.QPoint(0, 0))
    rendered = os.path.join(OUT, "view_in_window.png")
    view.saveImage(rendered, area.width(), area.height(), "White")
    picture = window.grab()
    painter = QtGui.QPainter(picture)
    painter.drawImage(corner, QtGui.QImage(rendered))
    painter.end()
    picture.save(path)


def shoot():
    Gui.activateWorkbench("PopUpWorkbench")
    doc = FreeCAD.openDocument(os.environ["POPUP_SHOT_CARD"])
    card = next(
        o for o in doc.Objects if o.TypeId == "Part::FeaturePython" and hasattr(o, "Validity")
    )
    card.FoldAngle = float(os.environ.get("POPUP_SHOT_ANGLE", "110"))
    doc.recompute()
    from popupwb.validity.check import run_check

    report = run_check(card)
    view = Gui.ActiveDocument.ActiveView
    view.viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    for _ in range(20):
        QtGui.QApplication.processEvents()
    view.saveImage(os.path.join(OUT, "view.png"), 1200, 800, "White")
    save_window(view, os.path.join(OUT, "window.png"))
    RESULT.update(
        freecad=".".join(FreeCAD.Version()[:3]),
        qt=QtCore.qVersion(),
        workbench=Gui.activeWorkbench().name(),
        card=card.Label,
        validity=card.Validity,
        valid=bool(report.get("valid")),
        popup_commands=sorted(c for c in Gui.listCommands() if c.startswith("PopUp_")),
    )


def run():
    try:
        shoot()
    except Exception:
        RESULT["errors"].append(traceback.format_exc())
    with open(os.path.join(OUT, "result.json"), "w") as handle:
        json.dump(RESULT, handle, indent=1)
    for name in list(FreeCAD.listDocuments()):
        FreeCAD.closeDocument(name)
    QtCore.QTimer.singleShot(0, Gui.getMainWindow().close)


QtCore.QTimer.singleShot(2000, run)
