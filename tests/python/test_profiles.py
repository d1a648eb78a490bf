"""Profiles on mechanism features (issue 12, section 3): a tree drawn in a Sketcher sketch cut
into a step fold's riser. Areas and lengths are worked out by hand from the tree below, never
read from the code under test.

The step: Offset 60, Width 60, RunGround 30, RunBackdrop 20, so its riser is u in [-30, 30],
v in [0, 20] in its profile frame (u along the ground fold from its middle, v up the riser).
The tree: trunk 8 x 6 mm, crown a triangle 40 mm wide at v = 6 with its apex at v = 36, above the
riser: clipped flat at v = 20, where it is 64/3 mm wide.
"""

import json
import math
import os

import pytest

from freecad_documents import in_error, recompute_ok

TREE = [(-4, 0), (4, 0), (4, 6), (20, 6), (0, 36), (-20, 6), (-4, 6)]
TRUNK = 8 * 6
TOP = 64.0 / 3  # the crown's width where the riser (v = 20) cuts it
TREE_AREA = TRUNK + (40 + TOP) / 2 * 14
SLANT = math.hypot(20 - TOP / 2, 20 - 6)  # a crown side from v = 6 up to the cut


def clipped_tree_area(half_width):
    """The tree on a riser u in [-half_width, half_width], v in [0, 20] (half_width >= 4)."""
    area = TRUNK
    steps = 20000  # the crown's width is piecewise linear in v: the midpoint rule is exact
    dv = 14.0 / steps
    for k in range(steps):
        v = 6 + (k + 0.5) * dv
        area += 2 * min(20 * (36 - v) / 30, half_width) * dv
    return area


def tree_sketch(doc, points=TREE, name="Tree"):
    import FreeCAD
    import Part

    sketch = doc.addObject("Sketcher::SketchObject", name)
    for a, b in zip(points, points[1:] + points[:1]):
        sketch.addGeometry(
            Part.LineSegment(FreeCAD.Vector(a[0], a[1], 0), FreeCAD.Vector(b[0], b[1], 0))
        )
    return sketch


def stepped_card(doc, popup):
    card = popup.make.make_card(doc, width=200, depth=140)
    step = popup.make.make_step_fold(
        card, name="Step", offset=60, width=60, run_ground=30, run_backdrop=20
    )
    return card, step


def riser_face(step):
    return step.Shape.Faces[0]  # the step's patches in id order: riser, tread


@pytest.fixture
def tree_on_step(doc, popup):
    card, step = stepped_card(doc, popup)
    recompute_ok(doc, card, step)
    sketch = tree_sketch(doc)
    doc.recompute()
    step.ProfileSketch = sketch
    step.ProfilePart = "riser"
    recompute_ok(doc, card, step, sketch)
    return card, step, sketch


def test_the_tree_cuts_the_riser_to_the_analytic_area(doc, popup, tree_on_step):
    card, step, _ = tree_on_step
    assert riser_face(step).Area == pytest.approx(TREE_AREA, abs=1e-5)
    assert step.Shape.Faces[1].Area == pytest.approx(60 * 30, abs=1e-6)  # the tread is whole
    built = popup.card_scaffold.for_card(card)
    riser = next(p for p in built.scaffold.patches if p.name == "Step.riser")
    tread = next(p for p in built.scaffold.patches if p.name == "Step.tread")
    nose = [h for h in built.scaffold.hinges if {h.patch_a, h.patch_b} == {riser.id, tread.id}]
    assert len(nose) == 1
    assert math.dist(nose[0].from_point, nose[0].to_point) == pytest.approx(TOP, abs=1e-5)


def test_the_tree_step_is_valid(doc, popup, tree_on_step):
    card, _, _ = tree_on_step
    report = popup.validity.run_check(card)
    assert report["valid"] is True, report["diagnostics"]


def _loop_area(loop):
    return 0.5 * abs(sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(loop, loop[1:] + loop[:1])))


