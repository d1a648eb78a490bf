"""The capture-like takes WITH a skinned mesh (issue 26 item 6), made in Blender by
tools/blender_capture.py and committed (tests/data/animations/capture_*.glb): read back through
popupcore and designed by `popup animate`, checked against each take's JSON, which Blender wrote
independently of PopUp. Blender is not needed here."""

import json
import os
import subprocess

import numpy as np
import pytest

popupcore = pytest.importorskip("popupcore")

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "data", "animations")
BUILD = os.environ.get("POPUP_BUILD_DIR", os.path.join(HERE, "..", "..", "build"))
POPUP = os.path.join(BUILD, "bin", "popup")
TAKES = ("walk", "wave")
FINGER_OR_FACE = ("Thumb", "Index", "Middle", "Ring", "Pinky", "Eye", "Brow", "Lip", "Jaw")
ARMATURE = "Capture"  # Blender's armature object: the .glb's node above the suit's Hips


def _path(name, ext):
    return os.path.join(DATA, f"capture_{name}.{ext}")


@pytest.fixture(scope="module")
def takes():
    out = {}
    for name in TAKES:
        with open(_path(name, "json")) as f:
            known = json.load(f)
        out[name] = (popupcore.load_animation(_path(name, "glb")), known)
    return out


def _chains(animation, prune_fraction=0.09, min_chain_size=0.15):
    options = popupcore.ChainOptions()
    options.prune_fraction = prune_fraction
    options.min_chain_size = min_chain_size
    return popupcore.linkage_chains(animation, options)


def _named(known, bone):
    """The chain a person would name that holds `bone`."""
    return next(name for name, bones in known["chains"].items() if bone in bones)


@pytest.mark.parametrize("name", TAKES)
def test_the_skinned_mesh_and_every_joint_and_frame_are_read(takes, name):
    animation, known = takes[name]
    assert len(animation.mesh.vertices) == known["mesh_vertices"] == 2946
    assert len(animation.mesh.triangles) > known["mesh_vertices"]
    names = [b[0] for b in animation.bones]
    assert names[0] == ARMATURE and len(names) == known["bones"] + 1 == 62
    assert sorted(names[1:]) == sorted(b for bones in known["chains"].values() for b in bones)
    assert animation.frames == known["frames"]
    assert np.diff(animation.frame_times_s) == pytest.approx(
        [1 / known["fps"]] * (known["frames"] - 1), abs=1e-6
    )
    assert os.path.getsize(_path(name, "glb")) < 400_000


@pytest.mark.parametrize("name", TAKES)
def test_the_pose_is_blenders(takes, name):
    animation, known = takes[name]
    names = [b[0] for b in animation.bones]
    for bone, heads in known["tracked_heads"].items():
        for i, head in enumerate(heads):
            pose = popupcore.forward_kinematics(animation, i * known["tracked_every"])
            # Blender's posed bone heads, in metres: assimp's floats agree within a micrometre.
            assert np.asarray(pose[names.index(bone)])[:3, 3] == pytest.approx(head, abs=1e-5)


def test_the_walk_travels_forward_and_the_wave_stands(takes):
    for name, travelled in (("walk", True), ("wave", False)):
        animation, known = takes[name]
        hips = [b[0] for b in animation.bones].index("Hips")
        first, last = (
            np.asarray(popupcore.forward_kinematics(animation, f)[hips])[:3, 3]
            for f in (0, animation.frames - 1)
        )
        assert last - first == pytest.approx(known["root_travel_m"], abs=1e-5)
        assert known["root_motion"] is travelled
    # 1.3 m/s for 179 frames at 60 fps along +z; the bob and the jitter stay within 3 cm.
    assert takes["walk"][1]["root_travel_m"][2] == pytest.approx(1.3 * 179 / 60, abs=0.03)


@pytest.mark.parametrize("name", TAKES)
def test_the_chains_are_the_ones_a_person_names(takes, name):
    animation, known = takes[name]
    chains = _chains(animation)
    names = [c.name for c in chains]
    assert not [n for n in names if any(word in n for word in FINGER_OR_FACE)]
    # Body (hips, then the chest where the arms and neck branch), head, two arms, two legs.
    assert names == ["Hips", "Spine2", "Head", "LeftHand", "RightHand"] + [
        "LeftToeBase",
        "RightToeBase",
    ]
    assert sorted({_named(known, n) for n in names}) == sorted(known["chains"])


