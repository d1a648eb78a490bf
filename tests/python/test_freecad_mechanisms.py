"""PopUpCard and mechanism features in headless FreeCAD: a nested card built with make_*, its
geometry against the core's, fold angles, parameter edits, errors that stay on one feature, the
validity check, and save and reopen in a fresh process."""

import json
import math

import numpy as np
import pytest

from freecad_documents import assert_same_points, in_error, recompute_ok

# The test card (valid, checked by test_the_nested_card_is_valid): a box fold on the central fold
# carrying a tent and a floating layer on its top and a step fold on its ground-side wall, a v-fold
# and a v-box beside the box.
CARD = dict(width=240.0, depth=140.0)
BOX = dict(offset=60.0, width=100.0, depth_ground=30.0, depth_backdrop=30.0, height=30.0)
TENT = dict(offset=10.0, width=40.0, foot=10.0, foot_backdrop=10.0, slope=14.0)
STEP = dict(offset=10.0, width=60.0, run_ground=15.0, run_backdrop=15.0)
V_FOLD = dict(offset=25.0, run=40.0, hinge_angle=45.0, spine=45.0, spine_angle=60.0)
V_BOX = dict(offset=185.0, side=10.0, height=8.0, wall_angle=45.0)
LAYER = dict(offset=58.0, width=35.0, height=10.0, support=8.0, overhang=5.0)
FACES = {"Box": 9, "Tent": 2, "Layer": 9, "Step": 2, "VFold": 2, "VBox": 6}
ALL_FACES = 2 + sum(FACES.values())


def build_card(doc, popup):
    """The test card as document objects (not recomputed): dict of name -> object."""
    make = popup.make
    card = make.make_card(doc, **CARD)
    box = make.make_box_fold(card, name="Box", **BOX)
    tent = make.make_tent_fold(box, host_pair="Box.top", name="Tent", **TENT)
    layer = make.make_floating_layer(box, host_pair="Box.top", name="Layer", **LAYER)
    step = make.make_step_fold(box, host_pair="Box.side_ground", name="Step", **STEP)
    v_fold = make.make_v_fold(card, name="VFold", **V_FOLD)
    v_box = make.make_v_box_fold(card, name="VBox", **V_BOX)
    objects = {"Card": card, "Box": box, "Tent": tent, "Layer": layer, "Step": step}
    objects.update(VFold=v_fold, VBox=v_box)
    return objects


def core_card(popup, height=BOX["height"]):
    """The same card built straight with popupcore: (scaffold, {name: patch ids})."""
    core = popup.core

    def params(cls, values):
        p = cls()
        for key, value in values.items():
            setattr(p, key, math.radians(value) if key.endswith("angle") else value)
        return p

    scaffold = core.make_card(params(core.CardParams, CARD))
    fold = core.central_fold(scaffold)
    box = core.add_box_fold(
        scaffold, fold, params(core.BoxFoldParams, dict(BOX, height=height)), "Box"
    )
    top, side_ground = box.offered[0], box.offered[1]
    # The workbench's order: depth first from the card, siblings in document order.
    tent = core.add_tent_fold(scaffold, top, params(core.TentFoldParams, TENT), "Tent")
    layer = core.add_floating_layer(scaffold, top, params(core.FloatingLayerParams, LAYER), "Layer")
    step = core.add_step_fold(scaffold, side_ground, params(core.StepFoldParams, STEP), "Step")
    v_fold = core.add_v_fold(scaffold, fold, params(core.VFoldParams, V_FOLD), "VFold")
    v_box = core.add_v_box_fold(scaffold, fold, params(core.VBoxFoldParams, V_BOX), "VBox")
    patches = {"Box": box.patches, "Tent": tent.patches, "Layer": layer.patches}
    patches.update(Step=step.patches, VFold=v_fold.patches, VBox=v_box.patches)
    return scaffold, patches


@pytest.fixture
def card(doc, popup):
    objects = build_card(doc, popup)
    recompute_ok(doc, *objects.values())
    return objects


def vertices(shape):
    return [(v.X, v.Y, v.Z) for v in shape.Vertexes]


