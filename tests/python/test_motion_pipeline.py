"""Motion from an animation, end to end (issue 13 §4), on the project's own animations
(tools/make_animations.py, tools/blender_rig.py; tests/data/animations/).

What each check is measured against:
- the hand-written BVH files against their known paths (NAME.json, the laws they were written
  from; Blender's importer agrees with them to 2e-5 mm, tools/blender_check_bvh.py);
- the synthetic rigs against the mechanism they were driven by: its type, the parameters its
  path determines (tools/make_animations.identifiable) within 1 % of the card (2.1 mm of its
  210 mm width) and a motion error near zero;
- collisions against the simulator (popupcore.check_validity on the returned scaffold), not the
  design's own verdict;
- the skinned figure against the tip paths Blender recorded when it made it (figure.json).
"""

import json
import math
import os
import sys

import numpy as np
import pytest

import popupcore

SOURCE = os.environ["POPUP_SOURCE_DIR"]
DATA = os.path.join(SOURCE, "tests", "data", "animations")
sys.path.insert(0, os.path.join(SOURCE, "tools"))
import make_animations  # noqa: E402

ONE_PERCENT = 0.01 * make_animations.CARD_WIDTH  # 2.1 mm: "within 1 % of the card size"
NEAR_ZERO_MM = 0.5  # motion error (RMS over the samples, eq 6.6) of a path a mechanism can make
RIGS = {
    "rig_rotation": "rotation",
    "rig_rotation_off_fold": "rotation",
    "rig_vertical": "vertical",
    "rig_horizontal": "horizontal",
    "rig_diagonal": "diagonal",
}


def meta(name):
    with open(os.path.join(DATA, name + ".json"), encoding="utf-8") as f:
        return json.load(f)


def view_of(m):
    view = popupcore.MotionView()
    view.scale = m["view"]["scale"]
    view.centre = tuple(m["view"]["centre"])
    return view


def options_for(name, seed=1):
    o = popupcore.MotionOptions()
    o.view = view_of(meta(name))
    o.seed = seed
    return o


_designs = {}


def design(name, seed=1):
    """design_motion of a test animation, once per (name, seed) in this session."""
    if (name, seed) not in _designs:
        animation = popupcore.load_animation(os.path.join(DATA, name + ".bvh"))
        _designs[(name, seed)] = popupcore.design_motion(animation, options_for(name, seed))
    return _designs[(name, seed)]


def chain_index(names, bone):
    """The chain ending at `bone`: its own name, or its end site's (assimp names a BVH end site
    EndSite_<joint>)."""
    for i, n in enumerate(names):
        if n in (bone, "EndSite_" + bone):
            return i
    raise AssertionError(f"no chain ends at {bone} (chains {names})")


def chain_for(result, bone):
    return result.chains[chain_index([c.name for c in result.chains], bone)]


# ------------------------------------------------------------------ the data itself


def test_committed_animations_are_what_the_tool_makes(tmp_path):
    for name in make_animations.NAMES:
        path = make_animations.write(name, str(tmp_path))
        stems = [os.path.basename(path)]
        if path.endswith(".bvh"):
            stems.append(os.path.basename(path)[:-4] + ".json")
        for stem in stems:
            with open(tmp_path / stem, "rb") as fresh, open(os.path.join(DATA, stem), "rb") as kept:
                assert fresh.read() == kept.read(), f"{stem}: rerun tools/make_animations.py"


