#!/usr/bin/python3
"""`make demo`: a pop-up designed from the bundled 3D model, then the issue-3 card built from
mechanism features and the bundled design file.

    /usr/bin/python3 tools/run_demo.py --build build --out out/demo

First the shape from a model (issue 12): (1) `popup fit resources/samples/house.stl --out
out/demo/fit` writes design.FCStd (a PopUpCard with its mechanism features and the house linked),
report.json, preview.png and the cutting sheets in fit/sheets/ (as `popup sheet` writes them);
(2) `popup verify fit/design.FCStd fit/sheets` proves the cutting file against the design. The
house was made by tools/make_models.py (see resources/samples/README.md).

Then motion from an animation (issue 13): (3) `popup animate resources/samples/waving_figure.glb
--out out/demo/animate` writes design.FCStd (a PopUpCard with motion mechanisms linked to the
animation), report.json, paths.png, motion.gif and animate/sheets/; (4) `popup verify` proves
those sheets. The animation was made by tools/make_animations.py.

Then the hand-made card: (a) copy resources/samples/demo_card.json into the output folder, (b) check its validity
(validity_report.json / .txt), (c) build demo_card.FCStd with three Scaffold objects of it at fold
angles 180, 90 and 30 degrees side by side, (d) build card.FCStd: an A4 PopUpCard carrying a box
fold with a tent fold and a floating layer on its top and a step fold on its side, and a v-fold
and a v-box beside the box, all made with popupwb.make, and check it (card_validity.json / .txt), (e) render
demo_card.png and card_180.png, card_90.png, card_30.png with the FreeCAD GUI under Xvfb (one
run), (f) lay card.FCStd out for cutting with `popup sheet` on A3 paper into sheets/ (DXF, SVG,
PDF, instructions, report.json, sheets.json) and render sheets/sheet_1.png, (g) list the outputs
and the verdicts, (h) prove the cutting file with `popup verify card.FCStd sheets/` (it reads only
sheets.dxf, re-folds the pieces and compares them with the card) and print its verdict last.
(c) and (d) run headless FreeCAD in subprocesses.
FreeCAD runs with a sandboxed user home (<build>/sandbox/home) whose Mod/PopUp links to the
workbench, so nothing is read from or written to the user's own FreeCAD setup.
"""

import argparse
import json
import os
import shutil
import subprocess
import sys
import textwrap

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PYTHON = "/usr/bin/python3"
sys.path.append(os.path.join(REPO, "Workbench"))
from popupwb import freecad_version  # noqa: E402  (importable before FreeCAD)

FREECAD_LIB = freecad_version.freecad_lib_dir()
DEMO_DESIGN = os.path.join(REPO, "resources", "samples", "demo_card.json")
DEMO_MODEL = os.path.join(REPO, "resources", "samples", "house.stl")
DEMO_ANIMATION = os.path.join(REPO, "resources", "samples", "waving_figure.glb")
FIT_TIMEOUT = 300  # seconds
ANIMATE_TIMEOUT = 600  # seconds
FOLD_ANGLES = (180.0, 90.0, 30.0)
SPACING = 1.3  # distance between the cards, in card sizes
IMAGE_SIZE = (1200, 800)
CAMERA_TURN = -20.0  # degrees about the vertical axis, away from the exact isometric view
GUI_TIMEOUT = 180  # seconds


class DemoError(Exception):
    """A step failed; the message says which and why."""


def sandbox_env(build):
    """Environment for FreeCAD runs: sandboxed home with Mod/PopUp -> <repo>/Workbench."""
    home = os.path.join(build, "sandbox", "home")
    os.makedirs(home, exist_ok=True)
    try:
        mod = freecad_version.user_mod_dir_for(dict(os.environ, FREECAD_USER_HOME=home, HOME=home))
        freecad_version.link_into(mod, os.path.join(REPO, "Workbench"))
    except RuntimeError as error:
        raise DemoError(str(error)) from error
    env = dict(os.environ)
    env.update(
        FREECAD_USER_HOME=home,
        HOME=home,
        PYTHONPATH=os.pathsep.join(
            [os.path.join(build, "python"), os.path.join(REPO, "Workbench"), FREECAD_LIB]
        ),
        QTWEBENGINE_DISABLE_SANDBOX="1",
    )
    return env