def test_card_presets_fold_the_sheet_across_its_long_side(doc, popup):
    expected = {
        "A4": (210.0, 148.5),
        "A5": (148.0, 105.0),
        "A6": (105.0, 74.0),
        "Letter": (215.9, 139.7),
        "HalfLetter": (139.7, 107.95),
    }
    for preset, (width, depth) in expected.items():
        card = popup.make.make_card(doc, preset=preset)
        recompute_ok(doc, card)
        assert (card.Width.Value, card.Depth.Value) == (width, depth)
        assert card.Preset == preset
        assert len(card.Shape.Faces) == 2
        assert card.Shape.Area == pytest.approx(2.0 * width * depth, rel=1e-12)
        box = card.Shape.BoundBox  # open flat: pages at x in [-depth, depth], fold along y
        assert (box.XLength, box.YLength, box.ZLength) == pytest.approx((2 * depth, width, 0))
    card.Width = 200.0  # a size of one's own is no longer the preset
    assert card.Preset == "Custom" and card.Depth.Value == pytest.approx(107.95)
    card.Preset = "A4"
    assert (card.Width.Value, card.Depth.Value) == (210.0, 148.5)
    custom = popup.make.make_card(doc, width=240, depth=140)
    assert custom.Preset == "Custom" and (custom.Width.Value, custom.Depth.Value) == (240, 140)


def test_nested_card_matches_the_core_patch_for_patch(doc, popup, card):
    scaffold, patches = core_card(popup)
    size = scaffold.size()
    for angle in (180.0, 120.0, 45.0):
        card["Card"].FoldAngle = angle
        recompute_ok(doc, *card.values())
        state = popup.core.simulate_fold(scaffold, [math.radians(angle)]).states[0]
        outlines = popup.core.posed_outlines(scaffold, state)
        whole = popup.card_scaffold.assembled_shape(card["Card"])
        assert whole.isValid()
        assert len(whole.Faces) == len(scaffold.patches) == ALL_FACES
        # The card shows its pages only: every patch is drawn once, by the object owning it.
        pages = card["Card"].Shape
        assert len(pages.Faces) == 2
        for face, patch_id in zip(pages.Faces, (scaffold.ground, scaffold.backdrop)):
            assert_same_points(vertices(face.OuterWire), outlines[patch_id], 1e-9 * size)
        for name, count in FACES.items():
            shape = card[name].Shape
            assert shape.isValid()
            assert len(shape.Faces) == count, name
            assert len(patches[name]) == count
            for face, patch_id in zip(shape.Faces, patches[name]):
                assert_same_points(vertices(face.OuterWire), outlines[patch_id], 1e-9 * size)
        for face, outline in zip(whole.Faces, outlines):
            assert_same_points(vertices(face.OuterWire), outline, 1e-9 * size)
    assert card["Tent"].SlopeBackdrop.Value == pytest.approx(14.0)  # 10 + 14 - 10


def test_closed_card_lies_in_the_page_plane(doc, popup, card):
    size = popup.card_scaffold.assembled_shape(card["Card"]).BoundBox.DiagonalLength
    card["Card"].FoldAngle = 0.0
    recompute_ok(doc, *card.values())
    for obj in card.values():
        assert obj.Shape.isValid()
        assert obj.Shape.BoundBox.XLength < 1e-6 * size, obj.Name  # everything in x = 0
    # Closed, the pages stand in the plane x = 0 and the card's depth is along z.
    assert card["Card"].Shape.BoundBox.ZLength == pytest.approx(CARD["depth"], rel=1e-9)


def test_fold_angle_poses_the_whole_card_with_one_simulation(doc, popup, card, monkeypatch):
    built = popup.card_scaffold.for_card(card["Card"])
    calls = []
    simulate = popup.core.simulate_fold
    resume = popup.core.continue_fold

    def counting(scaffold, angles):
        calls.append(list(angles))
        return simulate(scaffold, angles)

    def counting_resume(scaffold, from_state, angles):
        calls.append(list(angles))
        return resume(scaffold, from_state, angles)

    # A new angle continues from the nearest state already solved (here 180°).
    monkeypatch.setattr(popup.core, "simulate_fold", counting)
    monkeypatch.setattr(popup.core, "continue_fold", counting_resume)
    before = {name: np.array(vertices(obj.Shape)) for name, obj in card.items()}
    card["Card"].FoldAngle = 77.0
    touched = [o.Name for o in doc.Objects if "Touched" in o.State]
    assert touched == ["Card"]
    recompute_ok(doc, *card.values())
    assert calls == [[math.radians(77.0)]]  # one simulation, shared by the five features
    assert popup.card_scaffold.for_card(card["Card"]) is built  # the design was not rebuilt
    for name, obj in card.items():
        assert np.abs(np.array(vertices(obj.Shape)) - before[name]).max() > 1.0, name
    card["Card"].FoldAngle = 180.0
    recompute_ok(doc, *card.values())
    assert len(calls) == 1  # 180° was simulated before: cached


