"""GUI test (ctest gui_techdraw): cutting-sheet TechDraw pages as a maker meets them, and the
refuse-unless-forced rule of PopUp_CuttingSheet and PopUp_ExportSheets.

1. An A5 card whose tent sticks out of the closed card (not enclosed): PopUp_CuttingSheet refuses
   it with one line, selects the tent's faces, and leaves Export disabled; Force lays it out with
   the NOT VALID stamp on the page and enables Export.
2. An A4 card with a tent and a box on A3: its page holds a template of the paper with the title
   block's texts, one symbol view with the glue areas and labels, and a part view whose edges
   TechDraw itself exports in the cut colour (TechDrawGui.exportPageAsSvg); no view frames; the
   objects per page do not grow with the labels; opened, the page is fitted to its window.
The fitted page window is saved as techdraw_sheet.png in the output folder (docs/images/ keeps a
copy).
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import gui_harness  # noqa: E402

NAME = "gui_techdraw"

BODY = r"""
import xml.etree.ElementTree as ElementTree

SVG = "{http://www.w3.org/2000/svg}"
# Closed, this tent ends 30 + 80 = 110 mm from the fold of an A5 card's 105 mm pages.
TALL_TENT = dict(offset=40.0, width=60.0, foot=30.0, foot_backdrop=30.0, slope=80.0)
TENT = dict(offset=20.0, width=50.0, foot=20.0, foot_backdrop=20.0, slope=30.0)
BOX = dict(offset=110.0, width=60.0, depth_ground=30.0, depth_backdrop=30.0, height=30.0)


def symbol_texts(page):
    (marks,) = [v for v in page.Views if v.TypeId == "TechDraw::DrawViewSymbol"]
    root = ElementTree.fromstring(marks.Symbol)
    return [t.text for t in root.iter(SVG + "text")], root


def cutting_sheet_of(doc):
    return next(o for o in doc.Objects if "SheetSetJson" in o.PropertiesList)


def refused_then_forced():
    from popupwb import make
    from popupwb.sheets.techdraw_pages import pages_of

    export = Gui.Command.get("PopUp_ExportSheets")
    doc = FreeCAD.newDocument("TechDrawRefused")
    result["export_active_without_sheet"] = export.isActive()
    card = make.make_card(doc, preset="A5")
    tent = make.make_tent_fold(card, name="TallTent", **TALL_TENT)
    doc.recompute()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(card)
    before = report_view_text()
    Gui.runCommand("PopUp_CuttingSheet")
    sheet = cutting_sheet_of(doc)
    wait_until(lambda: False, 300)  # the report view appends queued messages on events
    new_text = report_view_text()[len(before):]
    result["refused"] = {
        "state": sorted(sheet.State),
        "pages": len(pages_of(sheet)),
        "export_active": export.isActive(),
        # The command's own line (a recompute traceback, if any, is another item's to remove).
        "refusal_lines": [
            l for l in new_text.splitlines() if re.match(r"^[0-9:]{8}  CardSheets: the card", l)
        ],
        "traceback": "Traceback" in new_text,
        "selection": [
            [s.Object.Name, list(s.SubElementNames)] for s in Gui.Selection.getSelectionEx()
        ],
        "tent_faces": len(tent.Shape.Faces),
        "report": new_text,
    }
    sheet.Force = True
    doc.recompute()
    pages = pages_of(sheet)
    result["forced"] = {
        "state": sorted(sheet.State),
        "pages": len(pages),
        "stamped": [symbol_texts(p)[0].count(sheet.NotValid) for p in pages],
        "not_valid": sheet.NotValid,
        "export_active": export.isActive(),
    }
    FreeCAD.closeDocument(doc.Name)


def page_window(page):
    # The page's MDI sub-window and its QGraphicsView (TechDraw names it after the page).
    mdi = Gui.getMainWindow().findChild(QtGui.QMdiArea)
    for sub in mdi.subWindowList():
        graphics = sub.findChild(QtGui.QGraphicsView, page.Name)
        if graphics is not None:
            return sub, graphics
    return None, None


