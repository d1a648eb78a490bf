#!/usr/bin/python3
"""GUI test (ctest gui_profile_picker): a card fitted to a model file, a sketch put on one of its
parts with PopUp_SetProfile, its cutting sheet exported with the model's artwork, in the real
FreeCAD GUI under Xvfb (tests/gui/gui_harness.py).

1. PopUp_FromModel on a model file: make_models' house written as OBJ with vertex colours (brick
   walls, slate roof). popupcore.load_model reads it in a child process forked from the FreeCAD
   GUI process; the panel fits it and OK builds the card, which keeps the file as SourceFile.
2. The fitted part with the largest smaller side gets a sketch: its own rectangle (read from the
   core's profile frame) with a tree-shaped window. A sketch with an open wire is refused first,
   in one line naming it, and changes nothing; OK stays refused. The panel's OK makes one undo
   step. The profiled face's area must equal the sketch's area (FreeCAD's faces of the sketch's
   wires) within 1e-6, and the face's plain area minus the tree's shoelace area. The mechanism's
   own task panel shows the same profile.
3. PopUp_CuttingSheet, then the export: the SVG's PRINT layer and the PDF hold the artwork images
   (the file's brick and slate among their pixels) and three registration marks per sheet where
   registration_marks.py puts them (re-read from the written files); the DXF has no image.
Screenshots in <build>/sandbox/gui_profile_picker/ (copies in docs/images/): profile_picker.png
(the command's panel), mechanism_panel_profile.png and profiled_card.png.

    POPUP_SOURCE_DIR=. POPUP_BUILD_DIR=build /usr/bin/python3 tests/gui/run_gui_profile_picker.py
"""

import json
import os
import shutil
import sys
import xml.etree.ElementTree as ElementTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_harness import SANDBOX, Checks, make_models, run_macro  # noqa: E402

NAME = "gui_profile_picker"
MARK = 5.0  # mm, the side of a registration mark (docs/DESIGN.md, Artwork)
SVG = "{http://www.w3.org/2000/svg}"
INKSCAPE_LABEL = "{http://www.inkscape.org/namespaces/inkscape}label"