def test_box_height_lifts_the_nested_tent_by_as_much(doc, popup, card):
    tent, step = card["Tent"], card["Step"]
    tent_box, step_box = tent.Shape.BoundBox, step.Shape.BoundBox
    tent_points = np.array(vertices(tent.Shape))
    card["Box"].Height = 37.5
    recompute_ok(doc, *card.values())
    moved = tent.Shape.BoundBox
    assert moved.ZMin - tent_box.ZMin == pytest.approx(7.5, abs=1e-9)
    assert moved.ZMax - tent_box.ZMax == pytest.approx(7.5, abs=1e-9)
    assert np.abs(np.array(vertices(tent.Shape)) - tent_points - [0, 0, 7.5]).max() < 1e-9
    # The step stands on the box's side, which grew taller but stayed where it was.
    assert step.Shape.BoundBox.ZMax == pytest.approx(step_box.ZMax, abs=1e-9)
    assert card["Box"].Shape.BoundBox.ZMax == pytest.approx(37.5, abs=1e-9)
    scaffold, patches = core_card(popup, height=37.5)
    outlines = popup.core.posed_outlines(
        scaffold, popup.core.simulate_fold(scaffold, [math.pi]).states[0]
    )
    for face, patch_id in zip(tent.Shape.Faces, patches["Tent"]):
        assert_same_points(vertices(face.OuterWire), outlines[patch_id], 1e-9)


def test_the_nested_card_is_valid(doc, popup, card):
    report = popup.validity.run_check(card["Card"])
    assert report["valid"] is True, report["diagnostics"]
    assert report["foldable"] and report["stable"]
    assert report["intersection_free"] and report["enclosed"]
    assert card["Card"].Valid is True and list(card["Card"].Diagnostics) == []
    assert "Touched" not in card["Card"].State  # the verdict does not trigger a recompute
    card["Card"].FoldAngle = 90.0  # posing the same design keeps the verdict
    recompute_ok(doc, *card.values())
    assert card["Card"].Valid is True
    card["Step"].RunGround = 16.0  # another design: the verdict is gone
    recompute_ok(doc, *card.values())
    assert card["Card"].Valid is False


def test_a_crossing_is_reported_with_the_patches_it_names(doc, popup, card):
    card["VFold"].Offset = 180.0  # beside the box's back: its back panels run into the v
    recompute_ok(doc, *card.values())
    report = popup.validity.run_check(card["Card"])
    assert report["valid"] is False and report["intersection_free"] is False
    built = popup.card_scaffold.for_card(card["Card"])
    offending = popup.validity.offending_patches(report)
    owners = {built.patch_owner(i) for i in offending}
    assert owners == {"Box", "VFold"}
    assert any("VFold.wing_ground" in line for line in card["Card"].Diagnostics)


def test_a_bad_parameter_puts_only_its_feature_in_error(doc, popup, card):
    shapes = {name: vertices(obj.Shape) for name, obj in card.items() if name != "Tent"}
    card["Tent"].Foot = -3.0
    doc.recompute()
    assert in_error(card["Tent"])
    message = card["Tent"].getStatusString()
    assert message.startswith("Tent: Foot = -3 mm, must be > 0")
    for name, obj in card.items():
        if name == "Tent":
            continue
        assert not in_error(obj), (name, obj.getStatusString())
        assert obj.Shape.isValid()
    assert card["Tent"].Shape.isNull()  # no stale tent on screen
    assert len(card["Card"].Shape.Faces) == 2
    whole = popup.card_scaffold.assembled_shape(card["Card"])
    assert len(whole.Faces) == ALL_FACES - 2  # the card without the tent
    for name in ("Box", "Layer", "Step", "VFold", "VBox"):
        assert vertices(card[name].Shape) == pytest.approx(shapes[name], abs=1e-9)
    report = popup.validity.run_check(card["Card"])
    assert report["valid"] is False
    assert any(line.startswith("design_error: Tent: Foot") for line in card["Card"].Diagnostics)

    card["Tent"].Foot = 10.0  # fixing it clears the error
    recompute_ok(doc, *card.values())
    assert len(card["Tent"].Shape.Faces) == 2
    assert len(popup.card_scaffold.assembled_shape(card["Card"]).Faces) == ALL_FACES


