"""popupcore's motion input (issue 13): animations read from files written here, with trajectories
known by construction (a BVH arm turning at a known rate, a JSON circle)."""

import json
import math

import numpy as np
import pytest

import popupcore


def codes(error):
    return [d["code"] for d in error.value.diagnostics]


def arm_bvh(frames, rate_deg=9.0):
    """Shoulder at (0, 0, 0) turning about z at rate_deg per frame; elbow 3 along x; end site 2
    further along x. Frame time 0.04 s."""
    lines = [
        "HIERARCHY",
        "ROOT Shoulder",
        "{",
        "  OFFSET 0 0 0",
        "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation",
        "  JOINT Elbow",
        "  {",
        "    OFFSET 3 0 0",
        "    CHANNELS 3 Zrotation Xrotation Yrotation",
        "    End Site",
        "    {",
        "      OFFSET 2 0 0",
        "    }",
        "  }",
        "}",
        "MOTION",
        f"Frames: {frames}",
        "Frame Time: 0.04",
    ]
    lines += [f"0 0 0 {rate_deg * f} 0 0 0 0 0" for f in range(frames)]
    return "\n".join(lines) + "\n"


def test_bvh_arm_forward_kinematics_and_targets(tmp_path):
    path = tmp_path / "arm.bvh"
    path.write_text(arm_bvh(21))
    animation = popupcore.load_animation(str(path))
    assert animation.frames == 21
    assert animation.mesh is None
    assert np.allclose(animation.frame_times_s, np.arange(21) * 0.04)
    names = [name for name, _ in animation.bones]
    elbow = names.index("Elbow")
    assert animation.bones[elbow][1] == names.index("Shoulder")
    tip = [i for i, (_, parent) in enumerate(animation.bones) if parent == elbow][0]
    for frame in (0.0, 4.0, 10.5, 20.0):
        pose = popupcore.forward_kinematics(animation, frame)
        assert pose[tip].shape == (4, 4)
        a = math.radians(9.0 * frame)
        # assimp keeps keys as float: agreement to ~1e-6 of the length 5.
        assert np.allclose(pose[tip][:3, 3], [5 * math.cos(a), 5 * math.sin(a), 0], atol=1e-5)

    chains = popupcore.linkage_chains(animation, popupcore.ChainOptions())
    assert len(chains) == 1 and chains[0].bones[-1] == tip and chains[0].weight == 1.0

    view = popupcore.MotionView()
    view.scale = 10.0
    view.centre = (0.0, 100.0)
    targets = popupcore.motion_targets(animation, view)
    path_ = targets.paths[0]
    # 0 .. 180°: a half turn of a circle, 65 samples (docs/MATH.md, Motion targets).
    assert len(path_.s) == 65 and path_.s[0] == 0.0 and path_.s[-1] == 1.0
    assert path_.effector.shape == (65, 2)
    # Box: x in [-5, 5], y in [0, 5]: centre (0, 2.5) goes to (0, 100).
    for s, p in zip(path_.s, path_.effector):
        a = math.pi * s
        assert np.allclose(p, [50 * math.cos(a), 50 * math.sin(a) - 25 + 100], atol=1e-4)
    assert targets.animation_to_card.shape == (4, 4)
    assert targets.diagonal_mm == pytest.approx(10 * math.hypot(10, 5), rel=1e-6)
    assert (targets.first_frame, targets.last_frame) == (0, 20)


def test_trajectory_json_and_its_named_errors(tmp_path):
    good = tmp_path / "circle.json"
    points = [[10 * math.cos(math.pi * f / 8), 10 * math.sin(math.pi * f / 8)] for f in range(9)]
    good.write_text(
        json.dumps(
            {"frame_rate": 8, "effectors": [{"name": "paw", "root": [0, 0], "points": points}]}
        )
    )
    animation = popupcore.load_trajectories(str(good))
    assert animation.bones == [("paw.root", -1), ("paw", 0)]
    assert np.allclose(animation.frame_times_s, np.arange(9) / 8)
    assert np.allclose(popupcore.forward_kinematics(animation, 3)[1][:2, 3], points[3])
    assert popupcore.check_animation(animation).frames == 9

    def error_codes(name, document):
        bad = tmp_path / f"{name}.json"
        bad.write_text(document if isinstance(document, str) else json.dumps(document))
        with pytest.raises(popupcore.DesignError) as error:
            popupcore.load_trajectories(str(bad))
        return codes(error), str(error.value)

    cycle = {
        "effectors": [
            {"name": "a", "parent": "b", "points": [[0, 0], [1, 0]]},
            {"name": "b", "parent": "a", "points": [[0, 1], [1, 1]]},
        ]
    }
    assert error_codes("cycle", cycle)[0] == ["skeleton_cycle"]
    single = {"effectors": [{"name": "a", "root": [0, 0], "points": [[1, 0]]}]}
    assert error_codes("single", single)[0] == ["single_frame"]
    nan = {"effectors": [{"name": "a", "root": [0, 0], "points": [[1, 0], [float("nan"), 0]]}]}
    assert error_codes("nan", nan)[0] == ["non_finite_animation"]  # json.dumps writes NaN
    assert error_codes("none", {"effectors": []})[0] == ["no_animation"]
    wrong, message = error_codes(
        "wrong", {"effectors": [{"name": "a", "root": [0, 0], "points": [[1, 0], [1, "x"]]}]}
    )
    assert wrong == ["bad_animation"] and "effectors[0].points[1][1]" in message