BODY = r'''
import Part


def line_sketch(doc, name, loops, closed=True):
    """A sketch of straight segments through each loop of (x, y) points."""
    sketch = doc.addObject("Sketcher::SketchObject", name)
    for loop in loops:
        pairs = list(zip(loop, loop[1:] + (loop[:1] if closed else [])))
        for a, b in pairs:
            sketch.addGeometry(
                Part.LineSegment(FreeCAD.Vector(a[0], a[1], 0), FreeCAD.Vector(b[0], b[1], 0))
            )
    return sketch


def frame_box(scaffold, patch):
    """(u min, u max, v min, v max) of a patch's outline in its profile frame."""
    from popupwb.core import popupcore

    frame = popupcore.profile_frame(scaffold, patch.id)
    us = [float((x - frame.origin) @ frame.u) for x in patch.outer]
    vs = [float((x - frame.origin) @ frame.v) for x in patch.outer]
    return min(us), max(us), min(vs), max(vs)


def run():
    from popupwb import profiles
    from popupwb.model import card_scaffold
    from popupwb.commands import create_cutting_sheet, from_model
    from popupwb.features.cutting_sheet import export_cutting_sheet
    from popupwb.taskpanels import profile_panel

    log_start = report_view_text()
    doc = FreeCAD.newDocument("Profiled")
    pid = os.getpid()

    # 1. The model file through PopUp_FromModel's code path: load_model forks in this process.
    panel = from_model.open_panel(path=CONFIG["model"])
    result["same_process"] = os.getpid() == pid
    result["model_object"] = panel.obj.TypeId if panel else None
    result["model_vertices"] = len(panel.model.vertices) if panel else 0
    panel.up.setCurrentIndex(panel.up.findText("+Z"))
    panel.facing.setCurrentIndex(panel.facing.findText("-Y"))
    panel.max_mechanisms.setValue(6)
    panel.seed.setValue(2)
    result["accepted"] = bool(panel.accept())
    settle()
    card = panel.design.card
    result["source_file"] = card.SourceFile
    result["validity"] = card.Validity
    panel.obj.Visibility = False  # the imported mesh; the card keeps its own copy
    card.SourceModel.Visibility = False

    # 2. The largest rectangular part of the fitted mechanisms.
    built = card_scaffold.for_card(card)
    candidates = []
    for mechanism in panel.design.mechanisms:
        for part, (w, h) in profiles.profile_parts(mechanism).items():
            patch = next(p for p in built.scaffold.patches if p.name == f"{mechanism.Label}.{part}")
            u0, u1, v0, v1 = frame_box(built.scaffold, patch)
            candidates.append((min(w, h), mechanism.Name, part, (u0, u1, v0, v1)))
    candidates.sort()
    _, name, part, (u0, u1, v0, v1) = candidates[-1]
    mechanism = doc.getObject(name)
    result["mechanism"], result["part"] = mechanism.Label, part
    result["part_box"] = [u0, u1, v0, v1]
    faces_before = sorted(f.Area for f in mechanism.Shape.Faces)

    # A tree window in the middle of the part: trunk and a triangular crown.
    cu, cv, s = 0.5 * (u0 + u1), 0.5 * (v0 + v1), 0.7 * min(u1 - u0, v1 - v0)
    tree = [
        (cu - 0.1 * s, cv - 0.5 * s), (cu + 0.1 * s, cv - 0.5 * s), (cu + 0.1 * s, cv - 0.2 * s),
        (cu + 0.5 * s, cv - 0.2 * s), (cu, cv + 0.5 * s), (cu - 0.5 * s, cv - 0.2 * s),
        (cu - 0.1 * s, cv - 0.2 * s),
    ]
    rectangle = [(u0, v0), (u1, v0), (u1, v1), (u0, v1)]
    result["tree"] = tree
    sketch = line_sketch(doc, "TreeWindow", [rectangle, tree])
    open_sketch = line_sketch(doc, "OpenOutline", [rectangle], closed=False)
    doc.recompute()
    sketch.ViewObject.Visibility = False
    open_sketch.ViewObject.Visibility = False
    wires = sketch.Shape.Wires
    result["sketch_area"] = Part.Face(wires[0]).Area - Part.Face(wires[1]).Area if len(wires) == 2 else None
    if result["sketch_area"] is not None and Part.Face(wires[0]).Area < Part.Face(wires[1]).Area:
        result["sketch_area"] = -result["sketch_area"]

    # The command on the selection: the mechanism and the sketch.
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(mechanism)
    Gui.Selection.addSelection(sketch)
    result["command_active"] = Gui.Command.get("PopUp_SetProfile").isActive()
    from popupwb.commands import context_menu

    result["context_menu"] = [entry for _, entries in context_menu.entries() for entry in entries]
    undo_before = list(doc.UndoNames)
    Gui.runCommand("PopUp_SetProfile")
    settle()
    picker_panel = profile_panel.last_panel
    result["panel_open"] = picker_panel is not None and picker_panel.obj is mechanism
    picker = picker_panel.picker
    result["parts_offered"] = [picker.part.itemText(i) for i in range(picker.part.count())]

    result["before_refusal"] = [
        mechanism.ProfileSketch.Name if mechanism.ProfileSketch else None,
        mechanism.ProfilePart,
    ]
    refusal = picker.choose(open_sketch, part, "Clip")
    result["refusal"] = refusal
    result["after_refusal"] = [
        mechanism.ProfileSketch.Name if mechanism.ProfileSketch else None,
        mechanism.ProfilePart,
    ]
    result["refusal_shown"] = picker.text()
    result["ok_refused"] = picker_panel.accept() is False

    applied = picker.choose(sketch, part, "Clip")
    result["applied_error"] = applied
    result["picker_text"] = picker.text()
    result["status"] = picker_panel.status.text()
    settle()
    picker_panel.form.grab().save(CONFIG["picker_png"])
    result["accepted_profile"] = bool(picker_panel.accept())
    settle()
    result["undo_added"] = list(doc.UndoNames)[: len(doc.UndoNames) - len(undo_before)]
    result["profile_state"] = [
        mechanism.ProfileSketch.Name if mechanism.ProfileSketch else None,
        mechanism.ProfilePart,
        mechanism.ProfileMode,
        mechanism.getStatusString(),
    ]
    faces_after = sorted(f.Area for f in mechanism.Shape.Faces)
    # Multiset difference: equal parts (two sides of a box) have equal areas.
    gone, new = [], list(faces_after)
    for a in faces_before:
        match = next((b for b in new if abs(a - b) < 1e-9), None)
        if match is None:
            gone.append(a)
        else:
            new.remove(match)
    result["faces_gone"], result["faces_new"] = gone, new
    holed = [f for f in mechanism.Shape.Faces if len(f.Wires) == 2]
    result["holed_faces"] = len(holed)
    from popupwb import validity

    result["card_valid"] = validity.run_check(card)["valid"]
    # A three-quarter view onto the printed side of the profiled part, world z up.
    Gui.Selection.clearSelection()
    view = Gui.ActiveDocument.ActiveView
    if holed:
        face = holed[0]
        normal = face.normalAt(*face.Surface.parameter(face.CenterOfMass))
        up = FreeCAD.Vector(0, 0, 1)
        side = normal.cross(up)
        towards = (normal + up * 0.7 + side * 0.5).normalize()
        up = (up - towards * up.dot(towards)).normalize()
        view.setCameraOrientation(FreeCAD.Rotation(up.cross(towards), up, towards, "ZYX"))
    else:
        view.viewIsometric()
    view.fitAll()
    settle()
    save_screenshot(CONFIG["card_png"], 1200, 900)
    count_non_white(CONFIG["card_png"], "card_")

    # One undo step: undo takes the whole profile off, redo puts it back.
    doc.undo()
    doc.recompute()
    result["after_undo"] = [
        mechanism.ProfileSketch.Name if mechanism.ProfileSketch else None,
        sorted(f.Area for f in mechanism.Shape.Faces) == faces_before,
    ]
    doc.redo()
    doc.recompute()
    result["after_redo"] = mechanism.ProfileSketch.Name if mechanism.ProfileSketch else None

    # The mechanism's own task panel shows the same profile in its Profile group.
    from popupwb.taskpanels import mechanism_panel

    Gui.ActiveDocument.setEdit(mechanism.Name, 0)
    settle()
    own = mechanism_panel.last_panel
    if own is not None and own.obj is mechanism and own.profile is not None:
        result["mechanism_panel_profile"] = [
            own.profile.sketch.currentText(),
            own.profile.part.currentText(),
            own.profile.mode.currentText(),
        ]
        own.form.grab().save(CONFIG["mechanism_panel_png"])
        own.reject()
        settle()
    result["profile_after_panel"] = mechanism.ProfileSketch.Name if mechanism.ProfileSketch else None

    # 3. Cutting sheet and export, with the model's artwork.
    sheet = create_cutting_sheet.create(card)
    result["sheet_state"] = sheet.getStatusString() if sheet else None
    result["print_artwork"] = bool(sheet.PrintArtwork) if sheet else None
    paths = export_cutting_sheet(sheet, CONFIG["export_dir"])
    result["paths"] = {k: v for k, v in paths.items()}
    result["log"] = report_view_text()[len(log_start):]
'''