def test_a_failing_host_takes_down_only_what_stands_on_it(doc, popup, card):
    card["Box"].Height = -1.0
    doc.recompute()
    assert in_error(card["Box"])
    assert card["Box"].getStatusString().startswith("Box: Height = -1 mm, must be > 0")
    assert not in_error(card["VFold"]) and not in_error(card["Card"])
    assert card["Box"].Shape.isNull()  # no stale box on screen
    whole = popup.card_scaffold.assembled_shape(card["Card"])
    assert len(whole.Faces) == 2 + 2 + 6  # the pages, the v-fold and the v-box
    built = popup.card_scaffold.for_card(card["Card"])
    for name in ("Tent", "Layer", "Step"):
        assert built.errors[name] == f"{name}: Host = Box, which is in error; fix it first"
    card["Box"].Height = 30.0
    recompute_ok(doc, *card.values())
    assert len(popup.card_scaffold.assembled_shape(card["Card"]).Faces) == ALL_FACES


def test_card_errors_name_the_card_and_the_property(doc, popup, card):
    card["Card"].Label = "Greeting"
    card["Card"].Depth = 0.0
    doc.recompute()
    assert in_error(card["Card"])
    assert card["Card"].getStatusString().startswith("Greeting: Depth = 0 mm, must be > 0")
    card["Card"].Depth = 140.0
    card["Card"].FoldAngle = -5.0
    doc.recompute()
    assert "Greeting: FoldAngle = -5°, must be within 0° and 180°" in (
        card["Card"].getStatusString()
    )
    card["Card"].FoldAngle = 30.0
    recompute_ok(doc, *card.values())
    # Negative and infinite lengths are kept as typed and refused with their range, not stored
    # as 0 (FreeCAD's unsigned PropertyLength did that).
    for name, value, fragment in (
        ("Width", -1.0, "Greeting: Width = -1 mm, must be > 0 and <= 2000 mm"),
        ("PaperThickness", -1.0, "Greeting: PaperThickness = -1 mm"),
        ("PaperThickness", float("-inf"), "Greeting: PaperThickness = -inf mm"),
    ):
        kept = getattr(card["Card"], name).Value
        setattr(card["Card"], name, value)
        doc.recompute()
        assert getattr(card["Card"], name).Value == value
        assert in_error(card["Card"])
        assert card["Card"].getStatusString().startswith(fragment), card["Card"].getStatusString()
        setattr(card["Card"], name, kept)
    recompute_ok(doc, *card.values())


def test_host_pairs_come_from_the_host_and_follow_its_label(doc, popup, card):
    box, tent, step = card["Box"], card["Tent"], card["Step"]
    built = popup.card_scaffold.for_card(card["Card"])
    names = ["Box.top", "Box.side_ground", "Box.side_backdrop"]
    assert built.pair_names("Box") == names == popup.card_scaffold.host_pair_names(box)
    layer = card["Layer"]  # what the workbench expects a host to offer is what the core offers
    assert built.pair_names("Layer") == popup.card_scaffold.host_pair_names(layer)
    assert built.pair_names("Tent") == [] == popup.card_scaffold.host_pair_names(tent)
    v_fold = card["VFold"]
    assert (
        built.pair_names("VFold") == ["VFold.wings"] == popup.card_scaffold.host_pair_names(v_fold)
    )
    assert built.pair_names(card["Card"].Name) == ["central fold"]
    assert tent.getEnumerationsOfProperty("HostPair") == names
    assert (tent.HostPair, step.HostPair) == ("Box.top", "Box.side_ground")
    assert tent.Card is card["Card"] and step.Card is card["Card"]
    step_points = vertices(step.Shape)
    box.Label = "Cake"
    recompute_ok(doc, *card.values())
    assert (tent.HostPair, step.HostPair) == ("Cake.top", "Cake.side_ground")
    assert vertices(step.Shape) == pytest.approx(step_points, abs=1e-12)
    names = [p.name for p in popup.card_scaffold.for_card(card["Card"]).scaffold.patches]
    assert "Cake.TG" in names and not any(n.startswith("Box.") for n in names)
    step.HostPair = "Cake.side_backdrop"  # same step on the other wall: mirrored in x
    recompute_ok(doc, *card.values())
    mirrored = np.array(vertices(step.Shape)) * [-1.0, 1.0, 1.0]
    assert_same_points(mirrored, step_points, 1e-9)