def test_bad_files_raise_without_killing_python(tmp_path):
    truncated = tmp_path / "cut.bvh"
    truncated.write_text(arm_bvh(10)[:150])
    with pytest.raises(popupcore.DesignError) as error:
        popupcore.load_animation(str(truncated))
    assert codes(error) == ["unreadable_model"]
    garbage = tmp_path / "noise.fbx"
    garbage.write_bytes(bytes((i * 7919 + 13) % 251 for i in range(4096)))
    with pytest.raises(popupcore.DesignError) as error:
        popupcore.load_animation(str(garbage), timeout_s=30.0)
    assert codes(error) == ["unreadable_model"]
    one = tmp_path / "one.bvh"
    one.write_text(arm_bvh(1))
    with pytest.raises(popupcore.DesignError) as error:
        popupcore.load_animation(str(one))
    assert codes(error) == ["single_frame"]


def test_motion_view_fields_and_bad_options(tmp_path):
    view = popupcore.MotionView()
    assert view.view == (0.0, 0.0, -1.0) and view.up == (0.0, 1.0, 0.0)
    assert view.scale is None and view.centre is None
    assert (view.margin, view.card_width, view.card_depth) == (0.1, 210.0, 148.0)
    assert (view.first_frame, view.last_frame, view.angle_tolerance) == (0, -1, 2.0)
    with pytest.raises(popupcore.DesignError):
        view.view = (1, 2)
    path = tmp_path / "arm.bvh"
    path.write_text(arm_bvh(5))
    animation = popupcore.load_animation(str(path))
    view.up = (0, 0, -3)  # parallel to the view
    with pytest.raises(popupcore.DesignError) as error:
        popupcore.motion_targets(animation, view)
    assert codes(error) == ["bad_option"] and "up" in str(error.value)
    view = popupcore.MotionView()
    view.last_frame = 9
    with pytest.raises(popupcore.DesignError) as error:
        popupcore.motion_targets(animation, view, popupcore.ChainOptions())
    assert "last_frame" in str(error.value)


def test_chains_of_a_trajectory_tree_prune_by_bone_length(tmp_path):
    # arm.root -> arm (10 long) -> {hand (5 long), finger (0.1 long)}; lengths 0, 10, 5, 0.1:
    # mean 3.775 per bone, τp 0.09 -> 0.34: the finger is pruned, the hand continues the arm.
    def track(x, y):
        return [[x, y], [x, y + 1]]

    document = {
        "effectors": [
            {"name": "arm", "root": [0, 0], "points": track(10, 0)},
            {"name": "hand", "parent": "arm", "points": track(15, 0)},
            {"name": "finger", "parent": "arm", "points": track(10, 0.1)},
        ]
    }
    path = tmp_path / "tree.json"
    path.write_text(json.dumps(document))
    animation = popupcore.load_trajectories(str(path))
    pruned = popupcore.linkage_chains(animation, popupcore.ChainOptions())
    assert [(c.name, c.bones, c.pruned, c.weight) for c in pruned] == [
        ("hand", [0, 1, 2], ["finger"], 1.0)
    ]
    options = popupcore.ChainOptions()
    options.prune_fraction = 0.0
    options.min_chain_size = 0.0  # the short-chain rule would fold the finger and hand too
    kept = popupcore.linkage_chains(animation, options)
    assert [(c.name, c.parent_chain) for c in kept] == [("arm", -1), ("hand", 0), ("finger", 0)]
    assert [c.weight for c in kept] == pytest.approx([10 / 15.1, 5 / 15.1, 0.1 / 15.1])