BRICK = (0.70, 0.25, 0.15)  # walls
SLATE = (0.20, 0.30, 0.55)  # roof
EAVES = 30.0  # mm: make_models' house has its walls below, its roof above


def _write_house(path):
    """make_models' house as OBJ text with vertex colours (`v x y z r g b`, which assimp reads):
    each triangle gets its own corners, brick below the eaves, slate above, so the artwork's
    colours can only come from the file."""
    module = make_models()
    points, facets = module.mesh_of(module.SOLIDS["house"]()).Topology
    lines = []
    for facet in facets:
        corners = [points[i] for i in facet]
        roof = sum(p.z for p in corners) / 3 > EAVES
        colour = " ".join(f"{c:g}" for c in (SLATE if roof else BRICK))
        lines += [f"v {p.x:.9g} {p.y:.9g} {p.z:.9g} {colour}" for p in corners]
    lines += [f"f {3 * k + 1} {3 * k + 2} {3 * k + 3}" for k in range(len(facets))]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path


def artwork_colours(images):
    """How many opaque pixels of the SVG's artwork images are nearest to BRICK and to SLATE
    (shading is not applied to vertex colours, docs/DESIGN.md, Artwork)."""
    import base64
    import io

    import numpy
    from PIL import Image

    near = {"brick": 0, "slate": 0, "other": 0}
    for image in images:
        href = image.get("{http://www.w3.org/1999/xlink}href") or image.get("href")
        rgba = numpy.asarray(
            Image.open(io.BytesIO(base64.b64decode(href.split(",", 1)[1]))).convert("RGBA")
        )
        opaque = rgba[rgba[..., 3] == 255][:, :3].astype(float) / 255
        for name, colour in (("brick", BRICK), ("slate", SLATE)):
            near[name] += int((numpy.abs(opaque - colour).max(axis=1) < 0.02).sum())
        near["other"] += len(opaque)
    near["other"] -= near["brick"] + near["slate"]
    return near


def shoelace(loop):
    return 0.5 * abs(
        sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(loop, loop[1:] + loop[:1]))
    )


def mark_corners(width, height, margin):
    """Lower-left corners of the three marks: centred in the margin band, top-left, top-right and
    bottom-left (docs/DESIGN.md, Artwork; registration_marks.py)."""
    inset = (margin - MARK) / 2
    return {
        (round(inset, 6), round(height - inset - MARK, 6)),
        (round(width - inset - MARK, 6), round(height - inset - MARK, 6)),
        (round(inset, 6), round(inset, 6)),
    }


