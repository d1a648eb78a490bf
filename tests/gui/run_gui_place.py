"""GUI test: grouped toolbars and menus, the right-click menu, and where new mechanisms land.

In the real FreeCAD GUI under Xvfb: the five PopUp toolbars and their commands, the PopUp menu
with its Mechanisms submenu and separators, the right-click menu of a card and of a mechanism in
the tree; a box then a step added with the toolbar commands on an A5 card stand apart (their
swept spans along the fold, read from the core, do not overlap, and Check validity finds the card
valid); the step's task panel draws the spans on the fold while it is open and not after; a
mechanism added to a full fold says so in the report view and in its panel; a 500 mm box is
refused in the panel with its range. Screenshots: the panel with its span overlay, and the
Mechanisms submenu.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gui_harness  # noqa: E402

MECHANISMS = [
    "PopUp_TentFold",
    "PopUp_StepFold",
    "PopUp_VFold",
    "PopUp_BoxFold",
    "PopUp_VBoxFold",
    "PopUp_FloatingLayer",
]
MOTION = ["PopUp_RotationArm", "PopUp_HorizontalTranslation", "PopUp_VerticalTranslation"]
TOOLBARS = {
    "PopUp card": ["PopUp_Card", "PopUp_LoadDesign", "PopUp_FromModel", "PopUp_FromAnimation"],
    "PopUp mechanisms": MECHANISMS + ["Separator", "PopUp_SetProfile"],
    "PopUp motion mechanisms": MOTION,
    "PopUp check": ["PopUp_CheckValidity", "PopUp_Animate"],
    "PopUp sheets": ["PopUp_CuttingSheet", "PopUp_ExportSheets"],
}
MENU = (
    [
        "PopUp_Card",
        "PopUp_LoadDesign",
        "PopUp_FromModel",
        "PopUp_FromAnimation",
        "Separator",
        "menu:Mechanisms",
    ]
    + ["PopUp_SetProfile", "Separator"]
    + ["PopUp_CheckValidity", "PopUp_Animate", "Separator"]
    + ["PopUp_CuttingSheet", "PopUp_ExportSheets"]
)
SUBMENU = MECHANISMS + ["Separator"] + MOTION
OWN = [1.0, 0.5, 0.0]
OVERLAP = [0.85, 0.0, 0.0]

BODY = r'''
def actions_of(widget, nested=False):
    """[command name or text, "Separator", "menu:TITLE"] of a toolbar or menu; with `nested`,
    submenus as {TITLE: their entries}."""
    found = []
    for action in widget.actions():
        if action.isSeparator():
            found.append("Separator")
        elif action.menu() is not None:
            title = action.menu().title().replace("&", "")
            found.append({title: actions_of(action.menu(), True)} if nested else "menu:" + title)
        else:
            found.append(action.objectName() or action.text().replace("&", ""))
    return found


def grab_context_menu(widget, position):
    """Right-clicks `widget` at `position` and returns the entries of the menu that opens,
    submenus as {title: entries}; the menu is closed again."""
    grabbed = {}

    def grab():
        menu = QtGui.QApplication.activePopupWidget()
        if menu is None:
            QtCore.QTimer.singleShot(100, grab)
            return
        grabbed["entries"] = actions_of(menu, nested=True)
        menu.close()

    QtCore.QTimer.singleShot(300, grab)
    event = QtGui.QContextMenuEvent(
        QtGui.QContextMenuEvent.Mouse, position, widget.mapToGlobal(position)
    )
    QtGui.QApplication.sendEvent(widget, event)
    wait_until(lambda: "entries" in grabbed, 10000)
    return grabbed.get("entries")


def tree_widget():
    for tree in Gui.getMainWindow().findChildren(QtGui.QTreeWidget):
        if tree.isVisible() and tree.topLevelItemCount():
            return tree
    return None


def right_click_in_tree(obj):
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(obj)
    Gui.updateGui()
    tree = tree_widget()
    if tree is None:
        return None
    items = tree.findItems(obj.Label, QtCore.Qt.MatchExactly | QtCore.Qt.MatchRecursive)
    if not items:
        return None
    tree.scrollToItem(items[0])
    rect = tree.visualItemRect(items[0])
    return grab_context_menu(tree.viewport(), rect.center())


def overlay_nodes():
    from pivy import coin
    from popupwb.taskpanels.span_overlay import NODE_NAME

    search = coin.SoSearchAction()
    search.setName(NODE_NAME)
    search.setInterest(coin.SoSearchAction.ALL)
    search.apply(Gui.ActiveDocument.ActiveView.getSceneGraph())
    return search.getPaths().getLength()


def spans(card):
    from popupwb.model import card_scaffold

    built = card_scaffold.for_card(card)
    return {name: [p.sweep_from, p.sweep_to, p.host] for name, p in built.parts.items()}


def run():
    from popupwb.model import card_scaffold
    from popupwb.commands import GROUPS
    from popupwb.taskpanels import mechanism_panel

    window = Gui.getMainWindow()
    result["toolbars"] = {}
    for name, _ in GROUPS:
        bar = window.findChild(QtGui.QToolBar, name)
        result["toolbars"][name] = actions_of(bar) if bar is not None else None
    result["flat_toolbar"] = window.findChild(QtGui.QToolBar, "PopUp") is not None
    wait_until(lambda: False, 500)  # the menu bar is rebuilt after the workbench switch
    popup_menu = next(
        (
            m
            for m in window.menuBar().findChildren(QtGui.QMenu)
            if m.title().replace("&", "") == "PopUp" and m.parent() is window.menuBar()
        ),
        None,
    )
    result["menu"] = actions_of(popup_menu) if popup_menu else None
    submenu = None
    if popup_menu is not None:
        found = [m for m in popup_menu.findChildren(QtGui.QMenu) if m.title() == "Mechanisms"]
        submenu = found[0] if found else None
    result["submenu"] = actions_of(submenu) if submenu else None

    doc = FreeCAD.newDocument("GuiPlace")
    Gui.runCommand("PopUp_Card")
    card = next(o for o in doc.Objects if card_scaffold.is_card(o))
    result["card_width"] = card.Width.Value

    def add(command, host):
        Gui.Selection.clearSelection()
        Gui.Selection.addSelection(host)
        known = set(o.Name for o in doc.Objects)
        Gui.runCommand(command)
        doc.recompute()
        return next((o for o in doc.Objects if o.Name not in known), None)

    box = add("PopUp_BoxFold", card)
    step = add("PopUp_StepFold", card)
    result["box"], result["step"] = box.Name, step.Name
    result["states"] = {o.Name: list(o.State) for o in (card, box, step)}
    result["spans"] = spans(card)
    result["step_values"] = [step.Offset.Value, step.Width.Value]
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(card)
    Gui.runCommand("PopUp_CheckValidity")
    result["valid"] = bool(card.Valid)
    result["diagnostics"] = list(card.Diagnostics)

    # Right-click menus in the tree.
    result["card_context"] = right_click_in_tree(card)
    result["box_context"] = right_click_in_tree(box)
    result["step_context"] = right_click_in_tree(step)

    # The step's panel: its span line and the overlay while open, nothing after.
    Gui.Selection.clearSelection()
    result["overlay_before"] = overlay_nodes()
    Gui.ActiveDocument.setEdit(step.Name, 0)
    Gui.updateGui()
    panel = mechanism_panel.last_panel
    result["overlay_open"] = overlay_nodes()
    result["overlay_spans"] = [
        [s.label, s.start, s.end, list(colour)] for s, colour in panel.overlay.spans
    ]
    result["span_text"] = panel.span_text()
    Gui.ActiveDocument.ActiveView.viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    Gui.updateGui()
    save_screenshot(os.path.join(CONFIG["out_dir"], "place_panel_overlay.png"))
    # Moved by hand into the box: the panel says so, the overlay turns red.
    panel.set_value("Offset", box.Offset.Value)
    result["moved_span_text"] = panel.span_text()
    result["moved_colours"] = [list(colour) for _, colour in panel.overlay.spans]
    save_screenshot(os.path.join(CONFIG["out_dir"], "place_overlap.png"))
    panel.reject()
    Gui.updateGui()
    result["overlay_after_cancel"] = overlay_nodes()
    result["step_offset_after_cancel"] = step.Offset.Value

    # A 500 mm box in the panel, then OK: the overlay goes with the panel too.
    Gui.ActiveDocument.setEdit(box.Name, 0)
    Gui.updateGui()
    panel = mechanism_panel.last_panel
    panel.set_value("Width", 500.0)
    result["box_error"] = panel.status_text()
    result["box_error_span"] = panel.span_text()
    result["overlay_in_error"] = overlay_nodes()
    panel.set_value("Width", box.Width.Value if box.Width.Value < 500 else 40.0)
    panel.reject()
    Gui.ActiveDocument.setEdit(box.Name, 0)
    Gui.updateGui()
    result["overlay_box_open"] = overlay_nodes()
    mechanism_panel.last_panel.accept()
    Gui.updateGui()
    result["overlay_after_ok"] = overlay_nodes()

    # A full fold: a step across all of it, then a tent from the toolbar.
    wide = add("PopUp_StepFold", card)
    doc.removeObject(wide.Name)
    doc.recompute()
    for obj in (box, step):
        doc.removeObject(obj.Name)
    doc.recompute()
    import popupwb.make

    full = popupwb.make.make_step_fold(card, offset=0.0, width=card.Width.Value, name="Full")
    doc.recompute()
    wait_until(lambda: False, 200)
    before = report_view_text()
    tent = add("PopUp_TentFold", card)
    wait_until(lambda: False, 300)
    result["full_report"] = report_view_text()[len(before):]
    Gui.ActiveDocument.setEdit(tent.Name, 0)
    Gui.updateGui()
    result["full_span_text"] = mechanism_panel.last_panel.span_text()
    mechanism_panel.last_panel.reject()
    Gui.updateGui()

    # The Mechanisms submenu, opened, for a screenshot of the grouping.
    if popup_menu is not None:
        popup_menu.popup(window.mapToGlobal(QtCore.QPoint(200, 30)))
        wait_until(lambda: False, 300)
        for action in popup_menu.actions():
            if action.menu() is not None:
                popup_menu.setActiveAction(action)
        wait_until(lambda: False, 500)
        QtGui.QApplication.primaryScreen().grabWindow(0).save(
            os.path.join(CONFIG["out_dir"], "place_menu.png")
        )
        popup_menu.close()
'''


def overlap(a, b):
    return a[0] < b[1] and b[0] < a[1]


def main():
    code, result, out_dir = gui_harness.run_macro("gui_place", BODY)
    check = gui_harness.Checks("gui_place")
    check("FreeCAD ran the macro and wrote its result", result is not None, f"exit code {code}")
    result = result or {}
    errors = result.get("errors", ["no result"])
    check("macro raised nothing", not errors, "\n".join(errors))

    for name, commands in TOOLBARS.items():
        got = result.get("toolbars", {}).get(name)
        check(f"toolbar {name!r} holds its group", got == commands, got)
    check("no flat 'PopUp' toolbar left", result.get("flat_toolbar") is False)
    check(
        "PopUp menu: card, Mechanisms submenu, check, sheets",
        result.get("menu") == MENU,
        result.get("menu"),
    )
    check(
        "Mechanisms submenu: structures, separator, motion",
        result.get("submenu") == SUBMENU,
        result.get("submenu"),
    )

    def flat(entries):
        found = []
        for entry in entries or []:
            if isinstance(entry, dict):
                for title, inner in entry.items():
                    found.append(("menu", title, tuple(inner)))
            else:
                found.append(entry)
        return found

    card_menu = flat(result.get("card_context"))
    check(
        "card's right-click menu: Add mechanism submenu, check, animate, cutting sheet",
        ("menu", "Add mechanism", tuple(SUBMENU)) in card_menu
        and all(
            c in card_menu for c in ["PopUp_CheckValidity", "PopUp_Animate", "PopUp_CuttingSheet"]
        ),
        card_menu,
    )
    box_menu = flat(result.get("box_context"))
    check(
        "a box's right-click menu nests mechanisms on it and checks its card, no cutting sheet",
        ("menu", "Add mechanism", tuple(SUBMENU)) in box_menu
        and "PopUp_CheckValidity" in box_menu
        and "PopUp_CuttingSheet" not in box_menu,
        box_menu,
    )
    step_menu = flat(result.get("step_context"))
    check(
        "a step's right-click menu (it hosts nothing) has no Add mechanism submenu",
        "PopUp_CheckValidity" in step_menu
        and not any(isinstance(e, tuple) and e[1] == "Add mechanism" for e in step_menu),
        step_menu,
    )

    spans = result.get("spans", {})
    box, step, width = result.get("box"), result.get("step"), result.get("card_width", 0)
    states = result.get("states", {})
    check("card, box and step built", all(s == ["Up-to-date"] for s in states.values()), states)
    if box in spans and step in spans:
        check(
            "the step from the toolbar does not overlap the box's swept span",
            not overlap(spans[box], spans[step]),
            f"box {spans[box][:2]}, step {spans[step][:2]}",
        )
        check(
            "both spans lie on the A5 card's 148 mm fold",
            width == 148.0 and all(0 <= s[0] and s[1] <= width for s in spans.values()),
            spans,
        )
        # At its fitted Offset (0.3 of the fold) the step would have started inside the box.
        check(
            "without placement the step would have overlapped",
            spans[box][0] < 0.3 * width < spans[box][1],
        )
    else:
        check("spans read", False, spans)
    check(
        "Check validity: the placed card is valid",
        result.get("valid") is True,
        result.get("diagnostics"),
    )

    check("no overlay before the panel opens", result.get("overlay_before") == 0)
    check("overlay in the 3D view while the panel is open", result.get("overlay_open") == 1)
    drawn = result.get("overlay_spans") or []
    check(
        "overlay draws the step (orange) and the box, with the core's spans",
        len(drawn) == 2
        and drawn[0][3] == OWN
        and step in spans
        and abs(drawn[0][1] - spans[step][0]) < 1e-9
        and abs(drawn[0][2] - spans[step][1]) < 1e-9,
        drawn,
    )
    text = result.get("span_text", "")
    check(
        "panel names the step's span",
        text.startswith("StepFold spans ") and "overlaps" not in text,
        text,
    )
    moved = result.get("moved_span_text", "")
    check(
        "moved into the box by hand: the panel says it overlaps the box",
        "overlaps BoxFold" in moved and "they may collide" in moved,
        moved,
    )
    check(
        "moved: the overlay turns red",
        result.get("moved_colours", [[0]])[0] == OVERLAP,
        result.get("moved_colours"),
    )
    check("overlay gone after Cancel", result.get("overlay_after_cancel") == 0)
    check(
        "Cancel restored the step",
        spans.get(step, [None])[0] == result.get("step_offset_after_cancel"),
    )
    error = result.get("box_error", "")
    check(
        "a 500 mm box: the panel shows the property and its range",
        error == "BoxFold: Width = 500 mm, must be > 0 and <= 148 mm (the length of central fold)",
        error,
    )
    check(
        "no span or overlay for a box in error",
        result.get("box_error_span") == "" and result.get("overlay_in_error") == 0,
    )
    check(
        "overlay present for the box's panel, gone after OK",
        result.get("overlay_box_open") == 1 and result.get("overlay_after_ok") == 0,
    )
    report = result.get("full_report", "")
    check(
        "a tent on a full fold: the report view says there is no free span",
        "TentFold: no free span on central fold for it (none is left" in report
        and "Traceback" not in report,
        report,
    )
    full = result.get("full_span_text", "")
    check(
        "and its panel says so",
        "overlaps Full" in full and "no free span left on central fold" in full,
        full,
    )
    for name in ("place_panel_overlay.png", "place_overlap.png", "place_menu.png"):
        path = os.path.join(out_dir, name)
        check(f"screenshot {name}", os.path.exists(path) and os.path.getsize(path) > 1000, path)
    return check.exit_code()


if __name__ == "__main__":
    sys.exit(main())
