#!/usr/bin/python3
"""GUI test (ctest gui_view): what a maker sees of a card in FreeCAD's GUI under Xvfb.

  - Files saved headless (the demo's card.FCStd, built by tools/run_demo.py, and a script's file
    with a card, a mechanism, a Scaffold and a cutting sheet) open with the card, its mechanisms
    and the Scaffold shown, the cutting sheet and its page outlines hidden; a file saved in the
    GUI keeps a mechanism its user hid.
  - Each patch is drawn once: the card shows its two pages, each mechanism its own patches
    (together: every patch of the scaffold). Selecting a mechanism paints its faces in the
    selection colour, hiding it takes its pixels off the screen, and a mechanism in error shows
    no shape and is marked in error (state and tree icon).
  - An invalid card: Validity goes NotChecked -> Invalid -> NotChecked (design changed) -> Valid;
    the check leaves nothing selected; with the card selected and with the offending mechanism
    selected, red offending faces or outlines stay on screen; the tree icon carries the verdict.
    Saves invalid_card_selected.png (800x600, card selected) in its sandbox folder, and with
    --update-docs, when every check passed, copies it to docs/images/.

    POPUP_SOURCE_DIR=. POPUP_BUILD_DIR=build /usr/bin/python3 tests/gui/run_gui_view.py [--update-docs]
"""

import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gui_harness  # noqa: E402

sys.path.insert(0, os.path.join(gui_harness.SOURCE_DIR, "tools"))
import run_demo  # noqa: E402

IMAGE_NAME = "invalid_card_selected.png"
DOCS_IMAGE = os.path.join(gui_harness.SOURCE_DIR, "docs", "images", IMAGE_NAME)

# A script's file: a card with a tent, a Scaffold of a design file and a cutting sheet, saved
# headless (so without GuiDocument.xml).
HEADLESS_SCRIPT = r"""
import sys
import FreeCAD
from popupwb import make
doc = FreeCAD.newDocument("Headless")
card = make.make_card(doc, preset="A5", name="Card")
make.make_tent_fold(card, name="Tent")
make.make_scaffold(doc, sys.argv[2], name="Scaffold")
doc.recompute()
make.make_cutting_sheet(card, paper="A4", name="CuttingSheet")
doc.recompute()
doc.saveAs(sys.argv[1])
"""