def open_page(page):
    # Opens the page's window as a double-click in the tree does; returns (sub-window, view).
    page.ViewObject.doubleClicked()
    wait_until(lambda: False, 500)
    sub, graphics = page_window(page)
    # Xvfb has no window manager to bring the new window to the front, as a maker's screen does.
    Gui.getMainWindow().findChild(QtGui.QMdiArea).setActiveSubWindow(sub)
    wait_until(lambda: False, 1000)
    return sub, graphics


def valid_page():
    import TechDrawGui
    from popupwb import make
    from popupwb.sheets.techdraw_pages import page_objects, pages_of

    doc = FreeCAD.newDocument("TechDrawSheet")
    card = make.make_card(doc, preset="A4")
    card.Label = "Birthday card"
    make.make_tent_fold(card, name="Tent", **TENT)
    make.make_box_fold(card, name="Box", **BOX)
    doc.recompute()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(card)
    Gui.runCommand("PopUp_CuttingSheet")
    sheet = cutting_sheet_of(doc)
    sheet_set = json.loads(sheet.SheetSetJson)
    (page,) = pages_of(sheet)
    (view,) = [v for v in page.Views if v.TypeId == "TechDraw::DrawViewPart"]
    texts, marks = symbol_texts(page)
    glue = [area for piece in sheet_set["pieces"] for area in piece["glue"]]
    labels = [label["text"] for piece in sheet_set["pieces"] for label in piece["labels"]]
    glue_layer = next(g for g in marks.iter(SVG + "g") if g.get("id") == "GLUE")
    out = {
        "state": sorted(sheet.State),
        "paper": sheet.Paper,
        "views": sorted(v.TypeId for v in page.Views),
        "page_objects": len(page_objects(page)),
        "tree_objects": len(doc.Objects),
        "labels": len(labels),
        "symbol_texts_are_labels": texts == labels,
        "glue_areas": len(glue),
        "glue_paths": [p.get("fill") for p in glue_layer.iter(SVG + "path")],
        "editable_texts": dict(page.Template.EditableTexts),
        "cut_edges": len(view.getVisibleEdges()),
        "folds": sum(len(piece["folds"]) for piece in sheet_set["pieces"]),
        "cosmetic_colours": sorted({tuple(e.Format[2][:3]) for e in view.CosmeticEdges}),
        "cut_loops": sum(
            1 + len(region["holes"]) for piece in sheet_set["pieces"] for region in piece["cut_nominal"]
        ),
    }
    sub, graphics = open_page(page)
    out["window_title"] = sub.windowTitle()
    out["show_frames_after_make"] = page.ViewObject.ShowFrames
    opened = graphics.transform().m11()
    views = Gui.getDocument(doc.Name).mdiViewsOfType("Gui::MDIView")
    (page_view,) = [v for v in views if hasattr(v, "getPage")]
    page_view.fitAll()
    wait_until(lambda: False, 300)
    out["zoom_opened"], out["zoom_fit_all"] = opened, graphics.transform().m11()
    shot = os.path.join(CONFIG["out_dir"], "techdraw_sheet.png")
    sub.grab().save(shot)
    out["screenshot"] = shot
    count_non_white(shot, "shot_", out)
    # As a document saved without the GUI opens: frames on. Opening the page must drop them.
    sub.close()
    wait_until(lambda: False, 300)
    page.ViewObject.ShowFrames = True
    sub, graphics = open_page(page)
    out["show_frames_after_open"] = page.ViewObject.ShowFrames
    sub.grab().save(os.path.join(CONFIG["out_dir"], "techdraw_sheet_reopened.png"))
    exported = os.path.join(CONFIG["out_dir"], "page.svg")
    TechDrawGui.exportPageAsSvg(page, exported)
    root = ElementTree.parse(exported).getroot()
    strokes = {}
    for element in root.iter():
        colour = element.get("stroke")
        if colour:
            strokes[colour] = strokes.get(colour, 0) + 1
    out["exported_strokes"] = strokes
    out["exported_fills"] = sorted({e.get("fill") for e in root.iter() if e.get("fill")})
    # More labels (fold hints) bring no more objects.
    sheet.FoldHints = True
    doc.recompute()
    out["labels_with_hints"] = len(symbol_texts(page)[0])
    out["tree_objects_with_hints"] = len(doc.Objects)
    result["page"] = out
    FreeCAD.closeDocument(doc.Name)


def run():
    refused_then_forced()
    valid_page()
