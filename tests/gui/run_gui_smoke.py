"""GUI smoke test: the PopUp workbench in the real FreeCAD GUI under Xvfb.

Writes a macro that activates the workbench, loads resources/samples/demo_card.json as a Scaffold,
runs PopUp_CheckValidity, saves an isometric screenshot; then builds a card with every mechanism
through the toolbar commands, edits one in its task panel, checks and animates the card, saves a
second screenshot; checks what the commands say when nothing suitable is selected, reads the
Python lines the commands echo off the Python console and replays them in a fresh document, opens
the legacy documents of tests/data; writes a JSON result. Runs FreeCAD on it and checks the result. Run by ctest (gui_smoke) with /usr/bin/python3; by hand:

    /usr/bin/python3 tests/gui/run_gui_smoke.py      # POPUP_BUILD_DIR defaults to ./build

Output (macro, result.json, screenshot.png, freecad.log) stays in <build>/sandbox/gui_smoke/; the
macro runs through tests/gui/gui_harness.py.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_harness import HEIGHT, SANDBOX, SOURCE_DIR, WIDTH, WORKBENCH_DIR, run_macro  # noqa: E402

OUT_DIR = os.path.join(SANDBOX, "gui_smoke")
SAMPLE = os.path.join(SOURCE_DIR, "resources", "samples", "demo_card.json")
COMMANDS = [
    "PopUp_Card",
    "PopUp_TentFold",
    "PopUp_StepFold",
    "PopUp_VFold",
    "PopUp_BoxFold",
    "PopUp_VBoxFold",
    "PopUp_FloatingLayer",
    "PopUp_RotationArm",
    "PopUp_HorizontalTranslation",
    "PopUp_VerticalTranslation",
    "PopUp_CheckValidity",
    "PopUp_Animate",
    "PopUp_LoadDesign",
    "PopUp_FromModel",
    "PopUp_SetProfile",
    "PopUp_FromAnimation",
    "PopUp_CuttingSheet",
    "PopUp_ExportSheets",
]
OTHER_COMMANDS = [
    "PopUp_Card",
    "PopUp_CheckValidity",
    "PopUp_Animate",
    "PopUp_LoadDesign",
    "PopUp_FromModel",
    "PopUp_SetProfile",
    "PopUp_FromAnimation",
    "PopUp_CuttingSheet",
    "PopUp_ExportSheets",
]
LEGACY = ("legacy_card.FCStd", "legacy_card_gui.FCStd")

# Runs in the GUI after gui_harness.PRELUDE (CONFIG, result, count_non_white, report_view_text,
# wait_until); run() is called with the workbench active.
BODY = r"""