def test_moving_and_removing_mechanisms_updates_the_card(doc, popup, card):
    other = popup.make.make_card(doc, preset="A4", name="Other")
    card["Box"].Host = other  # the box and what stands on it move to the other card
    assert all(card[n].Card is other for n in ("Tent", "Layer", "Step"))
    assert card["Box"].getEnumerationsOfProperty("HostPair") == ["central fold"]
    recompute_ok(doc, other, *card.values())
    whole, other_whole = (popup.card_scaffold.assembled_shape(c) for c in (card["Card"], other))
    assert len(whole.Faces) == 10 and len(other_whole.Faces) == ALL_FACES - 8
    doc.removeObject("VFold")
    assert "Touched" in card["Card"].State
    recompute_ok(doc, card["Card"])
    assert len(popup.card_scaffold.assembled_shape(card["Card"]).Faces) == 8


def test_mechanisms_move_with_their_card(doc, popup, card, freecad):
    before = {name: obj.Shape.BoundBox for name, obj in card.items()}
    card["Card"].Placement = freecad.Placement(freecad.Vector(5, -7, 11), freecad.Rotation())
    recompute_ok(doc, *card.values())
    for name, obj in card.items():
        box = obj.Shape.BoundBox
        assert (box.XMin, box.YMin, box.ZMin) == pytest.approx(
            (before[name].XMin + 5, before[name].YMin - 7, before[name].ZMin + 11), abs=1e-9
        )


def test_thickened_card_has_one_solid_per_patch(doc, popup, card):
    card["Card"].Thickened = True
    card["Card"].PaperThickness = 0.3
    recompute_ok(doc, *card.values())
    for name, count in FACES.items():
        assert len(card[name].Shape.Solids) == count and card[name].Shape.isValid()
    whole = popup.card_scaffold.assembled_shape(card["Card"])
    assert len(card["Card"].Shape.Solids) == 2 and len(whole.Solids) == ALL_FACES
    area = sum(p.area() for p in popup.card_scaffold.for_card(card["Card"]).scaffold.patches)
    assert whole.Volume == pytest.approx(0.3 * area, rel=1e-6)


def test_make_refuses_unknown_pairs_and_parameters(doc, popup, card):
    with pytest.raises(ValueError, match=r"host_pair = 'Box.bottom', must be one of"):
        popup.make.make_tent_fold(card["Box"], host_pair="Box.bottom")
    with pytest.raises(TypeError, match="unknown parameter"):
        popup.make.make_step_fold(card["Card"], rise=3)
    with pytest.raises(ValueError, match="must be a PopUpCard or a mechanism"):
        popup.make.make_box_fold(doc.addObject("App::FeaturePython", "Plain"))
    assert popup.card_scaffold.host_pair_names(card["Tent"]) == []  # a tent offers nothing


@pytest.mark.parametrize("kind", ["tent", "step", "v", "box", "v_box", "floating_layer"])
def test_a_new_mechanism_fits_its_host(doc, popup, kind):
    # What the toolbar commands build: defaults fitted to the host pair, valid alone on an A5
    # card and nested on the top of a box with default parameters.
    make = getattr(popup.make, f"make_{kind}" if kind == "floating_layer" else f"make_{kind}_fold")
    card = popup.make.make_card(doc, preset="A5")
    obj = make(card)
    recompute_ok(doc, card, obj)
    assert popup.validity.run_check(card)["valid"] is True, list(card.Diagnostics)
    doc.removeObject(obj.Name)
    box = popup.make.make_box_fold(card)
    nested = make(box)
    recompute_ok(doc, card, box, nested)
    assert nested.HostPair == f"{box.Label}.top"
    assert popup.validity.run_check(card)["valid"] is True, list(card.Diagnostics)


