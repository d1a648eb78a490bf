"""design_from_motion: a motion result (the shape popupcore.design_motion returns) becomes a
PopUpCard with motion-mechanism features. The results here are written by hand, so the moving
point of each mechanism at several fold angles can be checked against the mechanism library's
closed forms (docs/MATH.md, "Mechanisms on a base patch pair"): the features are posed by the
simulator, the closed forms are derived independently of it.
"""

import math
import types

import numpy as np
import pytest

ANGLES = (170.0, 120.0, 75.0, 30.0)
TOUCH = 1e-6  # mm: a vertex of the posed feature is the closed form's point


def _mechanism(type_, name, host, **parameters):
    return types.SimpleNamespace(kind=type_, name=name, host=host, parameters=parameters)


def _result(core, mechanisms, chains=(), matrix=None, width=240.0, depth=140.0):
    card = core.CardParams()
    card.width, card.depth = width, depth
    targets = types.SimpleNamespace(
        animation_to_card=np.eye(4) if matrix is None else matrix, first_frame=2, last_frame=11
    )
    return types.SimpleNamespace(
        card=card, mechanisms=mechanisms, profiles=[], chains=list(chains), targets=targets
    )


LAYER = _mechanism(
    "floating_layer",
    "L1",
    "central fold",
    offset=20.0,
    width=80.0,
    height=25.0,
    support=20.0,
    overhang=15.0,
)
ARM = _mechanism("rotation_arm", "A1", "L1.top", offset=10.0, spine=40.0, run=30.0, arm=20.0)
LIFT = _mechanism(
    "vertical_translation",
    "M1",
    "central fold",
    offset=150.0,
    side=30.0,
    height=30.0,
    wall_angle=math.radians(40.0),
    back=0.0,  # the core states the field the feature fixes (no back walls)
)
SLIDE = _mechanism(
    "horizontal_translation",
    "H1",
    "central fold",
    offset=185.0,
    width=40.0,
    run_ground=40.0,
    run_backdrop=20.0,
    reach=60.0,
)
SPINE = _mechanism(
    "v_fold",
    "V1",
    "central fold",
    offset=60.0,
    run=40.0,
    hinge_angle=math.radians(45.0),
    spine=45.0,
    spine_angle=math.radians(90.0),
)
# Unequal runs put the nose off the wings' bisector, so it leaves the card's bisecting plane.
STEP = _mechanism(
    "step_fold", "S1", "V1.wings", offset=10.0, width=20.0, run_ground=10.0, run_backdrop=5.0
)


@pytest.fixture
def core():
    from popupwb.core import popupcore

    return popupcore


def _nearest(obj, point):
    import FreeCAD

    p = FreeCAD.Vector(*[float(v) for v in point])
    return min((v.Point - p).Length for v in obj.Shape.Vertexes)


def _params(core, struct, **values):
    params = getattr(core, struct)()
    for name, value in values.items():
        setattr(params, name, value)
    return params


def _fold(doc, card, degrees):
    card.FoldAngle = degrees
    doc.recompute()


def test_rotation_arm_on_a_floating_layer_and_two_translations_follow_their_closed_forms(doc, core):
    from popupwb import validity
    from popupwb.motion.design_from_motion import build_design

    chains = [
        types.SimpleNamespace(name="LeftHand", mechanisms=["A1"]),
        types.SimpleNamespace(name="Head", mechanisms=["M1"]),
        types.SimpleNamespace(name="Tail", mechanisms=["H1"]),
        types.SimpleNamespace(name="Body", mechanisms=["L1"]),
    ]
    design = build_design(doc, _result(core, [LAYER, ARM, LIFT, SLIDE], chains))
    card = design.card
    layer, arm, lift, slide = design.mechanisms
    assert [m.Proxy.TYPE for m in design.mechanisms] == [
        "PopUp::FloatingLayer",
        "PopUp::RotationArm",
        "PopUp::VerticalTranslation",
        "PopUp::HorizontalTranslation",
    ]
    assert (arm.Host, arm.HostPair) == (layer, "L1.top")
    assert lift.WallAngle.Value == pytest.approx(40.0)  # radians in, degrees in the property
    assert [m.Chain for m in design.mechanisms] == ["Body", "LeftHand", "Head", "Tail"]
    assert (card.FirstFrame, card.LastFrame, card.SourceAnimation) == (2, 11, "")
    report = validity.run_check(card)
    assert report["valid"], report["diagnostics"]

    arm_params = _params(core, "RotationArmParams", offset=10.0, spine=40.0, run=30.0, arm=20.0)
    lift_params = _params(
        core,
        "VBoxFoldParams",
        offset=150.0,
        side=30.0,
        height=30.0,
        wall_angle=math.radians(40.0),
    )
    slide_params = _params(
        core,
        "HorizontalTranslationParams",
        offset=185.0,
        width=40.0,
        run_ground=40.0,
        run_backdrop=20.0,
        reach=60.0,
    )
    for degrees in ANGLES:
        _fold(doc, card, degrees)
        theta = math.radians(degrees)
        # The platform's hinge stays on the bisector at the layer's height (docs/MATH.md,
        # Floating layer: a platform point at r from the crease is at c·z + r·g(θ)), and the
        # platform opens as the card does, so the arm's frame is the central fold's moved by
        # (0, layer offset, layer height).
        tip = np.asarray(core.rotation_arm_tip(arm_params, theta)) + (0.0, 20.0, 25.0)
        assert _nearest(arm, tip) < TOUCH, degrees
        # P_x = -h sin δ (eq 4.10): the arm swings across the fold.
        assert tip[0] == pytest.approx(-20.0 * math.sin(theta / 2), abs=1e-9)
        corner = np.asarray(core.v_box_front_corner(lift_params, theta))
        assert _nearest(lift, corner) < TOUCH, degrees
        assert corner[0] == pytest.approx(0.0, abs=1e-12)  # only along the fold
        x, z = core.horizontal_translation_tip(slide_params, theta)
        assert _nearest(slide, (x, 185.0 + 5.0, z)) < TOUCH, degrees  # M's 5 mm bridge
    # The vertical translation's corner at 75°: eq 4.5 corrected, by hand.
    h, alpha, delta = 30.0, math.radians(40.0), math.radians(75.0 / 2)
    p_y = -h * math.sin(alpha) * math.cos(delta)
    p_y /= math.sqrt(math.cos(alpha) ** 2 + math.sin(alpha) ** 2 * math.cos(delta) ** 2)
    corner = np.asarray(core.v_box_front_corner(lift_params, math.radians(75.0)))
    assert corner[1] == pytest.approx(150.0 + p_y, abs=1e-9)