BODY = r"""
SELECTION_GREEN = (28, 173, 28)


def pixels(path):
    # Counts of red (offending), selection-green and non-white pixels of a screenshot.
    image = QtGui.QImage(path)
    red = green = inked = 0
    for y in range(image.height()):
        for x in range(image.width()):
            rgb = image.pixel(x, y) & 0xFFFFFF
            r, g, b = rgb >> 16, (rgb >> 8) & 0xFF, rgb & 0xFF
            inked += rgb != 0xFFFFFF
            red += r > 150 and g < 90 and b < 90
            green += g > 120 and r < 90 and b < 90
    return {"red": red, "green": green, "inked": inked, "size": [image.width(), image.height()]}


def changed_pixels(name_a, name_b):
    # Pixels that differ between two screenshots of the same size.
    a, b = (QtGui.QImage(os.path.join(CONFIG["out_dir"], n + ".png")) for n in (name_a, name_b))
    return sum(
        a.pixel(x, y) != b.pixel(x, y) for y in range(a.height()) for x in range(a.width())
    )


def shot(name, width=400, height=300):
    Gui.updateGui()
    path = os.path.join(CONFIG["out_dir"], name + ".png")
    save_screenshot(path, width, height)
    return pixels(path)


def tree_icon_colours(obj):
    # Red and green pixels of the icon the tree shows for `obj` (its verdict badge).
    for tree in Gui.getMainWindow().findChildren(QtGui.QTreeWidget):
        items = tree.findItems(obj.Label, QtCore.Qt.MatchExactly | QtCore.Qt.MatchRecursive)
        if items:
            image = items[0].icon(0).pixmap(32, 32).toImage()
            red = green = 0
            for y in range(image.height()):
                for x in range(image.width()):
                    pixel = image.pixel(x, y)
                    if (pixel >> 24) < 128:
                        continue
                    r, g, b = (pixel >> 16) & 0xFF, (pixel >> 8) & 0xFF, pixel & 0xFF
                    red += r > 180 and g < 80 and b < 80
                    green += g > 120 and r < 90 and b < 110
            pixels = [image.pixel(x, y) for y in range(image.height()) for x in range(image.width())]
            return {"red": red, "green": green, "key": hash(tuple(pixels))}
    return None


def visibilities(doc):
    return {o.Name: bool(o.ViewObject.Visibility) for o in doc.Objects if o.ViewObject}


def opened(path):
    doc = FreeCAD.openDocument(path)
    Gui.updateGui()
    wait_until(lambda: False, 300)
    return doc


def view_of(doc):
    view = Gui.getDocument(doc.Name).mdiViewsOfType("Gui::View3DInventor")[0]
    Gui.getMainWindow().setActiveWindow(view)
    view.viewIsometric()
    view.fitAll()
    return view


def open_headless_files():
    from popupwb.model import card_scaffold
    from popupwb.sheets.techdraw_pages import page_objects, pages_of

    for key in ("demo", "script"):
        doc = opened(CONFIG[key])
        visible = visibilities(doc)
        out = {"visible": visible}
        cards = [o for o in doc.Objects if card_scaffold.is_card(o)]
        designs = cards + [m for c in cards for m in card_scaffold.mechanisms_of(c)]
        designs += [o for o in doc.Objects if "DesignFile" in o.PropertiesList]
        sheets = [o for o in doc.Objects if o.TypeId == "Part::FeaturePython" and "PieceCount" in o.PropertiesList]
        outlines = [
            o for s in sheets for p in pages_of(s) for o in page_objects(p)
            if o.TypeId == "Part::Feature"
        ]
        out["designs"] = sorted(o.Name for o in designs)
        out["designs_shown"] = all(visible[o.Name] for o in designs)
        out["sheets"] = sorted(o.Name for o in sheets + outlines)
        out["sheets_hidden"] = not any(visible[o.Name] for o in sheets + outlines)
        view_of(doc)
        out["pixels"] = shot("opened_" + key)
        result[key] = out
        if key == "script":
            # Saved in the GUI with the tent hidden: it opens hidden (the user's choice).
            doc.getObject("Tent").ViewObject.Visibility = False
            gui_saved = os.path.join(CONFIG["out_dir"], "gui_saved.FCStd")
            doc.saveAs(gui_saved)
            FreeCAD.closeDocument(doc.Name)
            doc = opened(gui_saved)
            result["gui_saved"] = visibilities(doc)
        FreeCAD.closeDocument(doc.Name)


def one_object_per_thing():
    from popupwb import make
    from popupwb.model import card_scaffold

    doc = FreeCAD.newDocument("Once")
    card = make.make_card(doc, width=240.0, depth=140.0, name="Card")
    box = make.make_box_fold(
        card, name="Box", offset=60.0, width=100.0, depth_ground=30.0, depth_backdrop=30.0,
        height=30.0,
    )
    tent = make.make_tent_fold(
        box, host_pair="Box.top", name="Tent", offset=10.0, width=40.0, foot=10.0,
        foot_backdrop=10.0, slope=14.0,
    )
    v_fold = make.make_v_fold(
        card, name="VFold", offset=25.0, run=40.0, hinge_angle=45.0, spine=45.0, spine_angle=60.0
    )
    card.FoldAngle = 120.0
    doc.recompute()
    view_of(doc)
    built = card_scaffold.for_card(card)
    features = [card, box, tent, v_fold]
    out = {
        "faces": {o.Name: len(o.Shape.Faces) for o in features},
        "patches": len(built.scaffold.patches),
        "owned": {o.Name: len(built.patches[o.Name]) for o in features},
        "colours": {o.Name: len(o.ViewObject.DiffuseColor) for o in features},
    }
    Gui.Selection.clearSelection()
    out["none_selected"] = shot("none_selected")
    Gui.Selection.addSelection(box)
    out["box_selected"] = shot("box_selected")
    Gui.Selection.clearSelection()
    box.ViewObject.Visibility = False
    out["box_hidden"] = shot("box_hidden")
    out["box_hidden_changed"] = changed_pixels("none_selected", "box_hidden")
    box.ViewObject.Visibility = True
    # A tent refused by the core: no stale tent, in error, marked in the tree.
    icon_before = tree_icon_colours(tent)
    tent.Foot = -3.0
    doc.recompute()
    Gui.updateGui()
    # The tree redraws its icons from the event loop.
    wait_until(lambda: tree_icon_colours(tent)["key"] != icon_before["key"], 3000)
    out["tent_error"] = {
        "null_shape": tent.Shape.isNull(),
        "state": list(tent.State),
        "status": tent.getStatusString(),
        "card_state": list(card.State),
        "icon_changed": icon_before is not None
        and tree_icon_colours(tent)["key"] != icon_before["key"],
    }
    out["tent_error_pixels"] = shot("tent_in_error")
    tent.Foot = 10.0
    doc.recompute()
    out["tent_fixed"] = {"faces": len(tent.Shape.Faces), "state": list(tent.State)}
    result["once"] = out
    return doc, card, box, v_fold


def invalid_card(doc, card, box, v_fold):
    from popupwb.commands import check_validity
    from popupwb.viewproviders import offending_overlay

    out = {"before": [card.Validity, card.Valid], "icon_before": tree_icon_colours(card)}
    v_fold.Offset = 180.0  # beside the box's back: its back panels run into the v
    doc.recompute()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(card)
    Gui.runCommand(check_validity.COMMAND_ID)
    Gui.updateGui()
    wait_until(lambda: tree_icon_colours(card)["red"] > 20, 3000)
    out["checked"] = list(check_validity.last_checked)
    out["after_check"] = [card.Validity, card.Valid, len(card.Diagnostics)]
    out["selection_after_check"] = [o.Name for o in Gui.Selection.getSelection()]
    out["icon_invalid"] = tree_icon_colours(card)
    out["icon_file"] = os.path.basename(card.ViewObject.Proxy.getIcon())
    red = (0.90, 0.10, 0.10)
    out["red_faces"] = {
        o.Name: sum(1 for c in o.ViewObject.DiffuseColor if c[:3] == pytest_approx(red))
        for o in (card, box, v_fold)
    }
    out["outlined_edges"] = {
        o.Name: offending_overlay.outlined_edge_count(o.ViewObject) for o in (card, box, v_fold)
    }
    root = box.ViewObject.RootNode
    out["root_children"] = [
        str(root.getChild(i).getName()) or str(root.getChild(i).getTypeId().getName())
        for i in range(root.getNumChildren())
    ]
    out["unselected"] = shot("invalid_unselected")
    Gui.Selection.addSelection(card)
    out["card_selected"] = shot("invalid_card_selected")
    save_screenshot(CONFIG["image"], 800, 600)
    out["image"] = pixels(CONFIG["image"])
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(box)
    out["box_selected"] = shot("invalid_box_selected")
    # Without the red v-fold in the picture, the red left is the box's outlines over its
    # selection colour.
    v_fold.ViewObject.Visibility = False
    out["box_selected_alone"] = shot("invalid_box_selected_alone")
    v_fold.ViewObject.Visibility = True
    Gui.Selection.clearSelection()
    box.ViewObject.Visibility = False
    out["box_hidden_outlines"] = shot("invalid_box_hidden")
    box.ViewObject.Visibility = True
    # Moved away: another design, the verdict is gone; checked again: valid.
    v_fold.Offset = 25.0
    doc.recompute()
    out["after_change"] = [card.Validity, card.Valid, len(card.Diagnostics)]
    out["icon_after_change"] = tree_icon_colours(card)
    Gui.runCommand(check_validity.COMMAND_ID)
    Gui.updateGui()
    out["after_recheck"] = [card.Validity, card.Valid, len(card.Diagnostics)]
    wait_until(lambda: tree_icon_colours(card)["green"] > 20, 3000)
    out["icon_valid"] = tree_icon_colours(card)
    out["outlines_after_recheck"] = offending_overlay.outlined_edge_count(box.ViewObject)
    result["invalid"] = out


def pytest_approx(colour):
    class Near:
        def __eq__(self, other):
            return all(abs(a - b) < 0.01 for a, b in zip(colour, other))

    return Near()


def run():
    open_headless_files()
    invalid_card(*one_object_per_thing())
"""


