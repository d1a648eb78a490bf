"""Writes the legacy documents tests/data/legacy_card*.FCStd: an A5 card, a tent fold on its
central fold and a CuttingSheet with one TechDraw page, made with the workbench as it was before
the "house" changes (features importing view providers, popupwb.assembly), at commit ea71710.

They pin what .FCStd files store: proxy module paths and class names of the features
(Document.xml) and, for the GUI variant, of the view providers (GuiDocument.xml). Tests open them
with today's code and expect every proxy back. Do not regenerate them with newer code: that would
test nothing. How they were made (from a worktree at ea71710, after `make build`):

    headless:  B=$PWD/build PYTHONPATH=$B/python:$PWD/Workbench:/usr/lib/freecad-python3/lib \
               /usr/bin/python3 tests/data/make_legacy_card.py tests/data/legacy_card.FCStd
    GUI:       H=/tmp/legacy/home; mkdir -p $H/Mod; ln -s $PWD/Workbench $H/Mod/PopUp
               cp tests/data/make_legacy_card.py /tmp/legacy/make_legacy_card.FCMacro
               QTWEBENGINE_DISABLE_SANDBOX=1 FREECAD_USER_HOME=$H HOME=$H POPUP_BUILD_DIR=$B \
               POPUP_LEGACY_OUT=$PWD/tests/data/legacy_card_gui.FCStd \
               xvfb-run -a -s "-screen 0 1280x1024x24" freecad /tmp/legacy/make_legacy_card.FCMacro

legacy_card.FCStd (12 kB) stores the feature proxies popupwb.features.card_feature.PopUpCard,
.tent_fold.TentFold and .cutting_sheet.CuttingSheet; legacy_card_gui.FCStd (15 kB) also the view
providers popupwb.viewproviders.card_viewprovider.CardViewProvider,
.mechanism_viewprovider.MechanismViewProvider and .cutting_sheet_viewprovider.
CuttingSheetViewProvider. Neither names popupwb.assembly.
"""

import os
import sys

import FreeCAD


def build(path):
    from popupwb import make

    doc = FreeCAD.newDocument("LegacyCard")
    card = make.make_card(doc, preset="A5", name="Card")
    make.make_tent_fold(
        card, "central fold", offset=50, width=40, foot=20, foot_backdrop=20, slope=30, name="Tent"
    )
    doc.recompute()
    make.make_cutting_sheet(card, paper="A4", name="CuttingSheet")
    doc.recompute()
    broken = [o.Name for o in doc.Objects if "Invalid" in o.State]
    if broken:
        raise RuntimeError(f"objects in error: {broken}")
    doc.saveAs(os.path.abspath(path))
    FreeCAD.closeDocument(doc.Name)


if FreeCAD.GuiUp:
    import FreeCADGui
    from PySide import QtCore

    try:
        build(os.environ["POPUP_LEGACY_OUT"])
    finally:
        QtCore.QTimer.singleShot(0, FreeCADGui.getMainWindow().close)
elif __name__ == "__main__":
    build(sys.argv[1])