def mechanisms():
    # The card commands, the task panel, the validity check and the animation.
    from popupwb.model import card_scaffold
    from popupwb.commands import check_validity
    from popupwb.gui import fold_player
    from popupwb.taskpanels import mechanism_panel
    from popupwb.viewproviders.patch_colours import OFFENDING

    out = result["mechanisms"] = {}
    before = report_view_text()
    doc = FreeCAD.newDocument("GuiSmokeCard")
    Gui.runCommand("PopUp_Card")
    cards = [o for o in doc.Objects if card_scaffold.is_card(o)]
    out["card_made"] = len(cards) == 1 and cards[0].Preset == "A5"
    card = cards[0]
    card.Preset = "A4"
    doc.recompute()

    def add(command, host):
        Gui.Selection.clearSelection()
        Gui.Selection.addSelection(host)
        known = set(o.Name for o in doc.Objects)
        Gui.runCommand(command)
        new = [o for o in doc.Objects if o.Name not in known]
        out[command] = bool(new) and new[0].Host == host and new[0].Shape.isValid()
        return new[0] if new else None

    box = add("PopUp_BoxFold", card)
    tent = add("PopUp_TentFold", box)
    step = add("PopUp_StepFold", box)
    layer = add("PopUp_FloatingLayer", box)
    v_fold = add("PopUp_VFold", card)
    v_box = add("PopUp_VBoxFold", card)
    # The values of the demo card (valid): the commands fit their defaults to the host alone.
    values = {
        box: dict(Offset=60, Width=100, DepthGround=30, DepthBackdrop=30, Height=30),
        tent: dict(Offset=10, Width=40, Foot=10, FootBackdrop=10, Slope=14),
        step: dict(Offset=10, Width=60, RunGround=15, RunBackdrop=15),
        layer: dict(Offset=58, Width=35, Height=10, Support=8, Overhang=5),
        v_box: dict(Offset=185, Side=10, Height=8, WallAngle=45),
        v_fold: dict(Offset=25, Run=40, HingeAngle=45, Spine=45, SpineAngle=60),
    }
    for obj, properties in values.items():
        for name, value in properties.items():
            setattr(obj, name, value)
    step.HostPair = box.Label + ".side_ground"
    doc.recompute()
    objects = [card, box, tent, step, layer, v_fold, v_box]
    out["states"] = {o.Name: list(o.State) for o in objects}
    out["faces"] = {o.Name: len(o.Shape.Faces) for o in objects}
    out["colours"] = {o.Name: len(o.ViewObject.DiffuseColor) for o in objects}
    out["children"] = [c.Name for c in card.ViewObject.Proxy.claimChildren()]
    out["icons"] = [os.path.basename(o.ViewObject.Proxy.getIcon()) for o in objects]

    # The task panel: live edit, the error of a bad value, OK commits one undo step.
    foot_before = tent.Foot.Value
    Gui.ActiveDocument.setEdit(tent.Name, 0)
    Gui.updateGui()
    panel = mechanism_panel.last_panel
    out["panel_open"] = Gui.Control.activeDialog() and panel is not None and panel.obj is tent
    wait_until(lambda: False, 200)  # the report view appends queued messages on events
    log_before_error = report_view_text()  # the bad value's one-line error is expected
    panel.set_value("Foot", -3.0)
    out["panel_error"] = panel.status_text()
    panel.set_value("Foot", 9.0)
    wait_until(lambda: False, 200)
    log_after_error = report_view_text()
    out["panel_ok"] = panel.status_text()
    out["panel_applied"] = tent.Foot.Value == 9.0 and "Invalid" not in tent.State
    Gui.Control.activeDialog() and panel.accept()
    Gui.updateGui()
    out["panel_closed"] = not Gui.Control.activeDialog()
    Gui.ActiveDocument.setEdit(tent.Name, 0)
    mechanism_panel.last_panel.set_value("Slope", 40.0)
    mechanism_panel.last_panel.reject()
    Gui.updateGui()
    out["panel_cancel_restores"] = tent.Slope.Value != 40.0 and not Gui.Control.activeDialog()

    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(tent)  # a mechanism stands for its card
    Gui.runCommand("PopUp_CheckValidity")
    out["checked"] = check_validity.last_checked == [card.Name]
    out["valid"] = card.Valid
    out["diagnostics"] = list(card.Diagnostics)

    view = Gui.ActiveDocument.ActiveView
    card.FoldAngle = 100.0
    doc.recompute()
    view.setViewDirection((-0.35, 0.75, -0.56))  # from above the open card, in front of it
    view.fitAll()
    Gui.updateGui()
    view.saveImage(CONFIG["card_png"], CONFIG["width"], CONFIG["height"], "White")
    count_non_white(CONFIG["card_png"], "card_", out)

    # Offending patches turn red: the v-fold moved into the box's back.
    v_fold.Offset = box.Offset.Value + box.Width.Value + 2.0
    doc.recompute()
    Gui.runCommand("PopUp_CheckValidity")
    red = OFFENDING  # compared as RGB: the alpha's meaning differs between FreeCAD versions

    def is_red(c):
        return tuple(round(x, 3) for x in c[:3]) == tuple(round(x, 3) for x in red)

    # Colouring is deferred to the event loop: wait for it rather than for a fixed time.
    wait_until(lambda: any(is_red(c) for o in objects for c in o.ViewObject.DiffuseColor), 10000)
    out["red_faces"] = {
        o.Name: sum(1 for c in o.ViewObject.DiffuseColor if is_red(c))
        for o in objects
    }
    out["invalid_found"] = card.Valid is False
    v_fold.Offset = 25.0
    doc.recompute()
    # Colours are applied from the event loop: wait for them rather than for a fixed time.
    out["red_cleared"] = wait_until(
        lambda: not any(is_red(c) for o in objects for c in o.ViewObject.DiffuseColor),
        10000,
    )

    # The animation: timer-driven, the GUI keeps running, the angle comes back.
    fold_player.STEP_MS = 5
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(card)
    Gui.runCommand("PopUp_Animate")
    player = fold_player.current_player()
    out["animation_started"] = player is not None and player.running()
    finished = wait_until(lambda: not player.running(), 120000)
    out["animation_finished"] = finished
    out["animation_frames"] = player.frames if player else 0
    # Several timer ticks can pass in one event-loop turn: the player remembers its lowest angle.
    out["animation_reached_zero"] = player is not None and player.lowest == 0.0
    out["fold_angle_restored"] = card.FoldAngle.Value == 100.0

    # The panel's OK was one undo step: undoing it brings the old Foot back.
    doc.undo()
    doc.recompute()
    out["panel_undone"] = tent.Foot.Value == foot_before and "Invalid" not in tent.State
    log = log_before_error[len(before) :] + report_view_text()[len(log_after_error) :]
    out["report_errors"] = [
        line for line in log.splitlines() if "Traceback" in line or "Error" in line
    ]
    FreeCAD.closeDocument(doc.Name)