@pytest.mark.parametrize("name", TAKES)
def test_the_face_bones_go_by_their_few_vertices_and_the_fingers_by_their_size(takes, name):
    animation, known = takes[name]
    counts = known["vertices_per_bone"]
    # Thesis τp: 0.09 of the mean skinned vertices per bone (the armature's node counts as one).
    threshold = 0.09 * known["mesh_vertices"] / len(animation.bones)
    assert all(counts[b] < threshold for b in known["face_bones"])
    fingers = {b[:-1] for b in known["finger_bones"]}
    assert all(sum(counts[f + k] for k in "123") > threshold for f in fingers)

    # Nothing pruned: every face bone and finger is its own chain, holding the vertices Blender
    # gave it (PopUp counts each vertex for its largest weight, as the JSON does).
    every = {c.name: c for c in _chains(animation, prune_fraction=0.0, min_chain_size=0.0)}
    assert set(known["face_bones"]) <= set(every)
    for bone in known["face_bones"]:
        assert len(every[bone].vertices) == counts[bone]
    for finger in fingers:
        assert len(every[finger + "3"].vertices) == sum(counts[finger + k] for k in "123")

    # τp alone (no short-chain rule): the face bones are gone into the head, the fingers stay.
    by_vertices = {c.name: c for c in _chains(animation, min_chain_size=0.0)}
    assert not set(known["face_bones"]) & set(by_vertices)
    assert sorted(by_vertices["Head"].pruned) == sorted(known["face_bones"])
    assert {f + "3" for f in fingers} <= set(by_vertices)
    # The short-chain rule then folds the fingers into the arms.
    hands = {c.name: c for c in _chains(animation)}
    for side in ("Left", "Right"):
        tips = {f + "3" for f in fingers if f.startswith(side)}
        assert len(tips) == 5 and tips <= set(hands[f"{side}Hand"].pruned)


# What `popup animate` made of each take (seed 1, --view from the JSON), as measured when the
# takes were made: the chains animated and the weighted motion error (docs/CORPUS.md).
MEASURED = {"walk": (["LeftHand"], 0.0739), "wave": (["RightHand"], 0.0476)}


@pytest.fixture(scope="module")
def designs(takes, tmp_path_factory):
    out = {}
    for name in TAKES:
        known = takes[name][1]
        folder = tmp_path_factory.mktemp(name)
        view = ",".join(f"{v:g}" for v in known["view"])
        run = subprocess.run(
            [POPUP, "animate", _path(name, "glb"), "--out", str(folder), f"--view={view}"],
            capture_output=True,
            text=True,
            timeout=300,
        )
        assert run.returncode == 0, run.stderr[-2000:]
        with open(folder / "report.json") as f:
            out[name] = (json.load(f), run.stderr, folder)
    return out


@pytest.mark.parametrize("name", TAKES)
def test_popup_animate_designs_a_valid_card_from_it(designs, name):
    report, stderr, folder = designs[name]
    assert f"capture_{name}.glb: 62 bones" in stderr and "a mesh of 2946 vertices" in stderr
    assert report["valid"] and report["sheets_ok"]
    for written in ("design.FCStd", "motion.gif", "paths.png", "sheets/sheets.pdf"):
        assert (folder / written).is_file()
    names = [c["name"] for c in report["chains"]]
    assert len(names) == 7 and not [n for n in names if any(w in n for w in FINGER_OR_FACE)]
    animated, error = MEASURED[name]
    assert [c["name"] for c in report["chains"] if c["status"] == "animated"] == animated
    assert report["weighted_error"] == pytest.approx(error, abs=0.005)
    assert report["weighted_floor"] <= report["weighted_error"]


def test_the_walk_is_kept_in_place(designs, takes):
    """The travel taken out is the hips' over the frames shown, as Blender moved them: at a
    steady pace, root_travel_m over the whole take times the share of it shown, on the card's
    scale (the armature node above the hips, at the file's origin, stands still and is not
    what travels)."""
    report = designs["walk"][0]
    known = takes["walk"][1]
    targets = report["targets"]
    scale = np.linalg.norm(np.asarray(targets["animation_to_card"])[:3, 0])
    shown = (targets["last_frame"] - targets["first_frame"]) / (known["frames"] - 1)
    expected = np.linalg.norm(known["root_travel_m"]) * shown * scale
    assert targets["travel_removed_mm"] == pytest.approx(expected, rel=0.02)


def test_the_movie_draws_no_bone_from_the_armature_node(takes):
    """motion.gif's character half draws the character's bones only: the .glb's still armature
    node (bone 0, at the file's origin) is above the character (character_root is the Hips), so
    the 61 joints under it give 60 segments, none from the node."""
    from popupwb.motion.motion_movie import character_frames

    animation, known = takes["walk"]
    names = [name for name, _ in animation.bones]
    assert popupcore.character_root(animation) == names.index("Hips") == 1
    matrix = np.eye(4)
    for _, segments, _ in character_frames(animation, matrix, 0, known["frames"] - 1, count=3):
        assert len(segments) == len(names) - 2
        node = np.asarray(popupcore.forward_kinematics(animation, 0)[0])[:3, 3]
        assert min(np.linalg.norm(a - node) for a, _ in segments) > 1e-3  # the node is no end