@pytest.mark.parametrize("s", np.linspace(0.0, 1.0, 19))
def test_written_out_closed_forms_equal_the_library(s):
    """make_animations writes the rotation, vertical and horizontal laws from docs/MATH.md; they
    must be the library's (popupcore's closed forms are checked against the simulator)."""
    theta = math.pi * s
    p = make_animations.MECHANISMS["rotation"]["params"]
    r = popupcore.RotationArmParams()
    r.offset, r.spine, r.run, r.arm = p["offset"], p["spine"], p["run"], p["arm"]
    assert make_animations.rotation_tip(p, [s])[0] == pytest.approx(
        np.array(popupcore.rotation_arm_tip(r, theta))[:2], abs=1e-9
    )
    p = make_animations.MECHANISMS["rotation_off_fold"]["params"]
    for hinge in (p["hinge"], -p["hinge"]):
        arm = popupcore.RotationArmParams()
        arm.offset, arm.spine, arm.run, arm.arm = 0.0, p["spine"], p["run"], p["arm"]
        layer = popupcore.FloatingLayerParams()
        layer.offset, layer.width, layer.support = p["offset"], p["spine"], abs(hinge)
        side = popupcore.LayerSide.ground if hinge > 0 else popupcore.LayerSide.backdrop
        law = make_animations.rotation_off_fold_tip(dict(p, hinge=hinge), [s])[0]
        assert law == pytest.approx(
            np.array(popupcore.rotation_arm_tip_on_layer_side(arm, layer, side, theta))[:2],
            abs=1e-9,
        )
    p = make_animations.MECHANISMS["vertical"]["params"]
    v = popupcore.VBoxFoldParams()
    v.offset, v.side, v.height, v.wall_angle = p["offset"], p["side"], p["height"], p["wall_angle"]
    assert make_animations.vertical_tip(p, [s])[0] == pytest.approx(
        np.array(popupcore.v_box_front_corner(v, theta))[:2], abs=1e-9
    )
    p = make_animations.MECHANISMS["horizontal"]["params"]
    h = popupcore.HorizontalTranslationParams()
    h.offset, h.width, h.run_ground, h.run_backdrop, h.reach = (
        p[k] for k in ("offset", "width", "run_ground", "run_backdrop", "reach")
    )
    x_law = make_animations.horizontal_tip(p, [s])[0][0]
    assert x_law == pytest.approx(popupcore.horizontal_translation_tip(h, theta)[0], abs=1e-9)


def _build_known_mechanisms(names):
    card = popupcore.make_card(popupcore.CardParams())
    fold = popupcore.central_fold(card)

    def params(cls, values):
        out = cls()
        for key, value in values.items():
            setattr(out, key, value)
        return out

    for name in names:
        m = make_animations.MECHANISMS[name]
        p = m["params"]
        if m["type"] == "rotation_arm":
            popupcore.add_rotation_arm(card, fold, params(popupcore.RotationArmParams, p), name)
        elif m["type"] == "vertical_translation":
            vb = params(popupcore.VBoxFoldParams, p)
            vb.back = False
            popupcore.add_vertical_translation(card, fold, vb, name)
        elif m["type"] == "horizontal_translation":
            hp = params(popupcore.HorizontalTranslationParams, p)
            popupcore.add_horizontal_translation(card, fold, hp, name)
        else:
            vf = popupcore.add_v_fold(card, fold, params(popupcore.VFoldParams, p["v_fold"]), name)
            step = params(popupcore.StepFoldParams, p["step_fold"])
            popupcore.add_step_fold(card, vf.offered[0], step, name + "_step")
    return card


def test_the_synthetic_rigs_mechanisms_make_a_valid_card_together():
    """The answer the rigs ask for exists: all four mechanisms on one A4 card pass the simulator
    (so rig_four can be recovered without a collision)."""
    four = ["rotation", "vertical", "horizontal", "diagonal"]
    report = popupcore.check_validity(_build_known_mechanisms(four))
    assert report.valid, [d.message for d in report.diagnostics]


# ------------------------------------------------------------------ reading the files


BVH_NAMES = [n for n in make_animations.ANIMATIONS]