def test_the_cutting_sheet_has_the_tree(doc, popup, tree_on_step, tmp_path):
    from popupwb.sheets.dxf_reader import read_dxf
    from popupwb.sheets.export import export_sheets, layout

    card, _, _ = tree_on_step
    built = popup.card_scaffold.for_card(card)
    paths = export_sheets(layout(built.scaffold, paper="A3", kerf=0.0), str(tmp_path))
    drawings = read_dxf(paths["dxf"])
    drawings = drawings if isinstance(drawings, list) else [drawings]
    folds = [f for d in drawings for f in d.folds]
    # The nose is the riser-tread fold: as wide as the crown where the riser cuts it.
    nose = [f for f in folds if abs(math.dist(f.start, f.end) - TOP) < 1e-4]
    assert len(nose) == 1, [math.dist(f.start, f.end) for f in folds]
    loops = [loop for d in drawings for loop in d.cut]
    mid = ((nose[0].start[0] + nose[0].end[0]) / 2, (nose[0].start[1] + nose[0].end[1]) / 2)

    def near(loop):
        return min(math.dist(p, mid) for p in loop)

    piece = min(loops, key=near)
    edges = [math.dist(a, b) for a, b in zip(piece, piece[1:] + piece[:1])]
    # The crown's two clipped sides and its two 16 mm undersides are cut edges of the piece.
    assert sum(abs(e - SLANT) < 1e-4 for e in edges) == 2, edges
    assert sum(abs(e - 16.0) < 1e-4 for e in edges) == 2, edges
    # The piece is the tread and the tree unfolded across the nose, plus its glue tabs.
    assert _loop_area(piece) >= 60 * 30 + TREE_AREA - 1e-4


@pytest.mark.parametrize(
    "mode, expected",
    [("Clip", clipped_tree_area(15)), ("Scale", TREE_AREA / 2)],
)
def test_a_narrower_step_clips_or_scales_the_tree(doc, popup, tree_on_step, mode, expected):
    card, step, _ = tree_on_step
    step.ProfileMode = mode
    recompute_ok(doc, card, step)
    assert json.loads(step.Profiles)["riser"]["reference"] == pytest.approx([60, 20])
    step.Width = 30  # Clip: the tree stays 40 mm wide, cut at u = ±15; Scale: u halves
    recompute_ok(doc, card, step)
    assert riser_face(step).Area == pytest.approx(expected, abs=1e-4)
    assert popup.validity.run_check(card)["valid"] is True


def test_editing_the_sketch_recomputes_the_riser(doc, popup, tree_on_step):
    import FreeCAD

    card, step, sketch = tree_on_step
    assert popup.validity.run_check(card)["valid"] is True
    assert card.Validity == "Valid"
    # Move the apex down to v = 26: the crown is 40 mm wide at v = 6, 12 mm at v = 20.
    apex = TREE.index((0, 36))
    sketch.movePoint(apex - 1, 2, FreeCAD.Vector(0, 26, 0))
    sketch.movePoint(apex, 1, FreeCAD.Vector(0, 26, 0))
    doc.recompute()
    assert not in_error(step), step.getStatusString()
    assert riser_face(step).Area == pytest.approx(TRUNK + (40 + 12) / 2 * 14, abs=1e-5)
    assert card.Validity == "NotChecked"  # the verdict was for the tree before the edit
    assert "Touched" not in card.State


def round_sketch(doc, popup, radius, name):
    import FreeCAD
    import Part

    card, step = stepped_card(doc, popup)
    recompute_ok(doc, card, step)
    sketch = doc.addObject("Sketcher::SketchObject", name)
    sketch.addGeometry(Part.Circle(FreeCAD.Vector(0, 10, 0), FreeCAD.Vector(0, 0, 1), radius))
    doc.recompute()
    step.ProfileSketch = sketch
    step.ProfilePart = "riser"
    doc.recompute()
    return card, step