def copy_design(source, out):
    """(a) The design next to the outputs, so the document and the report refer to it."""
    if not os.path.isfile(source):
        raise DemoError(f"(a) copy design: {source} is missing")
    target = os.path.join(out, "demo_card.json")
    shutil.copyfile(source, target)
    return target


def check_design(build, design, out):
    """(b) Validity report as JSON and as text; returns the report dict."""
    for path in (os.path.join(REPO, "Workbench"), os.path.join(build, "python")):
        if path not in sys.path:
            sys.path.insert(0, path)
    if FREECAD_LIB not in sys.path:
        sys.path.append(FREECAD_LIB)
    try:
        import popupcore
        from popupwb.validity import format_report
    except ImportError as e:
        raise DemoError(f"(b) validity check: cannot import ({e}); did 'make build' run?")
    try:
        scaffold = popupcore.load_scaffold(design)
    except ValueError as e:
        raise DemoError(f"(b) validity check: {design}: {e}")
    report = popupcore.check_validity(scaffold).to_dict()
    json_path = os.path.join(out, "validity_report.json")
    txt_path = os.path.join(out, "validity_report.txt")
    with open(json_path, "w", encoding="utf-8") as f:
        json.dump(report, f, indent=2)
        f.write("\n")
    with open(txt_path, "w", encoding="utf-8") as f:
        f.write(format_report(report).rstrip("\n") + "\n")
    return report, [json_path, txt_path]


# Runs in a separate /usr/bin/python3 (FreeCAD's console mode); argv: design, fcstd.
BUILD_DOCUMENT = textwrap.dedent(
    """
    import sys
    import FreeCAD
    from popupwb.make import make_scaffold
    from popupwb.validity import run_check

    design, fcstd, angles, spacing = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
    doc = FreeCAD.newDocument("DemoCard")
    cards = [
        make_scaffold(doc, design, fold_angle=float(a), name="Card%03d" % round(float(a)))
        for a in angles.split(",")
    ]
    doc.recompute()
    flat = cards[0].Shape.BoundBox
    if not flat.isValid():
        sys.exit("the open card has an empty shape; diagnostics: %s" % list(cards[0].Diagnostics))
    step = spacing * max(flat.XLength, flat.YLength)
    for i, card in enumerate(cards):
        card.Placement = FreeCAD.Placement(FreeCAD.Vector(i * step, 0, 0), FreeCAD.Rotation())
    doc.recompute()
    boxes = [card.Shape.BoundBox for card in cards]
    for card, box in zip(cards, boxes):
        if card.Shape.isNull() or not box.isValid():
            sys.exit("%s has no shape; diagnostics: %s" % (card.Name, list(card.Diagnostics)))
    for a, b in zip(boxes, boxes[1:]):
        if a.XMax >= b.XMin:
            sys.exit("cards overlap along x: %s and %s" % (a, b))
    for card in cards:
        run_check(card)  # what the Check validity command does: fills Valid and Diagnostics
    doc.saveAs(fcstd)
    for card in cards:
        print("%s: FoldAngle %s, Valid %s" % (card.Name, card.FoldAngle, card.Valid))
    """
)


def build_document(build, design, out, env):
    """(c) demo_card.FCStd with the card open, half open and nearly closed."""
    fcstd = os.path.join(out, "demo_card.FCStd")
    if os.path.exists(fcstd):
        os.remove(fcstd)
    angles = ",".join(str(a) for a in FOLD_ANGLES)
    proc = subprocess.run(
        [PYTHON, "-c", BUILD_DOCUMENT, design, fcstd, angles, str(SPACING)],
        env=env,
        cwd=out,
        capture_output=True,
        text=True,
        timeout=300,
    )
    if proc.returncode != 0 or not os.path.isfile(fcstd):
        detail = (proc.stderr.strip() or proc.stdout.strip()).splitlines()[-15:]
        raise DemoError(
            f"(c) build FCStd: exit {proc.returncode}:\n  " + "\n  ".join(detail or ["no output"])
        )
    return fcstd, proc.stdout.strip()