def test_a_step_fold_on_v_fold_wings_moves_diagonally_as_the_closed_form_says(doc, core):
    from popupwb import validity
    from popupwb.motion.design_from_motion import build_design

    design = build_design(doc, _result(core, [SPINE, STEP]))
    card = design.card
    spine, step = design.mechanisms
    assert (step.Host, step.HostPair) == (spine, "V1.wings")
    report = validity.run_check(card)
    assert report["valid"], report["diagnostics"]
    v_params = _params(
        core,
        "VFoldParams",
        offset=60.0,
        run=40.0,
        hinge_angle=math.radians(45.0),
        spine=45.0,
        spine_angle=math.radians(90.0),
    )
    step_params = _params(core, "StepFoldParams", run_ground=10.0, run_backdrop=5.0)
    step_params.offset, step_params.width = 10.0, 20.0
    noses = []
    for degrees in ANGLES:
        _fold(doc, card, degrees)
        pair = core.v_fold_wings(v_params, math.pi, math.radians(degrees))
        origin, axis, up = (np.asarray(v, dtype=float) for v in (pair.origin, pair.axis, pair.up))
        across = np.cross(axis, up)  # x = y × z of the pair's local frame
        x, z = core.step_nose(step_params, pair.opening)
        nose = origin + 10.0 * axis + x * across + z * up  # the nose at the step's offset
        assert _nearest(step, nose) < TOUCH, degrees
        noses.append(nose)
    # Diagonal: the nose moves along x and along y at once as the card closes (§4.3.3).
    moves = np.diff(np.array(noses), axis=0)
    assert np.all(np.abs(moves[:, 0]) > 0.1) and np.all(np.abs(moves[:, 1]) > 0.1)


def test_the_card_links_its_animation_and_survives_save_and_reopen(core, tmp_path, freecad):
    from popupwb.motion.design_from_motion import build_design

    matrix = np.diag([2.0, 2.0, 2.0, 1.0])
    matrix[:3, 3] = (5.0, 7.0, 0.0)
    doc = freecad.newDocument("Motion")
    source = tmp_path / "walk.bvh"
    source.write_text("HIERARCHY\n")  # only its path is kept
    build_design(doc, _result(core, [SLIDE], matrix=matrix), source_file=str(source))
    path = str(tmp_path / "motion.FCStd")
    doc.saveAs(path)
    freecad.closeDocument(doc.Name)
    reopened = freecad.openDocument(path)
    try:
        card = reopened.getObject("Card")
        assert card.SourceAnimation == str(source)
        assert (card.AnimationToCard.A11, card.AnimationToCard.A14, card.AnimationToCard.A24) == (
            2.0,
            5.0,
            7.0,
        )
        slide = reopened.getObject("H1")
        slide.Reach = 70.0
        card.FoldAngle = 90.0
        reopened.recompute()
        params = _params(
            core,
            "HorizontalTranslationParams",
            offset=185.0,
            width=40.0,
            run_ground=40.0,
            run_backdrop=20.0,
            reach=70.0,
        )
        x, z = core.horizontal_translation_tip(params, math.radians(90.0))
        assert _nearest(slide, (x, 190.0, z)) < TOUCH
    finally:
        freecad.closeDocument(reopened.Name)


def test_bad_mechanisms_are_named(doc, core):
    from popupwb.motion.design_from_motion import build_design

    bad = _mechanism("rotation_arm", "A1", "central fold", offset=10.0, elbow=3.0)
    with pytest.raises(ValueError, match=r"A1: parameter\(s\) \['elbow'\]"):
        build_design(doc, _result(core, [bad]))
    with pytest.raises(ValueError, match="A1: host 'L1.top'"):
        build_design(doc, _result(core, [ARM]))
    nan = _mechanism("rotation_arm", "A2", "central fold", offset=float("nan"))
    with pytest.raises(ValueError, match="A2: parameter offset = nan, must be finite"):
        build_design(doc, _result(core, [nan]))
    backed = _mechanism("vertical_translation", "M2", "central fold", offset=150.0, back=1.0)
    with pytest.raises(ValueError, match="M2: parameter back = 1.0, a VerticalTranslation always"):
        build_design(doc, _result(core, [backed]))
    twice = [SLIDE, SLIDE]
    with pytest.raises(ValueError, match="H1: two mechanisms have this name"):
        build_design(doc, _result(core, twice))
    with pytest.raises(ValueError, match="animation_to_card: must be a finite 4x4"):
        build_design(doc, _result(core, [SLIDE], matrix=np.full((4, 4), np.nan)))