def test_a_round_outline_stays_round(doc, popup):
    # A disc of radius 12 centred at v = 10 on the riser [0, 20]: two segments of height 2 cut
    # off by the folds. Arcs are discretised to 0.002 mm, so the area is within 2e-4 of it.
    card, step = round_sketch(doc, popup, 12.0, "Wheel")
    assert not in_error(step), step.getStatusString()
    r, d = 12.0, 10.0
    segment = r * r * math.acos(d / r) - d * math.sqrt(r * r - d * d)
    expected = math.pi * r * r - 2 * segment
    assert riser_face(step).Area == pytest.approx(expected, rel=2e-4)
    assert riser_face(step).Area < expected  # inscribed chords: from below
    # 0.002 mm chords on a 12 mm circle: 2 acos(1 - 0.002 / 12) = 0.0365 rad each, over the
    # 2π - 4 acos(10 / 12) rad of arc the riser keeps: 108 chords and more.
    arc = 2 * math.pi - 4 * math.acos(d / r)
    assert len(riser_face(step).Vertexes) >= arc / (2 * math.acos(1 - 0.002 / r))


def test_a_disc_on_no_fold_is_refused(doc, popup):
    card, step = round_sketch(doc, popup, 8.0, "Disc")  # v in [2, 18]: it reaches no fold
    assert in_error(step)
    message = step.getStatusString()
    assert "profile 'Disc' leaves no paper along fold" in message, message
    assert popup.validity.run_check(card)["valid"] is False


def test_an_open_sketch_is_named_in_one_line(doc, popup):
    import FreeCAD
    import Part

    card, step = stepped_card(doc, popup)
    recompute_ok(doc, card, step)
    sketch = doc.addObject("Sketcher::SketchObject", "Open")
    points = [(-10, 0), (10, 0), (10, 25), (-10, 25)]
    for a, b in zip(points, points[1:]):
        sketch.addGeometry(
            Part.LineSegment(FreeCAD.Vector(a[0], a[1], 0), FreeCAD.Vector(b[0], b[1], 0))
        )
    doc.recompute()
    step.ProfileSketch = sketch
    step.ProfilePart = "riser"
    doc.recompute()
    assert in_error(step)
    message = step.getStatusString()
    assert "ProfileSketch Open" in message and "open" in message and "\n" not in message
    assert popup.validity.run_check(card)["valid"] is False


def test_a_circle_inside_the_tree_is_a_hole(doc, popup, tree_on_step):
    import FreeCAD
    import Part

    card, step, sketch = tree_on_step
    sketch.addGeometry(Part.Circle(FreeCAD.Vector(0, 14, 0), FreeCAD.Vector(0, 0, 1), 2))
    doc.recompute()
    assert not in_error(step), step.getStatusString()
    face = riser_face(step)
    assert len(face.Wires) == 2
    # The hole is the circle's inscribed polygon: within its chord deficit of π r².
    assert face.Area == pytest.approx(TREE_AREA - math.pi * 4, abs=2 * math.pi * 2 * 0.002)
    assert face.Area > TREE_AREA - math.pi * 4


def test_only_a_sketch_can_outline(doc, popup):
    card, step = stepped_card(doc, popup)
    box = doc.addObject("Part::Box", "Box")
    doc.recompute()
    step.ProfileSketch = box
    step.ProfilePart = "riser"
    doc.recompute()
    assert in_error(step)
    assert "ProfileSketch = Box (Part::Box), must be a Sketcher sketch" in step.getStatusString()


def test_a_crossing_sketch_is_named(doc, popup):
    card, step = stepped_card(doc, popup)
    recompute_ok(doc, card, step)
    sketch = tree_sketch(doc, [(-20, 0), (20, 30), (20, 0), (-20, 30)], name="Bow")
    doc.recompute()
    step.ProfileSketch = sketch
    step.ProfilePart = "riser"
    doc.recompute()
    assert in_error(step)
    assert "Bow" in step.getStatusString()