def selection_messages():
    # What the commands say when nothing suitable is selected, and that they then add nothing.
    from popupwb import make

    out = result["selection"] = {}
    doc = FreeCAD.newDocument("GuiSmokeSelection")
    card = make.make_card(doc, name="Card")
    make.make_card(doc, name="Card")  # Card001: two cards, so none is "the only one"
    doc.recompute()
    tent = make.make_tent_fold(card, name="Tent")
    doc.recompute()
    count = len(doc.Objects)

    def messages(command, selected=()):
        Gui.Selection.clearSelection()
        for obj in selected:
            Gui.Selection.addSelection(obj)
        wait_until(lambda: False, 100)
        before = report_view_text()
        Gui.runCommand(command)
        wait_until(lambda: False, 200)  # the report view appends queued messages on events
        lines = report_view_text()[len(before) :].splitlines()
        return [re.sub(r"^\d\d:\d\d:\d\d\s+", "", line) for line in lines if line]  # no time

    out["mechanism_without_host"] = messages("PopUp_StepFold")
    out["mechanism_on_tent"] = messages("PopUp_StepFold", [tent])
    out["sheet_without_card"] = messages("PopUp_CuttingSheet")
    out["added"] = len(doc.Objects) - count
    Gui.Selection.clearSelection()
    FreeCAD.closeDocument(doc.Name)


def python_console_text():
    console = Gui.getMainWindow().findChild(QtGui.QPlainTextEdit, "Python console")
    return console.toPlainText() if console else ""


def macro_replay():
    # The commands echo their Python in the console (as the macro recorder records it); replaying
    # those lines in a fresh document makes the same objects.
    out = result["macro"] = {}
    doc = FreeCAD.newDocument("GuiSmokeMacro")
    before = python_console_text()

    def run(command, host=None):
        Gui.Selection.clearSelection()
        if host is not None:
            Gui.Selection.addSelection(host)
        known = set(o.Name for o in doc.Objects)
        Gui.runCommand(command)
        return [o for o in doc.Objects if o.Name not in known][:1]

    (card,) = run("PopUp_Card")
    (box,) = run("PopUp_BoxFold", card)
    run("PopUp_TentFold", box)
    run("PopUp_CuttingSheet", card)
    run("PopUp_CheckValidity", card)
    wait_until(lambda: False, 200)
    # The console's last line is its prompt, which the next statement fills in.
    new_lines = python_console_text().splitlines()[len(before.splitlines()) - 1 :]
    echoed = [
        line[len(">>> ") :]
        for line in new_lines
        if line.startswith(">>> ") and ("popupwb" in line or "recompute()" in line)
    ]
    out["lines"] = echoed

    def summary(document):
        from popupwb.model import card_scaffold

        objects = [o for o in document.Objects if hasattr(o, "Proxy") and o.Proxy is not None]
        return {
            o.Name: {
                "class": type(o.Proxy).__name__,
                "host": o.Host.Name if getattr(o, "Host", None) else None,
                "parameters": o.Proxy.parameter_values(o) if card_scaffold.is_mechanism(o) else [],
                "faces": len(o.Shape.Faces),
                "valid": getattr(o, "Valid", None),
                "pieces": getattr(o, "PieceCount", None),
            }
            for o in objects
        }

    out["original"] = summary(doc)
    replay = FreeCAD.newDocument("GuiSmokeReplay")
    FreeCAD.setActiveDocument(replay.Name)
    exec("\n".join(echoed), {"FreeCAD": FreeCAD})
    out["replayed"] = summary(replay)
    FreeCAD.closeDocument(replay.Name)
    FreeCAD.closeDocument(doc.Name)


