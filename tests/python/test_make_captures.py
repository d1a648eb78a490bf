"""tools/make_captures.py (issue 26 item 6): the capture-like takes as assimp reads them back,
checked against what each take's JSON says and against the closed forms that made it."""

import json
import os
import sys

import numpy as np
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
popupcore = pytest.importorskip("popupcore")
import make_captures  # noqa: E402

SHORT_TAKES = ("walk", "wave", "fingers_only", "gallop")


@pytest.fixture(scope="module")
def takes(tmp_path_factory):
    folder = tmp_path_factory.mktemp("captures")
    out = {}
    for name in SHORT_TAKES:
        path = make_captures.write(name, str(folder))
        with open(path[: -len(".bvh")] + ".json") as f:
            known = json.load(f)
        out[name] = (popupcore.load_animation(path), known)
    return out


def _position(animation, bone, frame):
    names = [b[0] for b in animation.bones]
    return np.asarray(popupcore.forward_kinematics(animation, frame)[names.index(bone)])[:3, 3]


@pytest.mark.parametrize("name", SHORT_TAKES)
def test_every_joint_and_frame_is_read_back(takes, name):
    animation, known = takes[name]
    names = [b[0] for b in animation.bones]
    joints = [n for n in names if not n.startswith("EndSite_")]
    # A humanoid: 4 body, 2 neck and head, 9 face, 2 x (4 arm + 15 finger), 2 x 4 leg bones.
    assert len(joints) == known["bones"] == {"humanoid": 61, "quadruped": 29}[known["skeleton"]]
    assert sorted(joints) == sorted(b for chain in known["chains"].values() for b in chain)
    assert animation.frames == known["frames"] == round(TAKE_SECONDS[name] * 120)
    assert np.diff(animation.frame_times_s)[:5] == pytest.approx([1 / 120] * 5, abs=1e-5)


TAKE_SECONDS = {"walk": 4.0, "wave": 6.0, "fingers_only": 4.0, "gallop": 2.0}


def test_the_walk_travels_forward_at_its_speed(takes):
    animation, known = takes["walk"]
    assert known["root_motion"] is True
    start, end = _position(animation, "Hips", 0), _position(animation, "Hips", animation.frames - 1)
    # 130 cm/s for (frames - 1) / 120 s along +z; the bob and the noise stay within 2 cm.
    assert end[2] - start[2] == pytest.approx(130.0 * (animation.frames - 1) / 120, abs=0.5)
    assert abs(end[0] - start[0]) < 0.5 and abs(end[1] - start[1]) < 2.0


def test_only_the_fingers_move_in_fingers_only(takes):
    animation, known = takes["fingers_only"]
    assert known["root_motion"] is False

    def chord(a, b):
        """How much the distance from bone a to bone b changes over the take."""
        frames = range(0, animation.frames, 12)
        d = [
            np.linalg.norm(_position(animation, a, f) - _position(animation, b, f)) for f in frames
        ]
        return float(np.ptp(d))

    # The elbows keep their angle up to the suit's jitter (0.3°: a millimetre or two from the
    # shoulder to the hand); the fingers curl from 10° to 70° at each of three joints.
    assert chord("LeftArm", "LeftHand") < 0.5 and chord("RightArm", "RightHand") < 0.5
    assert chord("LeftHand", "LeftHandIndex3") > 3.0
    assert chord("RightHand", "RightHandMiddle3") > 3.0


def test_the_long_take_is_4500_frames_round_a_circle():
    text, known = make_captures.build("long_take")
    assert known["frames"] == 4500
    rows = text.split("MOTION\n", 1)[1].splitlines()[2:]
    assert len(rows) == 4500
    root = np.array([[float(v) for v in row.split()[:3]] for row in rows])
    # The root keeps to a circle of 250 cm about (0, z = 250) while it walks (noise 0.05 cm).
    radius = np.hypot(root[:, 0], root[:, 2] - 250.0)
    assert radius == pytest.approx(np.full(4500, 250.0), abs=0.3)


def _euler_zxy(degrees):
    """A BVH joint's rotation from its Zrotation Xrotation Yrotation channels (degrees)."""
    z, x, y = np.radians(degrees)
    c, s = np.cos, np.sin
    rz = np.array([[c(z), -s(z), 0], [s(z), c(z), 0], [0, 0, 1]])
    rx = np.array([[1, 0, 0], [0, c(x), -s(x)], [0, s(x), c(x)]])
    ry = np.array([[c(y), 0, s(y)], [0, 1, 0], [-s(y), 0, c(y)]])
    return rz @ rx @ ry


def test_the_long_take_reads_back_every_frame(tmp_path):
    # The loader makes a long take's frames on several threads from the keys its reading child
    # sends: every frame, the first and last of each share included, is the file's own row.
    path = make_captures.write("long_take", str(tmp_path))
    text, known = make_captures.build("long_take")
    rows = text.split("MOTION\n", 1)[1].splitlines()[2:]
    animation = popupcore.load_animation(path)
    assert animation.frames == known["frames"] == len(rows) == 4500
    # The file says "Frame Time: 0.008333".
    assert np.diff(animation.frame_times_s) == pytest.approx(np.full(4499, 1 / 120), abs=1e-6)
    names = [b[0] for b in animation.bones]
    for frame in (0, 1, 1124, 1125, 2249, 2250, 3374, 3375, 4498, 4499):
        hips = np.asarray(popupcore.forward_kinematics(animation, frame)[names.index("Hips")])
        values = [float(v) for v in rows[frame].split()[:6]]
        assert hips[:3, 3] == pytest.approx(values[:3], abs=1e-4)
        assert hips[:3, :3] == pytest.approx(_euler_zxy(values[3:6]), abs=1e-5)
