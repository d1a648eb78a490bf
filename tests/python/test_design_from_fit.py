"""design_from_fit: a fit result (the shape popupcore.fit_design returns) becomes a PopUpCard with
mechanism features, parameters converted from the core's fields (mm, radians, 0/1) to properties
(mm, degrees, bools), hosts by name, and the source model linked on the card.

The result here is written by hand with known dimensions, so the geometry can be checked against
what a box fold and a tent fold of those sizes must be (thesis Fig 4.2, 4.4), independently of the
fitter."""

import math
import types

import numpy as np
import pytest


def _mechanism(**fields):
    return types.SimpleNamespace(primitive="test", coverage_error=0.0, **fields)


def _result(popupcore, mechanisms, scale=2.0):
    card = popupcore.CardParams()
    card.width, card.depth = 186.0, 136.5
    matrix = np.diag([scale, scale, scale, 1.0])
    matrix[:3, 3] = (5.0, 7.0, 0.0)
    return types.SimpleNamespace(card=card, model_to_card=matrix, mechanisms=mechanisms)


BOX = _mechanism(
    kind="box_fold",
    name="B1",
    host="central fold",
    parameters=dict(
        offset=30.0,
        width=50.0,
        depth_ground=30.0,
        depth_backdrop=30.0,
        height=30.0,
        front=1.0,
        back=1.0,
        panel_pairs=1.0,
    ),
)
TENT = _mechanism(
    kind="tent_fold",
    name="T1",
    host="B1.top",
    parameters=dict(offset=10.0, width=30.0, foot=10.0, foot_backdrop=10.0, slope=15.0),
)
VFOLD = _mechanism(
    kind="v_fold",
    name="V1",
    host="central fold",
    parameters=dict(
        offset=150.0, run=20.0, hinge_angle=math.pi / 4, spine=25.0, spine_angle=math.pi / 3
    ),
)


@pytest.fixture
def core():
    from popupwb.core import popupcore

    return popupcore


@pytest.fixture
def tetrahedron(core):
    vertices = np.array([[0, 0, 0], [10, 0, 0], [0, 10, 0], [0, 0, 10]], dtype=float)
    triangles = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    return core.ModelMesh(vertices, triangles, source="tetrahedron.stl")


def test_fitted_mechanisms_become_features_with_their_dimensions(doc, core, tetrahedron):
    from popupwb import validity
    from popupwb.fitting.design_from_fit import build_design

    design = build_design(doc, _result(core, [BOX, TENT, VFOLD]), tetrahedron)
    card = design.card
    assert (card.Width.Value, card.Depth.Value) == (186.0, 136.5)
    box, tent, vfold = design.mechanisms
    assert [m.Label for m in design.mechanisms] == ["B1", "T1", "V1"]
    assert [m.Proxy.TYPE for m in design.mechanisms] == [
        "PopUp::BoxFold",
        "PopUp::TentFold",
        "PopUp::VFold",
    ]
    assert (box.Host, box.HostPair) == (card, "central fold")
    assert (tent.Host, tent.HostPair) == (box, "B1.top")
    assert vfold.HingeAngle.Value == pytest.approx(45.0)  # radians in, degrees in the property
    assert vfold.SpineAngle.Value == pytest.approx(60.0)
    assert box.Front is True and box.PanelPairs == 1

    # The box at the design state spans its depths across the fold, its width from the offset
    # along it, and its top stands Height over the card; the tent's apex is sqrt(15² - 10²) above
    # the box's top, its feet 10 mm either side of the top's hinge.
    bb = box.Shape.BoundBox
    assert (bb.XMin, bb.XMax, bb.YMin, bb.YMax, bb.ZMin, bb.ZMax) == pytest.approx(
        (-30, 30, 30, 80, 0, 30), abs=1e-6
    )
    tb = tent.Shape.BoundBox
    assert (tb.XMin, tb.XMax, tb.ZMin) == pytest.approx((-10, 10, 30), abs=1e-6)
    assert tb.ZMax == pytest.approx(30 + math.sqrt(15**2 - 10**2), abs=1e-6)

    report = validity.run_check(card)
    assert report["valid"], report["diagnostics"]
    assert card.Validity == "Valid"


def test_a_fit_result_with_a_v_fold_builds_its_wings_where_the_parameters_put_them(
    doc, core, tetrahedron
):
    """The mapping gives a v-fold where a prism's samples lie on its wings (docs/DESIGN.md,
    "Mapping by distance"); the repair and hand-edited results carry them too. At 180° the card is the plane z = 0, the fold the y axis: O = (0, 150, 0)
    on the fold, A and B `run` = 20 mm away at 45° to it on either page, the tip P in the bisecting
    plane x = 0, `spine` = 25 mm from O at 60° above the fold."""
    from popupwb import validity
    from popupwb.fitting.design_from_fit import build_design

    design = build_design(doc, _result(core, [VFOLD]), tetrahedron)
    (vfold,) = design.mechanisms
    assert (vfold.Label, vfold.Proxy.TYPE, vfold.HostPair) == ("V1", "PopUp::VFold", "central fold")
    a = 20.0 * math.sin(math.pi / 4)  # A and B across the fold, and along it
    tip_along, tip_up = 25.0 * math.cos(math.pi / 3), 25.0 * math.sin(math.pi / 3)
    bb = vfold.Shape.BoundBox
    assert (bb.XMin, bb.XMax, bb.YMin, bb.YMax, bb.ZMin, bb.ZMax) == pytest.approx(
        (-a, a, 150.0, 150.0 + max(a, tip_along), 0.0, tip_up), abs=1e-6
    )
    corners = sorted({tuple(round(c, 6) for c in v.Point) for v in vfold.Shape.Vertexes})
    expected = sorted(
        {
            (0.0, 150.0, 0.0),
            (round(a, 6), round(150.0 + a, 6), 0.0),
            (round(-a, 6), round(150.0 + a, 6), 0.0),
            (0.0, round(150.0 + tip_along, 6), round(tip_up, 6)),
        }
    )
    assert corners == expected
    report = validity.run_check(design.card)
    assert report["valid"], report["diagnostics"]