def read_svg(path):
    """(PRINT layer images, mark corners (sheet mm, y up)) of one written SVG."""
    root = ElementTree.parse(path).getroot()
    height = float(root.get("viewBox").split()[3])
    layers = [g for g in root.iter(SVG + "g") if g.get(INKSCAPE_LABEL) == "PRINT"]
    if len(layers) != 1:
        return [], set(), root
    images = [
        i
        for i in layers[0].iter(SVG + "image")
        if (i.get("{http://www.w3.org/1999/xlink}href") or i.get("href") or "").startswith(
            "data:image/png;base64,"
        )
    ]
    marks = {
        (round(float(r.get("x")), 6), round(height - float(r.get("y")) - MARK, 6))
        for r in layers[0].findall(SVG + "rect")
        if r.get("fill") == "#000000"
        and float(r.get("width")) == MARK
        and float(r.get("height")) == MARK
    }
    return images, marks, root


def read_pdf(path):
    """([images drawn per page], [mark rectangles per page]) of the written PDF (pypdf)."""
    from pypdf import PdfReader
    from pypdf.generic import ContentStream

    reader = PdfReader(path)
    images, marks = [], []
    for page in reader.pages:
        xobjects = page["/Resources"].get("/XObject", {})
        kinds = {name: x.get_object()["/Subtype"] for name, x in xobjects.items()}
        drawn = rects = 0
        for operands, operator in ContentStream(page.get_contents(), reader).operations:
            if operator == b"Do" and kinds.get(operands[0]) == "/Image":
                drawn += 1
            if operator == b"re" and [float(v) for v in operands[2:]] == [MARK, MARK]:
                rects += 1
        images.append(drawn)
        marks.append(rects)
    return images, marks