@pytest.mark.parametrize("name", BVH_NAMES)
def test_bvh_end_effector_paths_are_the_known_paths(name):
    m = meta(name)
    animation = popupcore.load_animation(os.path.join(DATA, m["file"]))
    assert animation.frames == m["frames"]
    targets = popupcore.motion_targets(animation, view_of(m))
    # scale 1 and the bounding box's centre: the file's (x, y) are the card's
    to_card = np.asarray(targets.animation_to_card)
    assert to_card[:2, :2] == pytest.approx(np.eye(2), abs=1e-9)
    assert to_card[:2, 3] == pytest.approx([0.0, 0.0], abs=1e-4)  # the file has 6 decimals
    names = [c.name for c in targets.chains]
    for bone, entry in m["known"].items():
        if entry["kind"] == "still":
            continue
        path = targets.paths[chain_index(names, bone)]
        assert path.s[0] == 0.0 and path.s[-1] == 1.0
        want = make_animations.known_path(entry, path.s)
        assert np.asarray(path.effector) == pytest.approx(want, abs=0.02), f"{name}: {bone}"


@pytest.mark.parametrize("extension", ["glb", "fbx", "bvh"])
def test_blender_figure_reads_with_its_recorded_hand_paths(extension):
    """The skinned figure made by tools/blender_rig.py: every format reads (skin and mesh where
    the format has them) and the hands follow the paths Blender recorded, mapped through the
    reported animation_to_card (glTF/FBX are y up, BVH z up; metres)."""
    m = meta("figure")
    f = m["files"][extension]
    animation = popupcore.load_animation(os.path.join(DATA, f["file"]))
    assert animation.frames == m["frames"]
    if extension != "bvh":
        assert animation.mesh is not None and len(animation.mesh.vertices) > 0
    view = popupcore.MotionView()
    view.view, view.up = tuple(f["view"]), tuple(f["up"])
    targets = popupcore.motion_targets(animation, view)
    to_card = np.asarray(targets.animation_to_card)
    # Blender world (x, y, z) in the file's axes: y up files have (x, z, −y)
    to_file = (
        (lambda p: np.array(p)) if extension == "bvh" else (lambda p: np.array([p[0], p[2], -p[1]]))
    )
    names = [c.name for c in targets.chains]
    for tip in ("Hand.R", "Hand.L"):
        path = targets.paths[chain_index(names, tip)]
        end = "tail" if extension == "bvh" else "head"  # a BVH end site is the bone's tail
        recorded = np.array(m["tips_blender_world"][tip][end])
        frames = np.array(path.s) * (m["frames"] - 1)
        for s_frame, got in zip(frames, path.effector):
            lo = int(math.floor(s_frame))
            hi = min(lo + 1, m["frames"] - 1)
            t = s_frame - lo
            # between frames the bones turn about one axis: a small chord error only
            world = (1 - t) * recorded[lo] + t * recorded[hi]
            want = (to_card @ np.append(to_file(world), 1.0))[:2]
            assert np.asarray(got) == pytest.approx(want, abs=0.01 * targets.diagonal_mm)


# ------------------------------------------------------------------ the pipeline (§4)


# Known failure of design_motion as merged on 2026-11-23 (strict: it fails the suite once fixed,
# so the mark comes off). STRAIGHT: a straight path keeps only its two end points under the
# flatness-only adaptive sampling (τangle), so E_m cannot tell a floating layer (whose platform
# point also slides out along x in projection) from the mechanism that moves like the path.
STRAIGHT = "straight paths are sampled at their 2 end points only (docs/MOTION_RESULTS.md)"