def test_proxies_keep_no_state_and_carry_a_version(doc, popup, card):
    for obj in card.values():
        for state in (obj.Proxy.__getstate__(), obj.Proxy.dumps()):
            json.dumps(state)
        assert obj.Version == "1"
        assert obj.getEditorMode("Version") == ["ReadOnly"]
    assert card["Tent"].getEditorMode("SlopeBackdrop") == ["ReadOnly"]
    assert card["Box"].getEditorMode("Card") == ["Hidden"]
    assert card["Card"].getEditorMode("Valid") == ["ReadOnly"]
    assert card["Card"].Proxy.TYPE == "PopUp::Card"
    assert {obj.Proxy.TYPE for obj in card.values()} == {
        "PopUp::Card",
        "PopUp::TentFold",
        "PopUp::StepFold",
        "PopUp::VFold",
        "PopUp::BoxFold",
        "PopUp::VBoxFold",
        "PopUp::FloatingLayer",
    }


def figures(objects):
    return {
        name: {"vertices": vertices(obj.Shape), "faces": len(obj.Shape.Faces)}
        for name, obj in objects.items()
    }


REOPEN_SCRIPT = """
import json
doc = FreeCAD.openDocument({path!r})
out = {{}}
for name in {names!r}:
    obj = doc.getObject(name)
    out[name] = {{"proxy": obj.Proxy is not None, "version": obj.Version,
                 "type": getattr(obj.Proxy, "TYPE", None)}}
card = doc.getObject("Card")
out["card"] = {{"valid": card.Valid, "fold_angle": card.FoldAngle.Value, "preset": card.Preset}}
for obj in doc.Objects:
    obj.touch()
doc.recompute()
for name in {names!r}:
    obj = doc.getObject(name)
    out[name].update(state=list(obj.State), faces=len(obj.Shape.Faces),
                     vertices=[[v.X, v.Y, v.Z] for v in obj.Shape.Vertexes],
                     host_pair=getattr(obj, "HostPair", None))
out["card"]["valid_after"] = card.Valid
print(json.dumps(out))
"""


def test_every_feature_survives_save_and_reopen(doc, popup, card, tmp_path, run_fresh_freecad):
    card["Card"].FoldAngle = 63.0
    recompute_ok(doc, *card.values())
    assert popup.validity.run_check(card["Card"])["valid"]
    expected = figures(card)
    path = str(tmp_path / "nested_card.FCStd")
    doc.saveAs(path)

    script = REOPEN_SCRIPT.format(path=path, names=list(card))
    reopened = run_fresh_freecad(script)
    assert reopened["card"] == {
        "valid": True,
        "fold_angle": pytest.approx(63.0),
        "preset": "Custom",
        "valid_after": True,
    }
    for name, obj in card.items():
        got = reopened[name]
        assert got["proxy"], f"{name}: proxy not restored (sandbox Mod/PopUp symlink?)"
        assert got["version"] == "1" and got["type"] == obj.Proxy.TYPE
        assert "Invalid" not in got["state"] and "Touched" not in got["state"], got["state"]
        assert got["host_pair"] == getattr(obj, "HostPair", None)
        assert got["faces"] == expected[name]["faces"]
        assert np.array(got["vertices"]) == pytest.approx(
            np.array(expected[name]["vertices"]), abs=1e-9
        )


def test_rotation_arm_feature_follows_its_closed_form(doc, popup):
    card = popup.make.make_card(doc, width=240, depth=140)
    arm = popup.make.make_rotation_arm(card, offset=60, spine=40, run=30, arm=45)
    card.FoldAngle = 100.0
    doc.recompute()
    assert arm.Shape.isValid()
    assert len(arm.Shape.Faces) == 2
    params = popup.core.RotationArmParams()
    params.offset, params.spine, params.run, params.arm = 60.0, 40.0, 30.0, 45.0
    tip = popup.core.rotation_arm_tip(params, math.radians(100.0))
    # The arm wing's vertex P is the tip: nearest vertex within 1e-9 of the closed form.
    distances = [
        (v.Point - popup_vector(tip)).Length for v in arm.Shape.Faces[0].OuterWire.Vertexes
    ]
    assert min(distances) < 1e-9
    arm.Arm = 60.0  # above l²/w = 53.3 mm: refused, naming the property
    doc.recompute()
    assert "Invalid" in arm.State or "Error" in arm.State
    assert card.Shape.isValid() and "Invalid" not in card.State


def popup_vector(values):
    import FreeCAD

    return FreeCAD.Vector(*[float(v) for v in values])