def test_a_stored_profile_on_a_box_top(doc, popup):
    card = popup.make.make_card(doc, width=200, depth=140)
    box = popup.make.make_box_fold(
        card, name="B1", offset=60, width=80, depth_ground=30, depth_backdrop=30, height=30
    )
    recompute_ok(doc, card, box)
    # TG: u along the top crease from its middle, v toward L (30 mm): two 10 x 10 corners off.
    popup.profiles.set_profile(
        box, "TG", [(-40, 0), (40, 0), (40, 20), (30, 30), (-30, 30), (-40, 20)]
    )
    recompute_ok(doc, card, box)
    built = popup.card_scaffold.for_card(card)
    top = next(p for p in built.scaffold.patches if p.name == "B1.TG")
    assert top.area() == pytest.approx(80 * 30 - 2 * 50, abs=1e-5)
    assert popup.validity.run_check(card)["valid"] is True
    popup.profiles.set_profile(box, "mast", [(0, 0), (1, 0), (0, 1)])
    doc.recompute()
    assert in_error(box) and "must be one of its parts" in box.getStatusString()


def test_a_broken_profiles_property_is_named(doc, popup):
    card, step = stepped_card(doc, popup)
    step.Profiles = '{"riser": {"outer": [[0, 0], [1]]}}'
    doc.recompute()
    assert in_error(step)
    assert "Step: Profiles['riser'].outer must be a list of [u, v] pairs" in step.getStatusString()
    step.Profiles = "{not json"
    doc.recompute()
    assert in_error(step) and "Step: Profiles is not JSON" in step.getStatusString()


def test_old_documents_get_empty_profiles(doc, popup):
    card, step = stepped_card(doc, popup)
    for name in ("Profiles", "ProfileSketch", "ProfilePart", "ProfileMode"):
        step.removeProperty(name)
    step.Proxy.onDocumentRestored(step)
    assert step.Profiles == "" and step.ProfileSketch is None and step.ProfileMode == "Clip"
    recompute_ok(doc, card, step)
    assert riser_face(step).Area == pytest.approx(60 * 20, abs=1e-9)


def test_the_tree_survives_save_and_reopen(doc, popup, tree_on_step, tmp_path, run_fresh_freecad):
    card, step, _ = tree_on_step
    step.ProfileMode = "Scale"
    doc.recompute()
    path = str(tmp_path / "tree.FCStd")
    doc.saveAs(path)
    result = run_fresh_freecad(
        f"""
import json
doc = FreeCAD.openDocument({path!r})
step = doc.getObject("Step")
proxy_loaded = step.Proxy is not None
doc.recompute()
before = step.Shape.Faces[0].Area
step.Width = 30
doc.recompute()
after = step.Shape.Faces[0].Area
print(json.dumps(dict(proxy=proxy_loaded, before=before, after=after,
                      state=step.getStatusString(), mode=step.ProfileMode,
                      sketch=step.ProfileSketch.Label)))
"""
    )
    assert result["proxy"] is True
    assert result["mode"] == "Scale" and result["sketch"] == "Tree"
    assert result["before"] == pytest.approx(TREE_AREA, abs=1e-5)
    assert result["after"] == pytest.approx(TREE_AREA / 2, abs=1e-5), result["state"]


def test_the_silhouette_of_a_meshed_cylinder_is_round(freecad, popup):
    """A FreeCAD cylinder (r = 10, axis z) meshed with 0.01 mm deviation, seen from above on the
    card's ground: its silhouette is the inscribed polygon of the meshed circle."""
    import MeshPart
    import numpy
    import Part

    solid = Part.makeCylinder(10, 15, freecad.Vector(50, 100, 5))
    mesh = MeshPart.meshFromShape(Shape=solid, LinearDeflection=0.01, AngularDeflection=0.05)
    points, facets = mesh.Topology
    model = popup.core.ModelMesh(
        numpy.array([(p.x, p.y, p.z) for p in points]), numpy.array(facets), "cylinder"
    )
    card = popup.core.make_card(popup.core.CardParams())
    silhouette = popup.core.silhouette_profile(model, card, card.ground, facing_only=True)
    assert silhouette.pieces == 1 and len(silhouette.profile.holes) == 0
    assert silhouette.area == pytest.approx(math.pi * 100, abs=2 * math.pi * 10 * 0.01)
    assert silhouette.area < math.pi * 100  # inscribed
    # The profile frame of the ground: u = W/2 - y, v = x; the centre at (W/2 - 100, 50).
    outer = numpy.asarray(silhouette.profile.outer)
    width = popup.core.CardParams().width
    centre = outer.mean(axis=0)
    assert centre == pytest.approx([width / 2 - 100, 50], abs=0.05)
    radii = numpy.linalg.norm(outer - centre, axis=1)
    assert radii.max() == pytest.approx(10, abs=0.02)
    layers = popup.core.depth_layers(model, card, card.ground)
    assert len(layers) == 1 and layers[0].depth == pytest.approx(20, abs=1e-9)  # the top face
    with pytest.raises(ValueError, match="depth_near must be below depth_far"):
        popup.core.silhouette_profile(model, card, card.ground, depth_near=3, depth_far=1)


