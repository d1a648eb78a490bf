"""A rotation hosted off the central fold (thesis §4.3.4, last paragraph): a RotationArm feature
on a FloatingLayer's side pair. The document recomputes with valid shapes, the card is valid, the
arm's tip (a vertex of its posed wing) is the closed form of docs/MATH.md ("A rotation arm on a
floating layer's side") at several fold angles, and the cutting sheets verify."""

import math

import numpy as np
import pytest

from cli_runner import popup as run_popup
from freecad_documents import recompute_ok

CARD = dict(width=240.0, depth=140.0)
LAYER = dict(offset=60.0, width=70.0, height=35.0, support=30.0, overhang=0.0)
ARM = dict(offset=15.0, spine=40.0, run=25.0, arm=30.0)
ANGLES = (180.0, 150.0, 100.0, 60.0, 20.0)
TOUCH = 1e-6  # mm


def _params(core, struct, values):
    params = getattr(core, struct)()
    for name, value in values.items():
        setattr(params, name, value)
    return params


def _nearest(obj, point):
    import FreeCAD

    p = FreeCAD.Vector(*[float(v) for v in point])
    return min((v.Point - p).Length for v in obj.Shape.Vertexes)


@pytest.fixture
def design(doc, popup):
    make = popup.make
    card = make.make_card(doc, **CARD)
    layer = make.make_floating_layer(card, name="Layer", **LAYER)
    ground = make.make_rotation_arm(layer, host_pair="Layer.side_ground", name="ArmG", **ARM)
    backdrop = make.make_rotation_arm(layer, host_pair="Layer.side_backdrop", name="ArmB", **ARM)
    recompute_ok(doc, card, layer, ground, backdrop)
    return card, layer, ground, backdrop


def test_arms_on_both_sides_of_a_layer_follow_the_closed_form(doc, popup, design):
    from popupwb import validity

    core = popup.core
    card, layer, ground, backdrop = design
    assert (ground.HostPair, backdrop.HostPair) == ("Layer.side_ground", "Layer.side_backdrop")
    report = validity.run_check(card)
    assert report["valid"], report["diagnostics"]
    arm = _params(core, "RotationArmParams", ARM)
    lay = _params(core, "FloatingLayerParams", LAYER)
    for degrees in ANGLES:
        card.FoldAngle = degrees
        doc.recompute()
        theta = math.radians(degrees)
        for obj, side in ((ground, core.LayerSide.ground), (backdrop, core.LayerSide.backdrop)):
            assert obj.Shape.isValid() and obj.Shape.Faces, obj.Name
            tip = np.asarray(core.rotation_arm_tip_on_layer_side(arm, lay, side, theta))
            assert _nearest(obj, tip) < TOUCH, (obj.Name, degrees)
        assert layer.Shape.isValid() and card.Shape.isValid()
    # By hand at 180° on the ground side: the side pair is open 90°, so in its frame the tip is
    # P = R + (h/w)(R − S) with δ = 45° (docs/MATH.md, Rotation); the frame's hinge is at x = 30,
    # its bisector (1, 0, 1)/√2 and its x axis (1, 0, −1)/√2.
    l, w, h, d = ARM["spine"], ARM["run"], ARM["arm"], math.pi / 4
    t = 2 * math.atan2(w * math.cos(d), l)
    R = np.array([0.0, l * math.cos(t), l * math.sin(t)])
    S = np.array([w * math.sin(d), l, w * math.cos(d)])
    P = R + h / w * (R - S)
    by_hand = np.array([30.0, 60.0 + 15.0, 0.0])
    by_hand += P[0] * np.array([1.0, 0, -1.0]) / math.sqrt(2) + P[2] * np.array([1.0, 0, 1.0]) / (
        math.sqrt(2)
    )
    by_hand[1] += P[1]
    tip = core.rotation_arm_tip_on_layer_side(arm, lay, core.LayerSide.ground, math.pi)
    assert np.allclose(tip, by_hand, atol=1e-9)


def test_a_run_longer_than_the_support_is_named(doc, popup):
    make = popup.make
    card = make.make_card(doc, **CARD)
    layer = make.make_floating_layer(card, name="Layer", **LAYER)
    bad = make.make_rotation_arm(
        layer, host_pair="Layer.side_ground", name="Arm", **dict(ARM, run=36.0)
    )
    doc.recompute()
    assert "Invalid" in bad.State or "Error" in bad.State
    assert not ("Invalid" in layer.State or "Error" in layer.State)
    status = bad.getStatusString()
    assert "Run = 36 mm" in status and "< 35 mm" in status, status


def test_sheets_of_the_off_fold_design_verify(doc, design, tmp_path):
    path = str(tmp_path / "offfold.FCStd")
    doc.saveAs(path)
    out = tmp_path / "sheets"
    proc = run_popup("sheet", path, "--out", str(out))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    proc = run_popup("verify", path, str(out))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert proc.stdout.startswith("sheets match the design")


def test_an_arm_added_with_its_fitted_defaults_on_a_side_pair_is_valid(doc, popup):
    """What the RotationArm command does: no parameters given, the feature fits its defaults to
    the pair (a side pair is open 90° and only as deep as the layer is high)."""
    from popupwb import validity

    make = popup.make
    card = make.make_card(doc, **CARD)
    layer = make.make_floating_layer(card, name="Layer", **LAYER)
    arm = make.make_rotation_arm(layer, host_pair="Layer.side_backdrop", name="Arm")
    recompute_ok(doc, card, layer, arm)
    assert arm.Shape.isValid() and len(arm.Shape.Faces) == 2
    report = validity.run_check(card)
    assert report["valid"], report["diagnostics"]