def build_inputs():
    """The demo's card.FCStd (tools/run_demo.py, headless) and a script's headless file."""
    inputs = os.path.join(gui_harness.SANDBOX, "view_inputs")
    shutil.rmtree(inputs, ignore_errors=True)
    os.makedirs(inputs)
    env = run_demo.sandbox_env(gui_harness.BUILD_DIR)
    paths, _report, _stdout = run_demo.build_card(gui_harness.BUILD_DIR, inputs, env)
    script = os.path.join(inputs, "headless.FCStd")
    design = os.path.join(gui_harness.SOURCE_DIR, "tests", "data", "tent_fold.json")
    subprocess.run(
        [run_demo.PYTHON, "-c", HEADLESS_SCRIPT, script, design],
        env=env,
        check=True,
        timeout=300,
    )
    return paths[0], script


def main():
    demo, script = build_inputs()
    image = os.path.join(gui_harness.SANDBOX, "view", IMAGE_NAME)
    code, r, out_dir = gui_harness.run_macro(
        "view", BODY, {"demo": demo, "script": script, "image": image}, timeout=400
    )
    check = gui_harness.Checks("gui_view")
    if r is None:
        check("the GUI macro wrote its result", False, f"exit {code}, see {out_dir}/freecad.log")
        return check.exit_code()
    check("the macro ran without errors", not r["errors"], "\n".join(r["errors"]))

    for key in ("demo", "script"):
        o = r.get(key) or {}
        check(
            f"{key}: card, mechanisms and Scaffolds open shown",
            o.get("designs") and o.get("designs_shown"),
            o.get("designs"),
        )
        check(
            f"{key}: cutting sheet and its page outlines open hidden",
            o.get("sheets") and o.get("sheets_hidden"),
            o.get("sheets"),
        )
        inked = (o.get("pixels") or {}).get("inked", 0)
        check(f"{key}: the 3D view shows the card", inked > 5000, f"{inked} non-white pixels")
    saved = r.get("gui_saved") or {}
    check(
        "a file saved in the GUI keeps a mechanism its user hid",
        saved.get("Tent") is False and saved.get("Card") is True,
        saved,
    )

    once = r.get("once") or {}
    faces, owned = once.get("faces") or {}, once.get("owned") or {}
    check(
        "each patch drawn once: card 2 faces, mechanisms their own, sum = scaffold patches",
        faces.get("Card") == 2 and faces == owned and sum(faces.values()) == once.get("patches"),
        f"{faces}, {once.get('patches')} patches",
    )
    check("faces coloured by role", once.get("colours") == faces, once.get("colours"))
    none, selected = once.get("none_selected") or {}, once.get("box_selected") or {}
    check(
        "selecting a mechanism paints its faces in the selection colour",
        selected.get("green", 0) > 1000 and none.get("green", 1) < 50,
        f"{none.get('green')} -> {selected.get('green')} green pixels",
    )
    check(
        "hiding a mechanism takes its faces off the screen",
        once.get("box_hidden_changed", 0) > 1000,
        f"{once.get('box_hidden_changed')} pixels changed",
    )
    error = once.get("tent_error") or {}
    check(
        "a mechanism in error shows no shape and is in error, the card is not",
        error.get("null_shape")
        and "Invalid" in error.get("state", [])
        and "Invalid" not in error.get("card_state", ["Invalid"]),
        error,
    )
    check("the tree icon of a mechanism in error changes", error.get("icon_changed"), error)
    fixed = once.get("tent_fixed") or {}
    check("fixed, the mechanism shows its patches again", fixed.get("faces") == 2, fixed)

    inv = r.get("invalid") or {}
    check("a new card is NotChecked", inv.get("before") == ["NotChecked", False], inv.get("before"))
    after = inv.get("after_check") or []
    check(
        "the check marks the card Invalid with findings",
        after[:2] == ["Invalid", False] and after[2] > 0 and inv.get("checked") == ["Card"],
        after,
    )
    check(
        "the check leaves nothing selected",
        inv.get("selection_after_check") == [],
        inv.get("selection_after_check"),
    )
    before, invalid = inv.get("icon_before") or {}, inv.get("icon_invalid") or {}
    check(
        "the tree marks the invalid card (red badge)",
        before.get("red", 1) == 0
        and invalid.get("red", 0) > 20
        and inv.get("icon_file") == "PopUp_CardInvalid.svg",
        f"{before} -> {invalid}, {inv.get('icon_file')}",
    )
    red_faces, outlined = inv.get("red_faces") or {}, inv.get("outlined_edges") or {}
    check(
        "offending patches red and outlined on the box and the v-fold",
        red_faces.get("Box", 0) > 0
        and red_faces.get("VFold", 0) > 0
        and outlined.get("Box", 0) > 0
        and outlined.get("VFold", 0) > 0,
        f"red faces {red_faces}, outlined edges {outlined}",
    )
    children = inv.get("root_children") or []
    check(
        "the outlines sit after the object's transform (they follow its Placement)",
        "Transform" in children
        and "PopUpOffendingOutlines" in children
        and children.index("Transform") < children.index("PopUpOffendingOutlines"),
        children,
    )
    unselected, card_selected = inv.get("unselected") or {}, inv.get("card_selected") or {}
    check(
        "card selected: the red marks stay on screen",
        unselected.get("red", 0) > 300
        and card_selected.get("red", 0) >= 0.9 * unselected.get("red", 0)
        and card_selected.get("green", 0) > 1000,
        f"red {unselected.get('red')} -> {card_selected.get('red')}, "
        f"green {card_selected.get('green')}",
    )
    box_selected = inv.get("box_selected_alone") or {}
    check(
        "offending mechanism selected (v-fold hidden): its red outlines stay on screen",
        box_selected.get("red", 0) > 50 and box_selected.get("green", 0) > 1000,
        box_selected,
    )
    box_hidden = inv.get("box_hidden_outlines") or {}
    check(
        "hidden, a mechanism's red outlines go with it",
        box_hidden.get("red", 0) < unselected.get("red", 0),
        f"red {unselected.get('red')} -> {box_hidden.get('red')}",
    )
    shot_counts = inv.get("image") or {}
    check(
        f"{IMAGE_NAME}: 800x600, red and selection green",
        shot_counts.get("size") == [800, 600]
        and shot_counts.get("red", 0) > 500
        and shot_counts.get("green", 0) > 1000,
        shot_counts,
    )
    changed = inv.get("after_change") or []
    check(
        "a changed design drops the verdict to NotChecked",
        changed == ["NotChecked", False, 0]
        and (inv.get("icon_after_change") or {}).get("red", 1) == 0,
        changed,
    )
    recheck, valid_icon = inv.get("after_recheck") or [], inv.get("icon_valid") or {}
    check(
        "checked again: Valid, green badge, no red outlines",
        recheck == ["Valid", True, 0]
        and valid_icon.get("green", 0) > 20
        and inv.get("outlines_after_recheck") == 0,
        f"{recheck}, {valid_icon}, {inv.get('outlines_after_recheck')}",
    )
    code = check.exit_code()
    if code == 0 and "--update-docs" in sys.argv[1:]:
        shutil.copyfile(image, DOCS_IMAGE)
        print(f"copied {image} to {DOCS_IMAGE}")
    return code


if __name__ == "__main__":
    sys.exit(main())