# Runs in a separate /usr/bin/python3 (FreeCAD's console mode); argv: fcstd, report json, txt.
BUILD_CARD = textwrap.dedent(
    """
    import json
    import sys
    import FreeCAD
    from popupwb import make
    from popupwb.validity import format_report, run_check

    fcstd, json_path, txt_path = sys.argv[1:4]
    doc = FreeCAD.newDocument("PopUpCard")
    card = make.make_card(doc, preset="A4", name="Card")
    box = make.make_box_fold(
        card, offset=60, width=100, depth_ground=30, depth_backdrop=30, height=30, name="Box"
    )
    tent = make.make_tent_fold(
        box, "Box.top", offset=4, width=26, foot=10, foot_backdrop=10, slope=14, name="Tent"
    )
    layer = make.make_floating_layer(
        box, "Box.top", offset=40, width=30, height=10, support=8, overhang=5, name="Layer"
    )
    # The motion mechanism: its arm swings as the card closes (thesis §4.3.4).
    arm = make.make_rotation_arm(box, "Box.top", offset=85, spine=15, run=10, arm=12, name="Arm")
    step = make.make_step_fold(
        box, "Box.side_ground", offset=10, width=60, run_ground=15, run_backdrop=15, name="Step"
    )
    v_fold = make.make_v_fold(
        card, "central fold", offset=25, run=40, hinge_angle=45, spine=45, spine_angle=60,
        name="VFold",
    )
    v_box = make.make_v_box_fold(
        card, "central fold", offset=185, side=10, height=8, wall_angle=45, name="VBox"
    )
    doc.recompute()
    features = [card, box, tent, layer, arm, step, v_fold, v_box]
    broken = [f"{o.Label}: {o.getStatusString()}" for o in features if "Invalid" in o.State]
    if broken:
        sys.exit("features in error: " + "; ".join(broken))
    report = run_check(card)
    with open(json_path, "w", encoding="utf-8") as f:
        json.dump(report, f, indent=2)
        f.write("\\n")
    with open(txt_path, "w", encoding="utf-8") as f:
        f.write(format_report(report).rstrip("\\n") + "\\n")
    # The cutting sheets as a feature with its TechDraw pages (the open A4 card needs A3).
    sheets = make.make_cutting_sheet(card, paper="A3", name="CuttingSheet")
    doc.recompute()
    if "Invalid" in sheets.State:
        sys.exit("cutting sheet in error: " + "; ".join(sheets.Diagnostics))
    doc.saveAs(fcstd)
    for obj in features:
        print("%s: %d faces" % (obj.Label, len(obj.Shape.Faces)))
    print("CuttingSheet: %d pieces on %d sheet(s), %d TechDraw page(s)" % (
        sheets.PieceCount, sheets.SheetCount,
        len([o for o in doc.Objects if o.TypeId == "TechDraw::DrawPage"])))
    """
)


def build_card(build, out, env):
    """(d) card.FCStd from mechanism features, and its validity report; returns (paths, report)."""
    paths = [os.path.join(out, name) for name in ("card.FCStd", "card_validity.json")]
    paths.append(os.path.join(out, "card_validity.txt"))
    for stale in paths:
        if os.path.exists(stale):
            os.remove(stale)
    proc = subprocess.run(
        [PYTHON, "-c", BUILD_CARD, *paths],
        env=env,
        cwd=out,
        capture_output=True,
        text=True,
        timeout=300,
    )
    if proc.returncode != 0 or not all(os.path.isfile(p) for p in paths):
        detail = (proc.stderr.strip() or proc.stdout.strip()).splitlines()[-15:]
        raise DemoError(
            f"(d) build card: exit {proc.returncode}:\n  " + "\n  ".join(detail or ["no output"])
        )
    with open(paths[1], encoding="utf-8") as f:
        report = json.load(f)
    return paths, report, proc.stdout.strip()