def test_step_on_v_fold_wings_is_a_valid_diagonal_translation(doc, popup):
    card = popup.make.make_card(doc, width=240, depth=140)
    v_fold = popup.make.make_v_fold(
        card, offset=60, run=40, hinge_angle=45, spine=45, spine_angle=90, name="Spine"
    )
    step = popup.make.make_step_fold(
        v_fold, "Spine.wings", offset=10, width=20, run_ground=8, run_backdrop=8, name="Arm"
    )
    card.FoldAngle = 70.0
    doc.recompute()
    assert step.Shape.isValid() and len(step.Shape.Faces) == 2
    report = popup.validity.run_check(card)
    assert report["valid"], report["diagnostics"]
    # Too wide for the triangular wings near the tip: refused, the rest still builds.
    step.Offset = 30.0
    step.RunGround = step.RunBackdrop = 12.0
    doc.recompute()
    assert "Invalid" in step.State or "Error" in step.State
    assert "Invalid" not in v_fold.State and v_fold.Shape.isValid()


def test_vertical_translation_corner_slides_along_the_fold(doc, popup):
    card = popup.make.make_card(doc, width=240, depth=140)
    mover = popup.make.make_vertical_translation(
        card, offset=80, side=40, height=30, wall_angle=40, name="Mover"
    )
    card.FoldAngle = 60.0
    doc.recompute()
    assert mover.Shape.isValid() and len(mover.Shape.Faces) == 4
    params = popup.core.VBoxFoldParams()
    params.offset, params.side, params.height = 80.0, 40.0, 30.0
    params.wall_angle = math.radians(40.0)
    corner = popup_vector(popup.core.v_box_front_corner(params, math.radians(60.0)))
    nearest = min((v.Point - corner).Length for v in mover.Shape.Vertexes)
    assert nearest < 1e-9
    assert abs(corner.x) < 1e-12 and corner.y < 80.0 - 1.0  # it moved along the fold only
    assert popup.validity.run_check(card)["valid"]


def test_horizontal_translation_slides_m_through_the_slit(doc, popup):
    card = popup.make.make_card(doc, width=240, depth=140)
    slider = popup.make.make_horizontal_translation(
        card, offset=60, width=50, run_ground=40, run_backdrop=20, reach=70, name="Slider"
    )
    card.FoldAngle = 90.0
    doc.recompute()
    assert slider.Shape.isValid() and len(slider.Shape.Faces) == 3  # riser, tread, M
    params = popup.core.HorizontalTranslationParams()
    params.offset, params.width, params.run_ground, params.run_backdrop, params.reach = (
        60.0,
        50.0,
        40.0,
        20.0,
        70.0,
    )
    x, z = popup.core.horizontal_translation_tip(params, math.radians(90.0))
    tip = popup_vector((x, 65.0, z))  # M stops 5 mm short of the step's ends (the slit's bridge)
    assert min((v.Point - tip).Length for v in slider.Shape.Vertexes) < 1e-9
    scaffold = popup.card_scaffold.for_card(card).scaffold
    assert len(scaffold.slits) == 1
    assert popup.validity.run_check(card)["valid"]
    slider.RunBackdrop = 45.0  # not below RunGround: refused, naming the property
    doc.recompute()
    assert "Invalid" in slider.State or "Error" in slider.State


def test_box_fold_with_stacked_panel_pairs(doc, popup):
    card = popup.make.make_card(doc, width=240, depth=140)
    box = popup.make.make_box_fold(
        card, offset=60, width=100, depth_ground=30, depth_backdrop=30, height=30, name="Box"
    )
    box.PanelPairs = 3
    doc.recompute()
    assert box.Shape.isValid() and len(box.Shape.Faces) == 5 + 2 * 2 * 3
    assert popup.validity.run_check(card)["valid"]
    box.PanelPairs = 0
    doc.recompute()
    assert "Invalid" in box.State or "Error" in box.State


def test_a_count_beyond_32_bits_puts_only_its_feature_in_error(doc, popup, card):
    card["Box"].PanelPairs = 2**31
    doc.recompute()
    assert in_error(card["Box"]) and not in_error(card["Card"])
    assert "PanelPairs = 2147483648, must be below 2147483648" in card["Box"].getStatusString()
    report = popup.validity.run_check(card["Card"])  # reports, does not raise
    assert report["valid"] is False
    assert any("PanelPairs" in d["message"] for d in report["diagnostics"])