def test_a_standing_riser_takes_the_silhouette_where_it_stands(popup):
    """A block 20 x 40 x 10 mm built square to the riser as it stands at 90° (pose from the
    simulator): seen from there its silhouette is 20 x 40 mm, of which the 60 x 20 riser keeps
    20 x 20; seen at the design state (the riser flat) it is something else."""
    import numpy

    core = popup.core
    scaffold = core.make_card(core.CardParams())
    params = core.StepFoldParams()
    params.offset, params.width, params.run_ground, params.run_backdrop = 60, 60, 30, 20
    riser = core.add_step_fold(scaffold, core.central_fold(scaffold), params, "Step").patches[0]
    state = core.simulate_fold(scaffold, [math.pi / 2]).states[0]
    index = [p.id for p in scaffold.patches].index(riser)
    rotation, translation = state.rotations[index], state.translations[index]
    frame = core.profile_frame(scaffold, riser)
    o = rotation @ frame.origin + translation
    u, v, n = rotation @ frame.u, rotation @ frame.v, rotation @ frame.normal
    corners = [
        o + (10 if k & 1 else -10) * u + (40 if k & 2 else 0) * v + (5 if k & 4 else -5) * n
        for k in range(8)
    ]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    triangles = [t for q in quads for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]
    block = core.ModelMesh(numpy.array(corners), numpy.array(triangles), "block")
    standing = core.silhouette_profile(block, scaffold, riser, state=state)
    assert standing.area == pytest.approx(20 * 40, abs=1e-4)
    flat = core.silhouette_profile(block, scaffold, riser)
    assert abs(flat.area - 20 * 40) > 1
    applied = core.apply_profile(scaffold, riser, standing.profile)
    assert applied.area_after == pytest.approx(20 * 20, abs=1e-4)
    other = core.make_card(core.CardParams())
    with pytest.raises(ValueError, match="not a state of this scaffold"):
        core.silhouette_profile(block, other, other.ground, state=state)


def test_loose_paper_is_dropped_with_a_warning(popup):
    """A column over the riser (u -10..10) and an arm (u 20..30, v 8..12) joined to it only
    outside the riser: the arm holds no fold, so it is dropped and the result says so."""
    core = popup.core
    scaffold = core.make_card(core.CardParams())
    params = core.StepFoldParams()
    params.offset, params.width, params.run_ground, params.run_backdrop = 60, 60, 30, 20
    core.add_step_fold(scaffold, core.central_fold(scaffold), params, "Step")
    arm = [(-10, -5), (40, -5), (40, 12), (20, 12), (20, 8), (35, 8), (35, -3), (10, -3)]
    arm += [(10, 25), (-10, 25)]
    applied = core.apply_profile(scaffold, "Step", "riser", core.Profile(arm, [], "Arm"))
    assert applied.area_after == pytest.approx(20 * 20, abs=1e-5)
    assert applied.dropped_pieces == 1
    assert [w["code"] for w in applied.warnings] == ["bad_profile"]
    assert "Step.riser: profile 'Arm' cut off 1 piece(s)" in applied.warnings[0]["message"]