# FreeCAD GUI macro rendering every picture in one run; its status (ok + share of non-white pixels
# per picture, or the error) goes to a file because the GUI's exit code does not reflect what the
# macro did.
RENDER_MACRO = textwrap.dedent(
    """
    import json
    import math
    import traceback
    import FreeCAD
    import FreeCADGui as Gui
    from PySide import QtCore, QtGui

    JOBS = json.loads({jobs!r})
    STATUS = {status!r}
    status = {{"ok": False, "inked": {{}}}}


    def inked(path):
        image = QtGui.QImage(path)
        count = total = 0
        for y in range(0, image.height(), 4):
            for x in range(0, image.width(), 4):
                total += 1
                if QtGui.QColor(image.pixel(x, y)).lightness() < 235:
                    count += 1
        return count / max(total, 1)


    def camera(view, kind):
        if kind == "isometric":
            view.viewIsometric()
            # In the exact isometric view the half-open card's ground is seen edge-on: turn the
            # camera a little about the vertical axis.
            d = view.getViewDirection()
            c, s = math.cos(math.radians({turn})), math.sin(math.radians({turn}))
            view.setViewDirection((c * d.x - s * d.y, s * d.x + c * d.y, d.z))
        else:
            # In front of the card (-y), above it (+z) and a little to the ground side (+x),
            # with z up on the screen: the same camera for every fold angle.
            back = FreeCAD.Vector(*kind).normalize()
            right = FreeCAD.Vector(0, 0, 1).cross(back).normalize()
            up = back.cross(right)
            view.setCameraOrientation(FreeCAD.Rotation(right, up, back, "ZYX"))


    try:
        for job in JOBS:
            doc = FreeCAD.openDocument(job["fcstd"])
            Gui.updateGui()
            for obj in doc.Objects:
                # Saved headless, every object opens hidden: show the design, not the sheets.
                shown = any(p in obj.PropertiesList for p in ("FoldAngle", "Host", "DesignFile"))
                obj.ViewObject.Visibility = shown
            # A TechDraw page may open as the active window: draw in the 3D view.
            view = Gui.getDocument(doc.Name).mdiViewsOfType("Gui::View3DInventor")[0]
            for shot in job["shots"]:
                if shot.get("fold_angle") is not None:
                    doc.getObject(shot["object"]).FoldAngle = shot["fold_angle"]
                    doc.recompute()
                Gui.updateGui()
                camera(view, shot["camera"])
                view.fitAll()
                Gui.updateGui()
                view.saveImage(shot["png"], {width}, {height}, "White")
                status["inked"][shot["png"]] = inked(shot["png"])
            FreeCAD.closeDocument(doc.Name)
        status["ok"] = True
    except Exception:
        status = {{"ok": False, "error": traceback.format_exc()}}
    finally:
        with open(STATUS, "w") as f:
            json.dump(status, f)
        QtCore.QTimer.singleShot(0, Gui.getMainWindow().close)
    """
)
# Direction from the card towards the eye, per fold angle: in front of the card (-y), above it
# (+z), lower as the card closes so that the light still reaches inside.
CARD_CAMERAS = {180.0: (0.15, -1.0, 0.9), 90.0: (0.15, -1.0, 0.9), 30.0: (0.05, -0.45, 1.0)}