def legacy_documents():
    # Documents an older workbench saved, headless (no view providers stored: features attach
    # theirs by name) and from the GUI (view providers stored by module and class).
    out = result["legacy"] = {}
    for path in CONFIG["legacy"]:
        doc = FreeCAD.openDocument(path)
        objects = [doc.getObject(name) for name in ("Card", "Tent", "CuttingSheet")]
        doc.getObject("Card").FoldAngle = 120.0
        doc.recompute()
        shown = objects[:2]
        coloured = wait_until(
            lambda: all(len(o.ViewObject.DiffuseColor) == len(o.Shape.Faces) for o in shown),
            10000,
        )
        out[os.path.basename(path)] = {
            "view_providers": [type(o.ViewObject.Proxy).__name__ for o in objects],
            "icons": [os.path.basename(o.ViewObject.Proxy.getIcon()) for o in objects],
            "coloured": coloured,
            "states": sorted(set(s for o in objects for s in o.State if s != "Expanded")),
        }
        FreeCAD.closeDocument(doc.Name)


def run():
    # "Show script commands in python console" (off by default): what a user turns on to see them.
    FreeCAD.ParamGet("User parameter:BaseApp/Preferences/Macro").SetBool("ScriptToPyConsole", True)
    Gui.activateWorkbench("PopUpWorkbench")
    result["workbench"] = Gui.activeWorkbench().name()
    result["commands"] = [c for c in CONFIG["commands"] if c in Gui.listCommands()]
    # Every registered PopUp_* command that is not one of the others comes from the registry.
    from popupwb import mechanism_registry

    registered = set(c for c in Gui.listCommands() if c.startswith("PopUp_"))
    result["mechanism_commands"] = sorted(registered - set(CONFIG["other_commands"]))
    result["registry_commands"] = sorted(mechanism_registry.COMMAND_IDS)
    # One toolbar per group (card, mechanisms, motion mechanisms, check, sheets): their commands.
    result["toolbar_commands"] = [
        action.objectName()
        for toolbar in Gui.getMainWindow().findChildren(QtGui.QToolBar)
        if toolbar.objectName().startswith("PopUp ")
        for action in toolbar.actions()
        if not action.isSeparator()
    ]

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
    result["command_ran"] = check_validity.last_checked == [obj.Name]
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

    mechanisms()
    motion_mechanisms()
    cutting_sheet()
    selection_messages()
    macro_replay()
    legacy_documents()


def cutting_sheet():
    # PopUp_CuttingSheet on the selected card, its TechDraw page, and the export past its dialog.
    from popupwb import make
    from popupwb.features.cutting_sheet import export_cutting_sheet

    doc = FreeCAD.newDocument("GuiSmokeSheets")
    card = make.make_card(doc, preset="A5")
    make.make_tent_fold(card, name="Tent")
    doc.recompute()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(card)
    Gui.runCommand("PopUp_CuttingSheet")
    sheets = [o for o in doc.Objects if "SheetSetJson" in o.PropertiesList]
    pages = [o for o in doc.Objects if o.TypeId == "TechDraw::DrawPage"]
    sheet = sheets[0] if sheets else None
    result["cutting_sheet"] = (
        len(sheets) == 1
        and "Invalid" not in sheet.State
        and sheet.PieceCount == 2
        and sheet.Shape.isValid()
        and len(pages) == sheet.SheetCount
        and sheet.RoundTripOk
    )
    folder = os.path.join(os.path.dirname(CONFIG["result"]), "sheets")
    paths = export_cutting_sheet(sheet, folder) if sheet else {}
    result["sheets_exported"] = all(
        os.path.isfile(paths.get(k, "")) for k in ("dxf", "pdf", "instructions", "report")
    )
    FreeCAD.closeDocument(doc.Name)


def motion_mechanisms():
    # The motion mechanisms' commands, each on a card of its own (their defaults fit it).
    from popupwb import make

    motion = ["PopUp_RotationArm", "PopUp_HorizontalTranslation", "PopUp_VerticalTranslation"]
    for command in motion:
        doc = FreeCAD.newDocument("GuiSmokeMotion")
        card = make.make_card(doc, preset="A5")
        doc.recompute()
        Gui.Selection.clearSelection()
        Gui.Selection.addSelection(card)
        Gui.runCommand(command)
        new = [o for o in doc.Objects if o is not card]
        card.FoldAngle = 90.0
        doc.recompute()
        result[command] = (
            len(new) == 1
            and new[0].Host == card
            and new[0].Shape.isValid()
            and "Invalid" not in new[0].State
        )
        FreeCAD.closeDocument(doc.Name)

