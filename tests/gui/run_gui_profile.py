#!/usr/bin/python3
"""GUI test (ctest gui_profile): a tree drawn in a Sketcher sketch on a step fold's riser, as a
maker sees it in FreeCAD's GUI under Xvfb.

A card with a step (Width 60, RunBackdrop 20) at FoldAngle 90; a sketch of a tree (trunk 8 x 6,
crown 40 mm wide, apex above the riser) becomes the riser's ProfileSketch. The riser's face has
the analytic area, the feature is not in error, and, seen square to the riser, the profiled step
covers fewer pixels than the plain one. Saves tree_on_step.png (800x600, isometric) and
tree_square.png in its sandbox folder.

    POPUP_SOURCE_DIR=. POPUP_BUILD_DIR=build /usr/bin/python3 tests/gui/run_gui_profile.py
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gui_harness  # noqa: E402

TREE_AREA = 8 * 6 + (40 + 64.0 / 3) / 2 * 14

BODY = r"""
import Part


def inked(path):
    image = QtGui.QImage(path)
    return sum(
        image.pixel(x, y) & 0xFFFFFF != 0xFFFFFF
        for y in range(image.height())
        for x in range(image.width())
    )


def run():
    from popupwb import make

    doc = FreeCAD.newDocument("Tree")
    card = make.make_card(doc, width=200, depth=140, fold_angle=90.0, name="Card")
    step = make.make_step_fold(
        card, name="Step", offset=70, width=60, run_ground=30, run_backdrop=20
    )
    doc.recompute()
    view = Gui.ActiveDocument.ActiveView
    riser = step.Shape.Faces[0]
    normal = riser.normalAt(*riser.Surface.parameter(riser.CenterOfMass))
    result["plain_area"] = riser.Area
    card.ViewObject.Visibility = False  # only the step: its riser and tread
    # Square to the riser's printed side, world z (away from the ground fold) up on the screen.
    up = FreeCAD.Vector(0, 0, 1)
    up = (up - normal * up.dot(normal)).normalize()
    view.setCameraOrientation(FreeCAD.Rotation(up.cross(normal), up, normal, "ZYX"))
    view.fitAll()
    plain = os.path.join(CONFIG["out_dir"], "plain_square.png")
    save_screenshot(plain)
    sketch = doc.addObject("Sketcher::SketchObject", "Tree")
    points = [(-4, 0), (4, 0), (4, 6), (20, 6), (0, 36), (-20, 6), (-4, 6)]
    for a, b in zip(points, points[1:] + points[:1]):
        sketch.addGeometry(
            Part.LineSegment(FreeCAD.Vector(a[0], a[1], 0), FreeCAD.Vector(b[0], b[1], 0))
        )
    doc.recompute()
    sketch.ViewObject.Visibility = False
    step.ProfileSketch = sketch
    step.ProfilePart = "riser"
    doc.recompute()
    result["state"] = step.getStatusString()
    result["tree_area"] = step.Shape.Faces[0].Area
    Gui.updateGui()
    square = os.path.join(CONFIG["out_dir"], "tree_square.png")
    save_screenshot(square)
    result["plain_inked"] = inked(plain)
    result["tree_inked"] = inked(square)
    card.ViewObject.Visibility = True
    view.viewIsometric()
    view.fitAll()
    Gui.updateGui()
    count_non_white(save_screenshot(os.path.join(CONFIG["out_dir"], "tree_on_step.png")))
"""


def main():
    check = gui_harness.Checks("gui_profile")
    code, result, out_dir = gui_harness.run_macro("gui_profile", BODY)
    check("FreeCAD ran the macro", result is not None, f"exit {code}, see {out_dir}")
    if result is None:
        return check.exit_code()
    check("no errors in the macro", not result["errors"], "\n".join(result["errors"]))
    check("the plain riser is 60 x 20", abs(result.get("plain_area", 0) - 1200) < 1e-6)
    check(
        "the riser has the tree's area",
        abs(result.get("tree_area", 0) - TREE_AREA) < 1e-5,
        f"{result.get('tree_area')} vs {TREE_AREA}, {result.get('state')}",
    )
    check(
        "seen square, the tree covers less than the plain riser",
        0 < result.get("tree_inked", 0) < result.get("plain_inked", 0),
        f"{result.get('tree_inked')} vs {result.get('plain_inked')}",
    )
    check("the isometric shot shows the card", result.get("non_white_pixels", 0) > 10000)
    return check.exit_code()


if __name__ == "__main__":
    sys.exit(main())