def test_the_source_model_stands_on_the_card_through_model_to_card(doc, core, tetrahedron):
    from popupwb.fitting.design_from_fit import build_design

    design = build_design(doc, _result(core, [BOX]), tetrahedron)
    mesh = design.source_model
    assert mesh.TypeId == "Mesh::Feature"
    assert design.card.SourceModel == mesh
    # x2 and moved by (5, 7, 0): the tetrahedron's 10 mm corner box becomes 20 mm at (5, 7, 0).
    bb = mesh.Mesh.BoundBox
    assert (bb.XMin, bb.YMin, bb.ZMin, bb.XMax, bb.YMax, bb.ZMax) == pytest.approx(
        (5, 7, 0, 25, 27, 20)
    )
    assert mesh.Mesh.CountFacets == 4 and mesh.Mesh.Volume == pytest.approx(8 * 1000 / 6)
    matrix = design.card.ModelToCard
    assert (matrix.A11, matrix.A14, matrix.A24) == (2.0, 5.0, 7.0)


def test_design_survives_save_and_reopen(core, tetrahedron, tmp_path, freecad):
    from popupwb.fitting.design_from_fit import build_design

    doc = freecad.newDocument("Fitted")
    build_design(doc, _result(core, [BOX, TENT]), tetrahedron)
    path = str(tmp_path / "fitted.FCStd")
    doc.saveAs(path)
    freecad.closeDocument(doc.Name)
    reopened = freecad.openDocument(path)
    try:
        mechanisms = [o for o in reopened.Objects if hasattr(o, "HostPair")]
        assert [(o.Label, o.Proxy.TYPE) for o in mechanisms] == [
            ("B1", "PopUp::BoxFold"),
            ("T1", "PopUp::TentFold"),
        ]
        card = reopened.getObject("Card")
        assert card.SourceModel.TypeId == "Mesh::Feature"
        mechanisms[0].Height = 35.0
        reopened.recompute()
        assert mechanisms[1].Shape.BoundBox.ZMin == pytest.approx(35.0, abs=1e-6)
    finally:
        freecad.closeDocument(reopened.Name)


def test_an_unknown_parameter_field_is_named(doc, core):
    from popupwb.fitting.design_from_fit import build_design

    bad = _mechanism(
        kind="tent_fold", name="T1", host="central fold", parameters=dict(foot=10, apex=3)
    )
    with pytest.raises(ValueError, match=r"T1: parameter\(s\) \['apex'\]"):
        build_design(doc, _result(core, [bad]))


def test_a_host_made_later_or_never_is_named(doc, core):
    from popupwb.fitting.design_from_fit import build_design

    with pytest.raises(ValueError, match="T1: host 'B1.top'"):
        build_design(doc, _result(core, [TENT]))


def _box_model(core):
    """The box fold BOX builds, as a closed mesh in the card's frame: x -30..30, y 30..80, z 0..30."""
    corners = np.array(
        [[x, y, z] for x in (-30.0, 30.0) for y in (30.0, 80.0) for z in (0.0, 30.0)], dtype=float
    )
    # Faces of the cube with corner index 4x + 2y + z, counter-clockwise from outside.
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    triangles = [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]
    return core.ModelMesh(corners, np.array(triangles), source="box.stl")


def test_the_card_gives_back_its_model_in_the_card_frame(doc, core, tetrahedron):
    from popupwb.fitting.design_from_fit import build_design
    from popupwb.model.model_source import card_model

    design = build_design(doc, _result(core, [BOX]), tetrahedron)
    design.card.Placement.Base = (100.0, 0.0, 0.0)  # the card moved: the model moves with it
    design.source_model.Placement = design.card.Placement
    doc.recompute()
    model = card_model(design.card)
    # The tetrahedron's corners x2 and moved by (5, 7, 0), in the card's own frame.
    expected = np.array([[0, 0, 0], [10, 0, 0], [0, 10, 0], [0, 0, 10]]) * 2.0 + [5, 7, 0]
    assert np.asarray(model.vertices) == pytest.approx(expected)
    assert card_model(design.card) is not None
    assert design.card.SourceFile == ""


def test_popup_sheet_prints_the_source_model_as_artwork(tmp_path, freecad, core):
    from cli_runner import popup

    from popupwb.fitting.design_from_fit import build_design

    paths = {}
    for name, model in (("with_model", _box_model(core)), ("by_hand", None)):
        doc = freecad.newDocument(name)
        result = _result(core, [BOX], scale=1.0)
        result.model_to_card = np.eye(4)
        build_design(doc, result, model)
        paths[name] = str(tmp_path / f"{name}.FCStd")
        doc.saveAs(paths[name])
        freecad.closeDocument(doc.Name)
    svgs = {}
    for name, path in paths.items():
        proc = popup("sheet", path, "--out", str(tmp_path / name), "--paper", "A3")
        assert proc.returncode == 0, proc.stdout + proc.stderr
        with open(tmp_path / name / "sheets.svg") as f:
            svgs[name] = f.read()
    assert "<image" in svgs["with_model"] and "<image" not in svgs["by_hand"]