"""


def main():
    code, result, out_dir = gui_harness.run_macro(NAME, BODY)
    check = gui_harness.Checks(NAME)
    check("FreeCAD exited cleanly", code == 0, f"exit code {code}")
    if result is None:
        check("the macro wrote its result", False, out_dir)
        return check.exit_code()
    check("no errors in the macro", not result["errors"], "\n".join(result["errors"]))
    refused, forced, page = result.get("refused", {}), result.get("forced", {}), result.get("page")
    check(
        "Export disabled without a cutting sheet",
        result.get("export_active_without_sheet") is False,
    )
    check("an invalid card is refused", "Invalid" in refused.get("state", []), refused.get("state"))
    check("refused: no pages", refused.get("pages") == 0)
    check("refused: Export disabled", refused.get("export_active") is False)
    lines = refused.get("refusal_lines", [])
    check(
        "refused: one line naming the card, NOT VALID and Force",
        len(lines) == 1 and "the card Card is NOT VALID: not enclosed" in lines[0],
        lines,
    )
    selection = refused.get("selection")
    tent_faces = [f"Face{n + 1}" for n in range(refused.get("tent_faces", 0))]
    check(
        "refused: the tent's faces are selected",
        selection
        and [name for name, _ in selection] == ["TallTent"]
        and sorted(selection[0][1]) == sorted(tent_faces)
        and tent_faces,
        selection,
    )
    check("forced: laid out", forced.get("state") == ["Up-to-date"], forced.get("state"))
    check(
        "forced: each page stamped once",
        forced.get("pages", 0) >= 1 and set(forced.get("stamped", [])) == {1},
        forced,
    )
    check("forced: Export enabled", forced.get("export_active") is True)
    if not page:
        check("the page run finished", False)
        return check.exit_code()
    check("valid card laid out", page["state"] == ["Up-to-date"], page["state"])
    check(
        "page views: one part view, one symbol view",
        page["views"] == ["TechDraw::DrawViewPart", "TechDraw::DrawViewSymbol"],
        page["views"],
    )
    check("5 objects per page", page["page_objects"] == 5, page["page_objects"])
    check(
        "labels are in the symbol, not objects",
        page["symbol_texts_are_labels"]
        and page["labels_with_hints"] > page["labels"]
        and page["tree_objects_with_hints"] == page["tree_objects"],
        (page["labels"], page["labels_with_hints"], page["tree_objects"]),
    )
    check(
        "glue areas drawn, filled grey",
        page["glue_areas"] > 0 and page["glue_paths"] == ["rgb(217,217,217)"] * page["glue_areas"],
        page["glue_paths"],
    )
    check(
        "title block texts",
        page["editable_texts"]
        == {
            "CardName": "Birthday card",
            "Paper": "A3 297 x 420 mm",
            "Sheet": "1 of 1",
            "Scale": "1:1",
        },
        page["editable_texts"],
    )
    strokes = page["exported_strokes"]
    # Qt's SVG writer joins edges into paths: at least one red path per cut loop, and no stroke
    # but the sheet colours (cut, mountain, valley, glue outline) and the labels' black.
    sheet_colours = {"#ff0000", "#0000ff", "#00ff00", "#808080", "#000000", "black", "none"}
    check(
        "TechDraw exports the cut edges red",
        strokes.get("#ff0000", 0) >= page["cut_loops"] > 0 and set(strokes) <= sheet_colours,
        (strokes, page["cut_loops"]),
    )
    check(
        "folds blue (mountain) and green (valley)",
        page["folds"] > 0 and page["cosmetic_colours"] == [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0]],
        page["cosmetic_colours"],
    )
    check("exported page shows the glue fill", "#d9d9d9" in page["exported_fills"])
    check("no view frames when opened", page["show_frames_after_make"] is False)
    check(
        "no view frames when a headless file's page opens", page["show_frames_after_open"] is False
    )
    check(
        "page fitted to its window when opened",
        abs(page["zoom_opened"] - page["zoom_fit_all"]) < 0.01 * page["zoom_fit_all"],
        (page["zoom_opened"], page["zoom_fit_all"]),
    )
    check("screenshot has content", page["shot_tinted_pixels"] > 1000, page["shot_tinted_pixels"])
    print("screenshot:", page["screenshot"])
    return check.exit_code()


if __name__ == "__main__":
    sys.exit(main())