def render_pngs(build, demo_fcstd, card_fcstd, out, env):
    """(e) demo_card.png (the three Scaffolds) and card_<angle>.png, from the real FreeCAD GUI."""
    for tool in ("xvfb-run", "freecad"):
        if shutil.which(tool) is None:
            raise DemoError(f"(e) render PNGs: '{tool}' not found (run 'make deps')")
    demo_png = os.path.join(out, "demo_card.png")
    card_pngs = [os.path.join(out, f"card_{round(a)}.png") for a in FOLD_ANGLES]
    jobs = [
        {"fcstd": demo_fcstd, "shots": [{"png": demo_png, "camera": "isometric"}]},
        {
            "fcstd": card_fcstd,
            "shots": [
                {"png": png, "object": "Card", "fold_angle": angle, "camera": CARD_CAMERAS[angle]}
                for png, angle in zip(card_pngs, FOLD_ANGLES)
            ],
        },
    ]
    work = os.path.join(build, "sandbox", "demo")
    os.makedirs(work, exist_ok=True)
    macro = os.path.join(work, "render_demo.FCMacro")
    status_path = os.path.join(work, "render_status.json")
    for stale in [demo_png, *card_pngs, status_path]:
        if os.path.exists(stale):
            os.remove(stale)
    with open(macro, "w", encoding="utf-8") as f:
        f.write(
            RENDER_MACRO.format(
                jobs=json.dumps(jobs),
                status=status_path,
                width=IMAGE_SIZE[0],
                height=IMAGE_SIZE[1],
                turn=CAMERA_TURN,
            )
        )
    cmd = [
        "timeout",
        str(GUI_TIMEOUT),
        "xvfb-run",
        "-a",
        "-s",
        "-screen 0 1280x1024x24",
        "freecad",
        macro,
    ]
    proc = subprocess.run(cmd, env=env, cwd=work, capture_output=True, text=True)
    if proc.returncode == 124:
        raise DemoError(f"(e) render PNGs: the FreeCAD GUI did not finish in {GUI_TIMEOUT} s")
    try:
        with open(status_path, encoding="utf-8") as f:
            status = json.load(f)
    except (OSError, ValueError):
        tail = (proc.stderr.strip() or proc.stdout.strip()).splitlines()[-10:]
        raise DemoError(
            f"(e) render PNGs: the macro did not run (freecad exit {proc.returncode}):\n  "
            + "\n  ".join(tail or ["no output"])
        )
    if not status.get("ok"):
        raise DemoError("(e) render PNGs: macro failed:\n" + status.get("error", "unknown error"))
    for png in [demo_png, *card_pngs]:
        if not os.path.isfile(png):
            raise DemoError(f"(e) render PNGs: {png} was not written")
        share = status["inked"].get(png, 0.0)
        if share < 0.01:
            raise DemoError(f"(e) render PNGs: {png} is blank ({share:.2%} non-white)")
    return [demo_png, *card_pngs]


def make_sheets(build, card_fcstd, out, env):
    """(f) The card's cutting sheets with `popup sheet` (A3: the open A4 card is 210 x 297 mm and
    needs more than A4 paper inside 10 mm margins), and a PNG of the first sheet."""
    folder = os.path.join(out, "sheets")
    command = [os.path.join(build, "bin", "popup"), "sheet", card_fcstd, "--out", folder]
    proc = subprocess.run(
        command + ["--paper", "A3", "--json"],
        env=env,
        capture_output=True,
        text=True,
        timeout=GUI_TIMEOUT,
    )
    if proc.returncode != 0:
        raise DemoError(f"(f) sheets: exit {proc.returncode}: {proc.stderr.strip()}")
    report = json.loads(proc.stdout)
    sys.path.insert(0, os.path.join(REPO, "Workbench"))
    sys.path.insert(0, os.path.join(build, "python"))  # this build's popupcore
    from popupwb.core import popupcore
    from popupwb.sheets.sheet_png import render_sheet_png

    with open(os.path.join(folder, "sheets.json")) as f:
        sheet_set = popupcore.sheet_set_from_json(f.read())

    png = render_sheet_png(sheet_set, 0, os.path.join(folder, "sheet_1.png"), dpi=150)
    files = [report["files"][k] for k in ("dxf", "pdf", "instructions", "report", "sheet_set")]
    return [*files[:1], *report["files"]["svg"], *files[1:], png], report


def verify_sheets(build, card_fcstd, sheets_folder, env):
    """(h) `popup verify` of the cutting file just written against the card: (ok, verdict line,
    the error findings)."""
    command = [os.path.join(build, "bin", "popup"), "verify", card_fcstd, sheets_folder]
    proc = subprocess.run(
        command + ["--json"], env=env, capture_output=True, text=True, timeout=GUI_TIMEOUT
    )
    if proc.returncode not in (0, 1):
        raise DemoError(f"(h) verify: exit {proc.returncode}: {proc.stderr.strip()}")
    result = json.loads(proc.stdout)
    errors = [d for d in result["diagnostics"] if d["severity"] == "error"]
    if result["ok"]:
        verdict = (
            f"sheets match the design: every patch within {result['max_error']:.3g} mm "
            f"(tolerance {result['tolerance']:.3g} mm) over {result['angles']} fold angles"
        )
    else:
        verdict = f"sheets do NOT match the design: {len(errors)} error(s)"
    return result["ok"] and proc.returncode == 0, verdict, errors


