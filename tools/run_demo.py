#!/usr/bin/python3
"""`make demo`: check the bundled demo card, build a FreeCAD document of it and render a picture.

    /usr/bin/python3 tools/run_demo.py --build build --out out/demo

Steps: (a) copy resources/samples/demo_card.json into the output folder, (b) check its validity
(validity_report.json / .txt), (c) build demo_card.FCStd with three Scaffold objects at fold
angles 180, 90 and 30 degrees side by side (headless FreeCAD in a subprocess), (d) render
demo_card.png with the FreeCAD GUI under Xvfb, (e) list the outputs and the verdict.
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
FREECAD_LIB = "/usr/lib/freecad-python3/lib"
DEMO_DESIGN = os.path.join(REPO, "resources", "samples", "demo_card.json")
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
    mod = os.path.join(home, "Mod")
    os.makedirs(mod, exist_ok=True)
    link = os.path.join(mod, "PopUp")
    target = os.path.join(REPO, "Workbench")
    if os.path.realpath(link) != os.path.realpath(target):
        if os.path.exists(link) and not os.path.islink(link):
            raise DemoError(f"{link} exists and is not a link to {target}; remove it")
        # Atomic: the tests create the same link, possibly at the same time.
        temporary = f"{link}.{os.getpid()}"
        os.symlink(target, temporary)
        os.replace(temporary, link)
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


# FreeCAD GUI macro; its status (ok + share of non-white pixels, or the error) goes to a file
# because the GUI's exit code does not reflect what the macro did.
RENDER_MACRO = textwrap.dedent(
    """
    import json
    import math
    import traceback
    import FreeCAD
    import FreeCADGui as Gui
    from PySide2 import QtCore, QtGui

    FCSTD = {fcstd!r}
    PNG = {png!r}
    STATUS = {status!r}
    status = {{"ok": False}}
    try:
        doc = FreeCAD.openDocument(FCSTD)
        Gui.updateGui()
        for obj in doc.Objects:
            obj.ViewObject.Visibility = True  # saved headless: every object opens hidden
        view = Gui.getDocument(doc.Name).ActiveView
        view.viewIsometric()
        # In the exact isometric view the half-open card's ground is seen edge-on: turn the
        # camera a little about the vertical axis.
        d = view.getViewDirection()
        c, s = math.cos(math.radians({turn})), math.sin(math.radians({turn}))
        view.setViewDirection((c * d.x - s * d.y, s * d.x + c * d.y, d.z))
        view.fitAll()
        view.saveImage(PNG, {width}, {height}, "White")
        image = QtGui.QImage(PNG)
        inked = total = 0
        for y in range(0, image.height(), 4):
            for x in range(0, image.width(), 4):
                total += 1
                if QtGui.QColor(image.pixel(x, y)).lightness() < 235:
                    inked += 1
        status = {{"ok": True, "inked": inked / max(total, 1)}}
        FreeCAD.closeDocument(doc.Name)
    except Exception:
        status = {{"ok": False, "error": traceback.format_exc()}}
    finally:
        with open(STATUS, "w") as f:
            json.dump(status, f)
        QtCore.QTimer.singleShot(0, Gui.getMainWindow().close)
    """
)


def render_png(build, fcstd, out, env):
    """(d) Isometric picture of the three cards from the real FreeCAD GUI under Xvfb."""
    for tool in ("xvfb-run", "freecad"):
        if shutil.which(tool) is None:
            raise DemoError(f"(d) render PNG: '{tool}' not found (run 'make deps')")
    png = os.path.join(out, "demo_card.png")
    work = os.path.join(build, "sandbox", "demo")
    os.makedirs(work, exist_ok=True)
    macro = os.path.join(work, "render_demo.FCMacro")
    status_path = os.path.join(work, "render_status.json")
    for stale in (png, status_path):
        if os.path.exists(stale):
            os.remove(stale)
    with open(macro, "w", encoding="utf-8") as f:
        f.write(
            RENDER_MACRO.format(
                fcstd=fcstd,
                png=png,
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
        raise DemoError(f"(d) render PNG: the FreeCAD GUI did not finish in {GUI_TIMEOUT} s")
    try:
        with open(status_path, encoding="utf-8") as f:
            status = json.load(f)
    except (OSError, ValueError):
        tail = (proc.stderr.strip() or proc.stdout.strip()).splitlines()[-10:]
        raise DemoError(
            f"(d) render PNG: the macro did not run (freecad exit {proc.returncode}):\n  "
            + "\n  ".join(tail or ["no output"])
        )
    if not status.get("ok"):
        raise DemoError("(d) render PNG: macro failed:\n" + status.get("error", "unknown error"))
    if not os.path.isfile(png):
        raise DemoError(f"(d) render PNG: {png} was not written")
    if status["inked"] < 0.01:
        raise DemoError(f"(d) render PNG: {png} is blank ({status['inked']:.2%} non-white)")
    return png


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="CMake build folder (default: build)")
    parser.add_argument("--out", default="out/demo", help="output folder (default: out/demo)")
    parser.add_argument(
        "--design",
        default=DEMO_DESIGN,
        help="design to show (default: resources/samples/demo_card.json)",
    )
    args = parser.parse_args(argv)
    build = os.path.abspath(args.build)
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    try:
        env = sandbox_env(build)
        design = copy_design(os.path.abspath(args.design), out)
        print(f"(a) design copied: {design}", flush=True)
        report, report_files = check_design(build, design, out)
        print(f"(b) validity checked: {'VALID' if report['valid'] else 'INVALID'}", flush=True)
        fcstd, summary = build_document(build, design, out, env)
        print(f"(c) document built: {fcstd}", flush=True)
        if summary:
            print(textwrap.indent(summary, "      "), flush=True)
        png = render_png(build, fcstd, out, env)
        print(f"(d) picture rendered: {png}", flush=True)
    except DemoError as e:
        print(f"run_demo: FAILED {e}", file=sys.stderr)
        return 1
    except subprocess.TimeoutExpired as e:
        print(f"run_demo: FAILED: '{e.cmd[0]}' timed out after {e.timeout} s", file=sys.stderr)
        return 1

    print("\nOutputs:")
    for path in [design, *report_files, fcstd, png]:
        print(f"  {path}")
    verdicts = ", ".join(
        f"{k} {'yes' if report[k] else 'NO'}"
        for k in ("foldable", "stable", "intersection_free", "enclosed")
    )
    print(f"\nVerdict: {'VALID' if report['valid'] else 'INVALID'} ({verdicts})")
    if not report["valid"]:
        print(
            "run_demo: FAILED the demo card must be valid; see validity_report.txt", file=sys.stderr
        )
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