@pytest.mark.parametrize("name", list(RIGS))
def test_synthetic_rig_recovers_its_mechanism(name):
    m = meta(name)
    ((bone, known),) = m["known"].items()
    result = design(name)
    assert result.valid, [d.message for d in result.diagnostics]
    arm = chain_for(result, bone)
    assert arm.mapping == RIGS[name]
    assert arm.status == "animated", arm.reason
    assert arm.error_mm < NEAR_ZERO_MM
    # A mechanism alone follows it too (its own, or one that ties: a diagonal whose step rises
    # straight draws a vertical path as well): the best-alone bound is near 0, not the page.
    assert arm.bound_mm < NEAR_ZERO_MM and arm.bound_mechanism != "printed"
    # the achieved path is the known one at every sample
    want = make_animations.known_path(known, arm.s)
    assert np.abs(np.asarray(arm.achieved) - want).max() < ONE_PERCENT
    ident = known["identifiable"]
    carried = [mm for mm in result.mechanisms if mm.name in arm.mechanisms]
    types = sorted(mm.type for mm in carried)
    if known["type"] == "rotation_off_fold":
        # A floating layer carrying the arm on its side pair; the path fixes only the family's
        # invariants (make_animations.identifiable, docs/MATH.md).
        assert types == ["floating_layer", "rotation_arm"]
        layer = next(mm for mm in carried if mm.type == "floating_layer")
        rotation = next(mm for mm in carried if mm.type == "rotation_arm")
        assert rotation.host == layer.name + ".side_ground"
        lp, p = layer.parameters, rotation.parameters
        assert p["offset"] == 0.0 and lp["width"] == p["spine"]
        assert lp["offset"] + p["spine"] == pytest.approx(ident["s_along"], abs=ONE_PERCENT)
        assert p["run"] + p["arm"] == pytest.approx(ident["reach"], abs=ONE_PERCENT)
        assert lp["support"] + p["run"] == pytest.approx(ident["s_across"], abs=ONE_PERCENT)
    elif known["type"] == "rotation_arm":
        assert types == ["rotation_arm"]
        p = carried[0].parameters
        for key in ("arm", "spine", "run", "offset"):
            assert p[key] == pytest.approx(ident[key], abs=ONE_PERCENT), key
    elif known["type"] == "vertical_translation":
        assert types == ["vertical_translation"]
        p = carried[0].parameters
        assert p["offset"] == pytest.approx(ident["offset"], abs=ONE_PERCENT)
        travel = p["height"] * math.sin(p["wall_angle"])
        assert travel == pytest.approx(ident["travel"], abs=ONE_PERCENT)
    elif known["type"] == "horizontal_translation":
        assert types == ["horizontal_translation"]
        p = carried[0].parameters
        assert p["reach"] == pytest.approx(ident["reach"], abs=ONE_PERCENT)
        assert p["offset"] + 0.5 * p["width"] == pytest.approx(ident["y"], abs=ONE_PERCENT)
    else:
        assert types == ["step_fold", "v_fold"]
        assert np.asarray(arm.achieved[0]) == pytest.approx(ident["closed"], abs=ONE_PERCENT)
        assert np.asarray(arm.achieved[-1]) == pytest.approx(ident["open"], abs=ONE_PERCENT)


def test_four_mechanisms_on_one_rig_are_all_recovered():
    m = meta("rig_four")
    result = design("rig_four")
    assert result.valid, [d.message for d in result.diagnostics]
    for bone, known in m["known"].items():
        arm = chain_for(result, bone)
        assert arm.mapping == known["mapping"], bone
        assert arm.status == "animated", f"{bone}: {arm.reason}"
        assert arm.error_mm < NEAR_ZERO_MM, bone
    assert result.weighted_error < 0.01


@pytest.mark.parametrize("seed", [1, 2, 3])
@pytest.mark.parametrize("name", ["character", "conflicting_arms", "crossing_alike", "rig_four"])
def test_the_design_never_collides(name, seed):
    """The simulator, not the design's own verdict: the returned scaffold is intersection-free
    and valid over the whole sweep."""
    result = design(name, seed)
    report = popupcore.check_validity(result.scaffold)
    assert report.intersection_free, [d.message for d in report.diagnostics]
    assert report.valid == result.valid
    assert result.valid