def main():
    check = Checks(NAME)
    models = os.path.join(SANDBOX, NAME + "_models")
    os.makedirs(models, exist_ok=True)
    export_dir = os.path.join(SANDBOX, NAME + "_export")
    shutil.rmtree(export_dir, ignore_errors=True)
    images_dir = os.path.join(SANDBOX, NAME)  # docs/images/ holds copies of the last good run
    config = {
        "model": _write_house(os.path.join(models, "house.obj")),
        "export_dir": export_dir,
        "picker_png": os.path.join(images_dir, "profile_picker.png"),
        "card_png": os.path.join(images_dir, "profiled_card.png"),
        "mechanism_panel_png": os.path.join(images_dir, "mechanism_panel_profile.png"),
    }
    code, result, out_dir = run_macro(NAME, BODY, config, timeout=400)
    r = check.macro_ran(code, result, out_dir)

    # 1. The model file in the GUI process.
    check(
        "load_model read the file in a child process and this one went on",
        r.get("same_process") is True
        and r.get("model_object") == "Mesh::Feature"
        and r.get("model_vertices", 0) > 0,
        f"{r.get('model_object')}, {r.get('model_vertices')} vertices",
    )
    check("OK built the card from the file", r.get("accepted") is True)
    check(
        "the card keeps the model file for its artwork",
        r.get("source_file") == config["model"],
        r.get("source_file"),
    )
    check("the fitted card is valid", r.get("validity") == "Valid", r.get("validity"))

    # 2. The picker.
    check("PopUp_SetProfile is active on a mechanism and a sketch", r.get("command_active") is True)
    check(
        "a mechanism's right-click menu offers it",
        "PopUp_SetProfile" in (r.get("context_menu") or []),
        r.get("context_menu"),
    )
    check("the command opens the panel on the mechanism", r.get("panel_open") is True)
    check(
        "the panel offers the mechanism's parts",
        r.get("part") in (r.get("parts_offered") or []),
        r.get("parts_offered"),
    )
    refusal = r.get("refusal") or ""
    check(
        "an open wire is refused in one line naming the sketch",
        "OpenOutline" in refusal and "open" in refusal and "\n" not in refusal,
        refusal,
    )
    check(
        "the refusal changes nothing (the selected sketch the panel opened with stays)",
        r.get("after_refusal")
        == r.get("before_refusal")
        == ["TreeWindow", r.get("before_refusal", [0, 0])[1]],
        f"{r.get('before_refusal')} -> {r.get('after_refusal')}",
    )
    check(
        "the refusal shows in the panel", r.get("refusal_shown") == refusal, r.get("refusal_shown")
    )
    check("OK is refused while the refusal stands", r.get("ok_refused") is True)
    check("the tree sketch is applied", r.get("applied_error") is None, r.get("applied_error"))
    check("the panel's OK commits", r.get("accepted_profile") is True)
    state = r.get("profile_state") or [None] * 4
    check(
        "the mechanism has the sketch on the part, Clip, and builds",
        state[:3] == ["TreeWindow", r.get("part"), "Clip"] and "Valid" in str(state[3]),
        state,
    )
    check(
        "one undo step for the whole profile",
        len(r.get("undo_added") or []) == 1 and r["undo_added"][0].startswith("Profile of"),
        r.get("undo_added"),
    )
    check(
        "undo takes the profile off, redo puts it back",
        r.get("after_undo") == [None, True] and r.get("after_redo") == "TreeWindow",
        f"{r.get('after_undo')}, {r.get('after_redo')}",
    )
    check(
        "the mechanism's own panel shows the profile, and Cancel there keeps it",
        r.get("mechanism_panel_profile") == ["TreeWindow", r.get("part"), "Clip"]
        and r.get("profile_after_panel") == "TreeWindow",
        f"{r.get('mechanism_panel_profile')}, {r.get('profile_after_panel')}",
    )
    gone, new = r.get("faces_gone") or [], r.get("faces_new") or []
    tree_area = shoelace([tuple(p) for p in r.get("tree") or [(0, 0)]])
    sketch_area = r.get("sketch_area") or 0.0
    ok = len(gone) == 1 and len(new) == 1 and sketch_area > 0
    check(
        "exactly one face changed, and it has a window",
        ok and r.get("holed_faces") == 1,
        f"gone {gone}, new {new}, holed {r.get('holed_faces')}",
    )
    if ok:
        relative = abs(new[0] - sketch_area) / sketch_area
        check(
            "profiled area = the sketch's area (FreeCAD faces of its wires), within 1e-6",
            relative < 1e-6,
            f"{new[0]:.9f} vs {sketch_area:.9f} mm², relative {relative:.2e}",
        )
        expected = gone[0] - tree_area
        relative = abs(new[0] - expected) / expected
        check(
            "profiled area = plain area - the tree's shoelace area, within 1e-6",
            relative < 1e-6,
            f"{new[0]:.9f} vs {gone[0]:.6f} - {tree_area:.6f}, relative {relative:.2e}",
        )
    check("the profiled card passes the validity check", r.get("card_valid") is True)
    check("screenshot of the card", r.get("card_non_white_pixels", 0) > 10000, config["card_png"])
    check(
        "screenshot of the picker",
        os.path.getsize(config["picker_png"]) > 1000
        if os.path.exists(config["picker_png"])
        else False,
    )

    # 3. The exported files, re-read.
    check("the cutting sheet prints artwork by default", r.get("print_artwork") is True)
    paths = r.get("paths") or {}
    try:
        with open(paths["sheet_set"]) as f:
            sheet_set = json.load(f)
    except (KeyError, OSError, ValueError) as error:
        check("the export wrote sheets.json", False, str(error))
        return check.exit_code()
    paper = sheet_set["paper"]
    margin = sheet_set["options"]["margin"]
    corners = mark_corners(paper["width"], paper["height"], margin)
    patches = sum(len(p["patches"]) for p in sheet_set["pieces"])
    svg_images = 0
    for path in paths["svg"]:
        images, marks, root = read_svg(path)
        svg_images += len(images)
        check(
            f"{os.path.basename(path)}: three registration marks where they belong",
            marks == corners,
            f"{sorted(marks)} vs {sorted(corners)}",
        )
    check(
        "the SVGs carry the artwork: PNG images on the PRINT layer, at most one per patch",
        0 < svg_images <= patches,
        f"{svg_images} images, {patches} patches",
    )
    near = artwork_colours([i for path in paths["svg"] for i in read_svg(path)[0]])
    check(
        "the artwork prints the file's colours: brick walls and slate roof",
        near["brick"] > 1000 and near["slate"] > 1000,
        near,
    )
    pdf_images, pdf_marks = read_pdf(paths["pdf"])
    check(
        "the PDF has one page per sheet, each with three 5 mm marks",
        len(pdf_marks) == len(sheet_set["sheets"]) and all(m == 3 for m in pdf_marks),
        pdf_marks,
    )
    check(
        "the PDF draws as many images as the SVGs hold",
        sum(pdf_images) == svg_images,
        f"{pdf_images} vs {svg_images}",
    )
    with open(paths["dxf"], "rb") as f:
        check("the DXF stays a cut file (no image)", b"IMAGE" not in f.read())
    check.no_traceback(r.get("log"), shown=(r.get("log") or "")[-2000:])
    return check.exit_code()


if __name__ == "__main__":
    sys.exit(main())