"""


def run_freecad():
    """Runs the GUI on BODY; returns (exit code, result dict or None)."""
    config = {
        "sample": SAMPLE,
        "fold_angle": 120.0,
        "check_command": "PopUp_CheckValidity",
        "legacy": [os.path.join(SOURCE_DIR, "tests", "data", name) for name in LEGACY],
        "commands": COMMANDS,
        "other_commands": OTHER_COMMANDS,
        "png": os.path.join(OUT_DIR, "screenshot.png"),
        "card_png": os.path.join(OUT_DIR, "card.png"),
        "width": WIDTH,
        "height": HEIGHT,
    }
    code, result, _ = run_macro("gui_smoke", BODY, config)
    return code, result


def check_mechanisms(check, m):
    """The card-and-mechanisms part of the macro's result."""
    check("PopUp_Card made an A5 card", m.get("card_made") is True)
    for command in ["PopUp_BoxFold", "PopUp_TentFold", "PopUp_StepFold", "PopUp_FloatingLayer"]:
        check(f"{command} built on the selected host", m.get(command) is True)
    for command in ["PopUp_VFold", "PopUp_VBoxFold"]:
        check(f"{command} built on the selected card", m.get(command) is True)
    states = m.get("states") or {}
    # "Expanded" is the tree item's state (the tree opens a card's children when a mechanism is
    # added under a busy event loop), not a recompute state.
    recomputed = {name: [s for s in state if s != "Expanded"] for name, state in states.items()}
    check(
        "every feature recomputed",
        len(states) == 7 and all(s == ["Up-to-date"] for s in recomputed.values()),
        states,
    )
    faces = m.get("faces") or {}
    check(
        "face counts (each patch drawn once: the card its 2 pages, each mechanism its own)",
        sorted(list(faces.values())[1:]) == [2, 2, 2, 6, 9, 9] and faces.get("Card") == 2,
        faces,
    )
    check("faces coloured by role", m.get("colours") == faces, m.get("colours"))
    check(
        "the card claims its mechanisms",
        m.get("children") == ["BoxFold", "VFold", "VBoxFold"],
        m.get("children"),
    )
    check(
        "icons per kind",
        m.get("icons")
        == [
            "PopUp_Card.svg",
            "PopUp_BoxFold.svg",
            "PopUp_TentFold.svg",
            "PopUp_StepFold.svg",
            "PopUp_FloatingLayer.svg",
            "PopUp_VFold.svg",
            "PopUp_VBoxFold.svg",
        ],
        m.get("icons"),
    )
    check("task panel opens on setEdit", m.get("panel_open") is True)
    check("task panel shows the error", "Foot = -3 mm" in (m.get("panel_error") or ""))
    check("task panel applies a value", m.get("panel_applied") is True, m.get("panel_ok"))
    check("task panel closes on OK", m.get("panel_closed") is True)
    check("task panel Cancel restores", m.get("panel_cancel_restores") is True)
    check("PopUp_CheckValidity checks the card", m.get("checked") is True)
    check("the card is valid", m.get("valid") is True, m.get("diagnostics"))
    red = m.get("red_faces") or {}
    check(
        "offending patches in red",
        m.get("invalid_found") is True and red.get("BoxFold", 0) > 0 and red.get("VFold", 0) > 0,
        red,
    )
    check("red goes when the design changes", m.get("red_cleared") is True)
    check(
        "PopUp_Animate plays 180 -> 0 -> 180",
        m.get("animation_started") is True
        and m.get("animation_finished") is True
        and m.get("animation_reached_zero") is True
        and m.get("animation_frames", 0) > 100,
        f"{m.get('animation_frames')} frames",
    )
    check("the fold angle comes back", m.get("fold_angle_restored") is True)
    check("the panel's edit is one undo step", m.get("panel_undone") is True)
    check("no errors in the report view", m.get("report_errors") == [], m.get("report_errors"))
    pixels = m.get("card_non_white_pixels", 0)
    check(
        "card screenshot shows the pop-up",
        m.get("card_image_size") == [WIDTH, HEIGHT]
        and pixels > 0.02 * WIDTH * HEIGHT
        and m.get("card_tinted_pixels", 0) > 0.005 * WIDTH * HEIGHT,
        f"{pixels} non-white pixels, {m.get('card_tinted_pixels')} in colour, "
        + os.path.join(OUT_DIR, "card.png"),
    )


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
    check(
        "the PopUp toolbars hold every command once",
        sorted(result.get("toolbar_commands", [])) == sorted(COMMANDS),
        result.get("toolbar_commands"),
    )
    check(
        "every mechanism command comes from the registry, and every registry entry is a command",
        result.get("mechanism_commands") == result.get("registry_commands")
        and result.get("registry_commands") == sorted(set(COMMANDS) - set(OTHER_COMMANDS)),
        result.get("mechanism_commands"),
    )
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
    for command in [
        "PopUp_RotationArm",
        "PopUp_HorizontalTranslation",
        "PopUp_VerticalTranslation",
    ]:
        check(f"{command} builds on the selected card", result.get(command) is True)
    check("PopUp_LoadDesign is one undo step", result.get("load_undone") is True)
    check("PopUp_CuttingSheet lays out the selected card", result.get("cutting_sheet") is True)
    check("the cutting sheet exports its files", result.get("sheets_exported") is True)
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
    check_mechanisms(check, result.get("mechanisms") or {})
    selection = result.get("selection") or {}
    hosts = "a card or a mechanism offering base patch pairs (box fold, floating layer, v-fold)"
    check(
        "a mechanism command without a host says what to select",
        selection.get("mechanism_without_host")
        == [f"PopUp_StepFold: select {hosts} (the document has several: Card, Card001)"],
        selection.get("mechanism_without_host"),
    )
    check(
        "a mechanism command on a tent says it offers no pair",
        selection.get("mechanism_on_tent")
        == [f"PopUp_StepFold: Tent offers no base patch pair: select {hosts}"],
        selection.get("mechanism_on_tent"),
    )
    check(
        "PopUp_CuttingSheet without a card says what to select",
        selection.get("sheet_without_card")
        == [
            "PopUp_CuttingSheet: select a card or one of its mechanisms "
            "(the document has several: Card, Card001)"
        ],
        selection.get("sheet_without_card"),
    )
    check("refused commands add nothing", selection.get("added") == 0, selection.get("added"))
    macro = result.get("macro") or {}
    expected = [
        "card = popupwb.make.make_card(FreeCAD.ActiveDocument, preset='A5')",
        "mechanism = popupwb.make.make_box_fold(FreeCAD.ActiveDocument.getObject('Card'))",
        "mechanism = popupwb.make.make_tent_fold(FreeCAD.ActiveDocument.getObject('BoxFold'))",
        "sheet = popupwb.make.make_cutting_sheet(FreeCAD.ActiveDocument.getObject('Card'), "
        "paper='A4', name='CardSheets')",
        "popupwb.validity.run_check(FreeCAD.ActiveDocument.getObject('Card'))",
    ]
    lines = macro.get("lines") or []
    check(
        "the commands echo their popupwb calls in the Python console",
        [line for line in lines if "popupwb." in line and "import" not in line] == expected
        and lines.count("import popupwb.make") == 4
        and lines.count("import popupwb.validity") == 1
        and lines.count("FreeCAD.ActiveDocument.recompute()") == 4,
        lines,
    )
    original = macro.get("original") or {}
    check(
        "replaying the echoed lines in a fresh document makes the same objects",
        set(original) == {"Card", "BoxFold", "TentFold", "CardSheets"}
        and macro.get("replayed") == original
        and original["TentFold"]["host"] == "BoxFold"
        and original["Card"]["valid"] is True,
        {"original": original, "replayed": macro.get("replayed")},
    )
    for name in LEGACY:
        legacy = (result.get("legacy") or {}).get(name) or {}
        check(
            f"{name} opens with its view providers",
            legacy.get("view_providers")
            == ["CardViewProvider", "MechanismViewProvider", "CuttingSheetViewProvider"]
            and legacy.get("icons")
            == ["PopUp_Card.svg", "PopUp_TentFold.svg", "PopUp_CuttingSheet.svg"],
            legacy,
        )
        check(
            f"{name} recomputes, coloured by role",
            legacy.get("coloured") is True and legacy.get("states") == ["Up-to-date"],
            legacy,
        )
    failed = checks.count(False)
    print(f"gui_smoke: {len(checks) - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