def fit_model(build, model, out, env):
    """(1) `popup fit` of the bundled model into out/fit: (the fit's report.json, its stdout).
    The model's z is up and its front faces -y (tools/make_models.py)."""
    folder = os.path.join(out, "fit")
    command = [os.path.join(build, "bin", "popup"), "fit", model, "--out", folder]
    command += ["--up", "0,0,1", "--facing", "0,-1,0", "--seed", "1"]
    proc = subprocess.run(command, env=env, capture_output=True, text=True, timeout=FIT_TIMEOUT)
    if proc.returncode not in (0, 1) or not os.path.isfile(os.path.join(folder, "report.json")):
        raise DemoError(f"(1) popup fit: exit {proc.returncode}: {proc.stderr.strip()}")
    with open(os.path.join(folder, "report.json")) as f:
        report = json.load(f)
    if proc.returncode != 0 or not report["valid"]:
        raise DemoError(f"(1) popup fit found no valid design; see {folder}/report.json")
    return report, proc.stdout


def animate(build, animation, out, env):
    """(3) `popup animate` of the bundled animation into out/animate: (its report.json, its
    stdout). The animation was made by tools/make_animations.py (resources/samples/README.md)."""
    if not os.path.isfile(animation):
        raise DemoError(f"(3) popup animate: {animation} is missing (tools/make_animations.py)")
    folder = os.path.join(out, "animate")
    command = [os.path.join(build, "bin", "popup"), "animate", animation, "--out", folder]
    command += ["--seed", "1"]
    proc = subprocess.run(command, env=env, capture_output=True, text=True, timeout=ANIMATE_TIMEOUT)
    if proc.returncode not in (0, 1) or not os.path.isfile(os.path.join(folder, "report.json")):
        raise DemoError(f"(3) popup animate: exit {proc.returncode}: {proc.stderr.strip()}")
    with open(os.path.join(folder, "report.json")) as f:
        report = json.load(f)
    if report["valid"] and not report.get("sheets_ok"):
        raise DemoError(
            f"(3) popup animate: the design is valid but its cutting sheets have errors; see "
            f"{folder}/sheets/report.json"
        )
    if proc.returncode != 0 or not report["valid"]:
        raise DemoError(f"(3) popup animate found no valid design; see {folder}/report.json")
    return report, proc.stdout


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="CMake build folder (default: build)")
    parser.add_argument("--out", default="out/demo", help="output folder (default: out/demo)")
    parser.add_argument(
        "--design",
        default=DEMO_DESIGN,
        help="design to show (default: resources/samples/demo_card.json)",
    )
    parser.add_argument(
        "--model",
        default=DEMO_MODEL,
        help="3D model to design a pop-up from (default: resources/samples/house.stl)",
    )
    parser.add_argument(
        "--animation",
        default=DEMO_ANIMATION,
        help="animation to design an animated pop-up from (default: "
        "resources/samples/waving_figure.glb)",
    )
    args = parser.parse_args(argv)
    build = os.path.abspath(args.build)
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    try:
        env = sandbox_env(build)
        fit_report, fit_summary = fit_model(build, os.path.abspath(args.model), out, env)
        fit_files = fit_report["files"]
        print(f"(1) popup fit {os.path.basename(args.model)}: {fit_files['design']}", flush=True)
        print(textwrap.indent(fit_summary.strip(), "      "), flush=True)
        fit_verified, fit_verdict, fit_findings = verify_sheets(
            build, fit_files["design"], fit_files["sheets"], env
        )
        for d in fit_findings:
            print(f"      error: {d['code']}: {d['message']}", flush=True)
        print(f"(2) popup verify fit/sheets against fit/design.FCStd: {fit_verdict}", flush=True)
        if not fit_verified:
            raise DemoError("(2) popup verify: the fitted card's cutting file does not make it")
        motion_report, motion_summary = animate(build, os.path.abspath(args.animation), out, env)
        motion_files = motion_report["files"]
        print(
            f"(3) popup animate {os.path.basename(args.animation)}: {motion_files['design']}",
            flush=True,
        )
        print(textwrap.indent(motion_summary.strip(), "      "), flush=True)
        motion_verified, motion_verdict, motion_findings = verify_sheets(
            build, motion_files["design"], motion_files["sheets"], env
        )
        for d in motion_findings:
            print(f"      error: {d['code']}: {d['message']}", flush=True)
        print(
            f"(4) popup verify animate/sheets against animate/design.FCStd: {motion_verdict}",
            flush=True,
        )
        if not motion_verified:
            raise DemoError("(4) popup verify: the animated card's cutting file does not make it")
        design = copy_design(os.path.abspath(args.design), out)
        print(f"(a) design copied: {design}", flush=True)
        report, report_files = check_design(build, design, out)
        print(f"(b) validity checked: {'VALID' if report['valid'] else 'INVALID'}", flush=True)
        fcstd, summary = build_document(build, design, out, env)
        print(f"(c) document built: {fcstd}", flush=True)
        if summary:
            print(textwrap.indent(summary, "      "), flush=True)
        card_files, card_report, card_summary = build_card(build, out, env)
        verdict = "VALID" if card_report["valid"] else "INVALID"
        print(f"(d) card built and checked: {card_files[0]} ({verdict})", flush=True)
        if card_summary:
            print(textwrap.indent(card_summary, "      "), flush=True)
        pngs = render_pngs(build, fcstd, card_files[0], out, env)
        print(f"(e) pictures rendered: {', '.join(os.path.basename(p) for p in pngs)}", flush=True)
        sheet_files, sheets = make_sheets(build, card_files[0], out, env)
        print(
            f"(f) cutting sheets: {len(sheets['pieces'])} pieces on {sheets['sheets']} A3 "
            f"sheet(s) (shelf packing: {sheets['shelf_packer_sheets']}), round trip "
            f"{sheets['round_trip']['max_error']:.2g} mm, in {os.path.dirname(sheet_files[0])}",
            flush=True,
        )
    except DemoError as e:
        print(f"run_demo: FAILED {e}", file=sys.stderr)
        return 1
    except subprocess.TimeoutExpired as e:
        print(f"run_demo: FAILED: '{e.cmd[0]}' timed out after {e.timeout} s", file=sys.stderr)
        return 1

    print("\nOutputs:")
    print(f"  {os.path.join(out, 'fit')}/  (the pop-up from {os.path.basename(args.model)}:")
    print("      design.FCStd, report.json, preview.png, sheets/)")
    print(
        f"  {os.path.join(out, 'animate')}/  (the pop-up from {os.path.basename(args.animation)}:"
    )
    print("      design.FCStd, report.json, paths.png, motion.gif, sheets/)")
    for path in [design, *report_files, fcstd, *card_files, *pngs, *sheet_files]:
        print(f"  {path}")
    failed = False
    for name, result in (("demo_card.json", report), ("card.FCStd", card_report)):
        verdicts = ", ".join(
            f"{k} {'yes' if result[k] else 'NO'}"
            for k in ("foldable", "stable", "intersection_free", "enclosed")
        )
        print(f"Verdict {name}: {'VALID' if result['valid'] else 'INVALID'} ({verdicts})")
        failed = failed or not result["valid"]
    if sheets["errors"] or not sheets["round_trip"]["ok"]:
        print(f"Sheets: {len(sheets['errors'])} error(s); see {sheet_files[-3]}")
        failed = True
    try:
        verified, verdict, findings = verify_sheets(
            build, card_files[0], os.path.dirname(sheet_files[0]), env
        )
    except (DemoError, subprocess.TimeoutExpired, ValueError) as e:
        print(f"run_demo: FAILED (h) verify: {e}", file=sys.stderr)
        return 1
    for d in findings:
        print(f"  error: {d['code']}: {d['message']}")
    print(f"Verify {os.path.basename(sheet_files[0])} against card.FCStd: {verdict}")
    if failed:
        print("run_demo: FAILED the demo cards must be valid; see the reports", file=sys.stderr)
        return 1
    if not verified:
        print(
            "run_demo: FAILED popup verify: the cutting file does not make the card",
            file=sys.stderr,
        )
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