@pytest.mark.parametrize("seed", [1, 2, 3])
@pytest.mark.parametrize("name", ["character", "conflicting_arms", "crossing_alike", "rig_four"])
def test_every_moving_mechanism_follows_its_chain_closer_than_its_printed_part(name, seed):
    """A mechanism that moves a part no closer to its path than the part printed on the page
    (open-state point (x1, y1) at (x1 sin(90° s), y1): docs/MATH.md, a printed part's path) takes
    room for nothing; the design prints such a part. Recomputed here from each chain's target."""
    result = design(name, seed)
    moving = 0
    for chain in result.chains:
        if chain.status == "stationary":
            continue
        moving += 1
        target = np.asarray(chain.target, dtype=float)
        x1, y1 = target[-1]
        s = np.asarray(chain.s, dtype=float)
        printed = np.c_[x1 * np.sin(np.pi * s / 2), np.full_like(s, y1)]
        printed_mm = math.sqrt(np.mean(np.sum((printed - target) ** 2, axis=1)))
        assert chain.error_mm < printed_mm, (chain.name, chain.mapping, chain.error_mm, printed_mm)
    assert moving >= 1


def test_two_crossing_arms_that_move_alike_are_merged():
    result = design("crossing_alike")
    arms = [chain_for(result, bone) for bone in ("LeftArmFore", "RightArmFore")]
    statuses = sorted(c.status for c in arms)
    assert "stationary" not in statuses, [(c.name, c.reason) for c in arms]
    assert "merged" in statuses, [(c.name, c.status, c.reason) for c in arms]
    merged = [c for c in arms if c.status == "merged"][0]
    other = [c for c in arms if c is not merged][0]
    assert merged.reason, "a merged chain says why"
    # merged onto one patch: they share the carrying mechanism
    assert set(merged.mechanisms) & set(other.mechanisms)
    # both hands still rise the 40 mm they rise in the file
    for c in arms:
        travel = np.asarray(c.achieved[-1]) - np.asarray(c.achieved[0])
        assert travel[1] == pytest.approx(40.0, abs=4 * ONE_PERCENT)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_two_conflicting_arms_leave_one_stationary_and_say_why(seed):
    """Both hands leave the fold at (0, 85) in opposite directions, on a card 110 mm along the
    fold: whatever carries either stands on the fold around y = 85 and there is no room to move
    one out of the way. (On the rig's A4 card the search finds room: a rotation off the fold, its
    layer at y = 115, reaches down to the hand; docs/MOTION_RESULTS.md.)"""
    options = options_for("conflicting_arms", seed)
    options.view.card_width = 110.0
    animation = popupcore.load_animation(os.path.join(DATA, "conflicting_arms.bvh"))
    result = popupcore.design_motion(animation, options)
    arms = [chain_for(result, bone) for bone in ("LeftArmFore", "RightArmFore")]
    still = [c for c in arms if c.status == "stationary"]
    moving = [c for c in arms if c.status == "animated"]
    assert len(still) == 1 and len(moving) == 1, [(c.name, c.status, c.reason) for c in arms]
    assert still[0].reason, "the report says why"
    assert still[0].mapping == "stationary"
    assert result.valid


def test_the_same_seed_gives_the_same_design():
    def snapshot(result):
        return (
            [(m.type, m.name, m.host, sorted(m.parameters.items())) for m in result.mechanisms],
            [(c.name, c.mapping, c.status, c.error) for c in result.chains],
            result.weighted_error,
            result.cost,
        )

    first = design("character", seed=7)
    animation = popupcore.load_animation(os.path.join(DATA, "character.bvh"))
    again = popupcore.design_motion(animation, options_for("character", seed=7))
    assert snapshot(first) == snapshot(again)


