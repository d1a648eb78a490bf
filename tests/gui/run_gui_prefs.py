"""GUI test: Edit › Preferences › PopUp in the real FreeCAD GUI under Xvfb.

Opens FreeCAD's preferences dialog (Std_DlgPreferences), finds the PopUp group and page, types
values into it and presses OK, then reads the parameters back from FreeCAD's user.cfg; opens the
dialog again to see them loaded and to try an empty layer name (refused, one line in the report
view, the stored name kept); creates a card and a cutting sheet with the toolbar commands and reads
the preferences off their properties; exports and reads the DXF's layers. Then checks a box fold
card with a step fold inside the box and reads the maker names of its patches in the report view.
Screenshots of the page go to <build>/sandbox/gui_prefs/. Run by ctest (gui_prefs); by hand:

    /usr/bin/python3 tests/gui/run_gui_prefs.py
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_harness import Checks, run_macro  # noqa: E402

MACRO = r'''
import popupwb.preferences as prefs

TYPED = {"Kerf": 0.25, "TabWidth": 6.0, "PaperThickness": 0.3, "CutLayerName": "Schnitt",
         "CutLayerColour": [255, 0, 255], "CardPreset": "A6", "SheetPaper": "A3",
         "ExportFolder": CONFIG["out_dir"]}


def preferences_dialog():
    for widget in QtGui.QApplication.topLevelWidgets():
        if widget.inherits("Gui::Dialog::DlgPreferencesImp") and widget.isVisible():
            return widget
    return None


def with_dialog(act):
    """Opens Edit › Preferences and runs act(dialog, page) inside its event loop."""
    state = {}

    def inside():
        dialog = preferences_dialog()
        if dialog is None:
            QtCore.QTimer.singleShot(200, inside)
            return
        try:
            page = dialog.findChild(QtGui.QWidget, "PopUpPreferences")
            state["page_found"] = page is not None
            state["groups"] = [
                view.item(i).text()
                for view in dialog.findChildren(QtGui.QListWidget)
                for i in range(view.count())
            ]
            act(dialog, page, state)
        except Exception:
            result["errors"].append(traceback.format_exc())
            dialog.reject()

    QtCore.QTimer.singleShot(500, inside)
    Gui.runCommand("Std_DlgPreferences", 0)
    return state


def show_page(dialog, page):
    # The group list on the left: select PopUp so the page is on screen for the screenshot.
    for view in dialog.findChildren(QtGui.QListWidget):
        for i in range(view.count()):
            if view.item(i).text() == "PopUp":
                view.setCurrentRow(i)
    QtCore.QCoreApplication.processEvents()


def type_values(dialog, page, state):
    show_page(dialog, page)
    page.findChild(QtGui.QDoubleSpinBox, "Kerf").setValue(TYPED["Kerf"])
    page.findChild(QtGui.QDoubleSpinBox, "TabWidth").setValue(TYPED["TabWidth"])
    page.findChild(QtGui.QDoubleSpinBox, "PaperThickness").setValue(TYPED["PaperThickness"])
    page.findChild(QtGui.QLineEdit, "CutLayerName").setText(TYPED["CutLayerName"])
    page.findChild(QtGui.QPushButton, "CutLayerColour").set_rgb(TYPED["CutLayerColour"])
    preset = page.findChild(QtGui.QComboBox, "CardPreset")
    preset.setCurrentIndex(preset.findText(TYPED["CardPreset"]))
    page.findChild(QtGui.QComboBox, "SheetPaper").setEditText(TYPED["SheetPaper"])
    page.findChild(QtGui.QLineEdit, "ExportFolder").setText(TYPED["ExportFolder"])
    state["visible"] = page.isVisible()
    dialog.grab().save(os.path.join(CONFIG["out_dir"], "preferences_page.png"))
    dialog.accept()  # OK: FreeCAD calls saveSettings


def read_back_and_break(dialog, page, state):
    show_page(dialog, page)
    state["loaded_kerf"] = page.findChild(QtGui.QDoubleSpinBox, "Kerf").value()
    state["loaded_cut_name"] = page.findChild(QtGui.QLineEdit, "CutLayerName").text()
    state["loaded_colour"] = list(page.findChild(QtGui.QPushButton, "CutLayerColour").rgb)
    page.findChild(QtGui.QLineEdit, "CutLayerName").setText("")
    page.findChild(QtGui.QDoubleSpinBox, "TabWidth").setValue(8.0)  # back to the default
    dialog.accept()


def stored():
    group = FreeCAD.ParamGet(prefs.PARAMETER_GROUP)
    values = prefs.stored(group)
    return {k: list(v) if isinstance(v, tuple) else v for k, v in values.items()}


def cfg_text():
    FreeCAD.saveParameter()
    with open(FreeCAD.ConfigGet("UserParameter")) as stream:
        return stream.read()


def run():
    result["stored_before"] = stored()
    first = with_dialog(type_values)
    result["first"] = first
    result["stored_after_ok"] = stored()
    result["cfg_has_kerf"] = 'FCFloat Name="Kerf" Value="0.25' in cfg_text()
    second = with_dialog(read_back_and_break)
    result["second"] = second
    result["stored_after_bad"] = stored()
    wait_until(lambda: "PopUp preference CutLayerName" in report_view_text(), 5000)
    result["report_view"] = report_view_text()

    Gui.runCommand("PopUp_Card", 0)
    card = FreeCAD.ActiveDocument.getObject("Card")
    result["card"] = {"preset": card.Preset, "thickness": card.PaperThickness.Value,
                      "width": card.Width.Value}
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(card)
    Gui.runCommand("PopUp_CuttingSheet", 0)
    sheet = FreeCAD.ActiveDocument.getObject("CardSheets")
    result["sheet"] = {"paper": sheet.Paper, "kerf": sheet.Kerf.Value,
                       "tab_width": sheet.TabWidth.Value, "state": list(sheet.State)}
    from popupwb.features.cutting_sheet import export_cutting_sheet
    paths = export_cutting_sheet(sheet, CONFIG["out_dir"], style=prefs.read().style)
    import ezdxf
    layers = ezdxf.readfile(paths["dxf"]).layers
    result["dxf_layers"] = {layer.dxf.name: layer.dxf.color for layer in layers}

    # Maker names (issue 11, item 6): a box fold with a step fold inside it, checked from the
    # toolbar; the report view and the card's Diagnostics name the patches as a maker does.
    from popupwb import make
    doc = FreeCAD.newDocument("names")
    card = make.make_card(doc, preset="A5")
    box = make.make_box_fold(card)
    make.make_step_fold(card, offset=box.Offset.Value)  # inside the box, not placed beside it
    doc.recompute()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(card)
    Gui.runCommand("PopUp_CheckValidity", 0)
    wait_until(lambda: "Step fold 'StepFold'" in report_view_text(), 10000)
    result["names_report_view"] = report_view_text()
    result["names_diagnostics"] = list(card.Diagnostics)
    Gui.getMainWindow().grab().save(os.path.join(CONFIG["out_dir"], "maker_names.png"))
'''


def main():
    check = Checks("gui_prefs")
    code, result, out_dir = run_macro("gui_prefs", MACRO)
    check("FreeCAD ran the macro", result is not None, f"exit {code}, see {out_dir}")
    if result is None:
        return check.exit_code()
    check("no errors in the macro", not result["errors"], "\n".join(result["errors"]))
    first, second = result.get("first", {}), result.get("second", {})
    check("a fresh home stores no PopUp preference", result.get("stored_before") == {})
    check("the PopUp group is in the dialog's list", "PopUp" in first.get("groups", []))
    check("the PopUp page is in the dialog", first.get("page_found") and first.get("visible"))
    after = result.get("stored_after_ok", {})
    expected = {
        "Kerf": 0.25,
        "TabWidth": 6.0,
        "PaperThickness": 0.3,
        "CutLayerName": "Schnitt",
        "CutLayerColour": [255, 0, 255],
        "CardPreset": "A6",
        "SheetPaper": "A3",
        "ExportFolder": out_dir,
    }
    # Only what differs from the built-in defaults is stored (TabAngle, the other layers: not).
    check("OK stores exactly the changed values", after == expected, f"{after}")
    check("user.cfg on disk holds them", result.get("cfg_has_kerf"))
    check(
        "the page loads what is stored",
        (second.get("loaded_kerf"), second.get("loaded_cut_name"), second.get("loaded_colour"))
        == (0.25, "Schnitt", [255, 0, 255]),
        f"{second}",
    )
    bad = result.get("stored_after_bad", {})
    check("an empty layer name is not stored", bad.get("CutLayerName") == "Schnitt", f"{bad}")
    check("a value set back to its default is removed", "TabWidth" not in bad, f"{bad}")
    lines = [
        line
        for line in result.get("report_view", "").splitlines()
        if "PopUp preference CutLayerName = ''" in line
    ]
    check("the report view says why, in one line", len(lines) == 1, f"{lines}")
    check("no traceback in the report view", "Traceback" not in result.get("report_view", ""))
    check("the group has its icon", "preferences-popup" not in result.get("report_view", ""))
    card = result.get("card", {})
    # A6 folded in half across its long side: 105 mm along the fold (card_feature.PRESETS).
    check(
        "PopUp_Card uses the preset and thickness",
        (card.get("preset"), card.get("thickness"), card.get("width")) == ("A6", 0.3, 105.0),
        f"{card}",
    )
    sheet = result.get("sheet", {})
    check(
        "PopUp_CuttingSheet uses the paper and kerf (tab width back to default)",
        (sheet.get("paper"), sheet.get("kerf"), sheet.get("tab_width")) == ("A3", 0.25, 8.0),
        f"{sheet}",
    )
    layers = result.get("dxf_layers", {})
    # ACI 6 is magenta (255, 0, 255) in AutoCAD's palette.
    check("the exported DXF has the cut layer's name and colour", layers.get("Schnitt") == 6)
    check("the other layers keep their names", "MOUNTAIN" in layers and "CUT" not in layers)
    # The box's top (ground half) is patch 5: after the card's two pages and the box's centre
    # wall and two side walls (parallel_box.cpp's order C, L, R, TG).
    top = "Box fold 'BoxFold': top, ground side [#5 BoxFold.TG] passes through Step fold"
    diagnostics = result.get("names_diagnostics", [])
    check("the card's Diagnostics use the maker names", any(top in d for d in diagnostics))
    check("the report view uses the maker names", top in result.get("names_report_view", ""))
    return check.exit_code()


if __name__ == "__main__":
    sys.exit(main())