def test_trajectory_json_example_reads_with_its_points():
    """tests/data/animations/trajectories.json (docs/ANIMATION_INPUT.md's format): each effector's
    bone is at its listed point at every frame, the head hanging from the hip."""
    path = os.path.join(DATA, "trajectories.json")
    with open(path, encoding="utf-8") as f:
        doc = json.load(f)
    animation = popupcore.load_trajectories(path)
    frames = len(doc["effectors"][0]["points"])
    assert animation.frames == frames
    assert np.asarray(animation.frame_times_s) == pytest.approx(np.arange(frames) / 30.0)
    names = [name for name, _ in animation.bones]
    parents = dict(animation.bones)
    assert names[parents["head"]] == "hip"
    for frame in (0, frames // 2, frames - 1):
        pose = popupcore.forward_kinematics(animation, frame)
        for effector in doc["effectors"]:
            point = np.zeros(3)
            point[: len(effector["points"][frame])] = effector["points"][frame]
            got = np.asarray(pose[names.index(effector["name"])])[:3, 3]
            assert got == pytest.approx(point, abs=1e-9), (effector["name"], frame)


def test_arm_rotation_is_held_to_the_rotation_arms_floor():
    """arm_rotation's arc (centre (-40, 110), r = 40, 0° → 90°) leaves the fold along it, but
    every point a rotation arm carries has x = k sin δ (docs/MATH.md, What a rotation arm can
    follow): the least-squares k over the chain's own samples leaves an x residual that no
    rotation arm can go under. The pipeline's arm must respect that floor and stay near it (the
    y law costs the rest: an unbounded fit of the closed form ends at 7.01 mm, 1.10 × the floor
    of these samples); the issue's 0.03 goal is below the floor (0.113 of the diagonal)."""
    result = design("arm_rotation")
    (chain,) = result.chains
    assert chain.mapping == "rotation" and chain.status == "animated", chain.reason
    delta = 0.5 * math.pi * np.asarray(chain.s)
    x = np.asarray(chain.target)[:, 0]
    k = np.dot(np.sin(delta), x) / np.dot(np.sin(delta), np.sin(delta))
    floor = math.sqrt(np.mean((k * np.sin(delta) - x) ** 2))
    assert floor / result.targets.diagonal_mm > 0.03  # the goal is out of the arm's reach
    assert chain.error_mm >= floor - 1e-9
    assert chain.error_mm <= 1.2 * floor


def test_a_character_that_only_stands_still_stands_on_a_floating_layer(tmp_path):
    """Thesis §6.4: a part that does not move stands on a floating layer. Alone on the card it
    costs what a part printed on the page costs (both follow its still path), and the tie goes
    to the layer, so the card has something that pops up."""
    path = tmp_path / "still.json"
    still = [[30.0, 40.0, 0.0]] * 5
    path.write_text(
        json.dumps({"effectors": [{"name": "statue", "root": [0, 40, 0], "points": still}]})
    )
    animation = popupcore.load_trajectories(str(path))
    o = popupcore.MotionOptions()
    o.seed = 1
    result = popupcore.design_motion(animation, o)
    assert result.valid
    (chain,) = result.chains
    assert (chain.status, chain.mapping) == ("stationary", "stationary")
    assert "floating layer carries it" in chain.reason
    assert [m.type for m in result.mechanisms] == ["floating_layer"]


@pytest.mark.parametrize("seed", [1, 2])
def test_alike_arms_the_search_left_apart_share_a_patch_instead_of_standing_still(seed):
    """crossing_alike placed as `popup animate` places it (fitted to the A4 card, 186 x 136.5 mm):
    the search ended with the two hands on different mechanisms, one of them far off its path,
    and the repair made the other stationary "because they move too differently" though their
    motions are 1e-5 mm apart. Alike chains now share one patch when that collides with nothing
    and costs less than standing still; a reason never says they move differently when they
    do not."""
    o = popupcore.MotionOptions()
    o.view.card_width, o.view.card_depth = 186.0, 136.5
    o.seed = seed
    animation = popupcore.load_animation(os.path.join(DATA, "crossing_alike.bvh"))
    result = popupcore.design_motion(animation, o)
    assert result.valid
    arms = [chain_for(result, bone) for bone in ("LeftArmFore", "RightArmFore")]
    assert [c.status for c in arms] == ["merged", "merged"], [(c.name, c.reason) for c in arms]
    assert len({tuple(c.mechanisms) for c in arms}) == 1
    for c in result.chains:
        assert "move too differently" not in c.reason, c.reason
