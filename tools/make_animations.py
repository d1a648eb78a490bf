#!/usr/bin/python3
"""Test animations for motion from an animation (issue 13 §4), made here with known answers.

    /usr/bin/python3 tools/make_animations.py --out tests/data/animations [NAME ...]

Every file is authored in card millimetres: with the view stored next to it (scale 1, centre =
the centre of the bones' projected bounding box over all frames, the rule of motion_targets) the
file's (x, y) ARE the card's (x, y): y along the central fold, x > 0 the ground page, the viewer
looking down from +z (MotionView's default view and up). Frame 0 is the closed card (s = 0),
the last frame the card open flat (s = 1), θ = 180°·s.

Two families, each BVH written by hand (plain text) with a NAME.json of what is known:

- hand-written trajectories: a hand turning about a shoulder (circle), hands on straight
  vertical, horizontal and diagonal lines, two crossing arms that move alike, two arms that
  conflict, and a character with a body, a head, two arms and two legs;
- synthetic rigs whose hands follow the mechanism library's closed forms (docs/MATH.md,
  "Mechanisms on a base patch pair"): rotation arm, vertical translation, horizontal translation
  and the diagonal translation (a step on a v-fold's wings), alone and all four on one card. The
  JSON holds the mechanism's parameters and the quantities its path determines, so a test can
  check the pipeline recovers them within 1 % of the card.

Arms are two-bone chains posed by planar inverse kinematics (Z rotations only, so the slerp of
forward kinematics between frames is a linear blend of angles); the horizontal line is a root
translation channel. Rotation, vertical and horizontal closed forms are written out here from
docs/MATH.md (tests compare them with popupcore's); the diagonal composes popupcore.v_fold_wings
and popupcore.step_nose, so it needs the built module. Importable: tests call write(name, dir).

The plain trajectory JSON (docs/ANIMATION_INPUT.md) example is `trajectories`.
"""

import argparse
import json
import math
import os
import sys

import numpy as np

FRAMES = 121  # 1.5° of fold per frame: the interpolated path stays within 0.01 mm of the law
FRAME_TIME = 1.0 / 30.0
CARD_WIDTH = 210.0  # mm along the fold (MotionView's default card)
CARD_DEPTH = 148.0  # mm, each page


# ------------------------------------------------------------------ skeleton and BVH writing


class Joint:
    """A BVH joint: offset from its parent, channels, children, an optional end site."""

    def __init__(self, name, offset, channels, children=(), end=None):
        self.name = name
        self.offset = tuple(float(v) for v in offset)
        self.channels = list(channels)
        self.children = list(children)
        self.end = None if end is None else tuple(float(v) for v in end)

    def walk(self):
        yield self
        for child in self.children:
            yield from child.walk()


ROOT_CHANNELS = ["Xposition", "Yposition", "Zposition", "Zrotation", "Xrotation", "Yrotation"]
JOINT_CHANNELS = ["Zrotation", "Xrotation", "Yrotation"]


def _fmt(v):
    text = f"{v:.6f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def bvh_text(root, motion, frames=FRAMES, frame_time=FRAME_TIME):
    """BVH text. motion[name][channel] is a per-frame sequence (missing channels are 0)."""
    lines = ["HIERARCHY"]

    def emit(joint, depth, is_root):
        pad = "\t" * depth
        lines.append(f"{pad}{'ROOT' if is_root else 'JOINT'} {joint.name}")
        lines.append(f"{pad}{{")
        lines.append(f"{pad}\tOFFSET {' '.join(_fmt(v) for v in joint.offset)}")
        lines.append(f"{pad}\tCHANNELS {len(joint.channels)} {' '.join(joint.channels)}")
        for child in joint.children:
            emit(child, depth + 1, False)
        if joint.end is not None:
            lines.append(f"{pad}\tEnd Site")
            lines.append(f"{pad}\t{{")
            lines.append(f"{pad}\t\tOFFSET {' '.join(_fmt(v) for v in joint.end)}")
            lines.append(f"{pad}\t}}")
        lines.append(f"{pad}}}")

    emit(root, 0, True)
    lines += ["MOTION", f"Frames: {frames}", f"Frame Time: {frame_time:.6f}"]
    joints = list(root.walk())
    for f in range(frames):
        row = []
        for joint in joints:
            values = motion.get(joint.name, {})
            for channel in joint.channels:
                series = values.get(channel)
                row.append(_fmt(0.0 if series is None else float(series[f])))
        lines.append(" ".join(row))
    return "\n".join(lines) + "\n"


def _rotation(channel, degrees):
    a = math.radians(degrees)
    c, s = math.cos(a), math.sin(a)
    if channel == "Xrotation":
        return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    if channel == "Yrotation":
        return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def joint_positions(root, motion, frame):
    """{name: world position} at a frame, end sites as NAME_end (BVH semantics: a joint with
    position channels is placed by them instead of its offset; rotations in channel order)."""
    out = {}

    def visit(joint, rotation, origin):
        values = motion.get(joint.name, {})
        offset = np.array(joint.offset)
        if "Xposition" in joint.channels:
            offset = np.array(
                [float(values.get(c, [0.0] * (frame + 1))[frame]) for c in ROOT_CHANNELS[:3]]
            )
        position = origin + rotation @ offset
        local = np.eye(3)
        for channel in joint.channels:
            if channel.endswith("rotation"):
                local = local @ _rotation(
                    channel, float(values.get(channel, [0.0] * (frame + 1))[frame])
                )
        world = rotation @ local
        out[joint.name] = position
        for child in joint.children:
            visit(child, world, position)
        if joint.end is not None:
            out[joint.name + "_end"] = position + world @ np.array(joint.end)

    visit(root, np.eye(3), np.zeros(3))
    return out


def view_for(root, motion, frames=FRAMES):
    """The view that maps the file onto the card unchanged: scale 1, centre = the centre of every
    joint's (x, y) over all frames (motion_targets' bounding box)."""
    points = np.array([p for f in range(frames) for p in joint_positions(root, motion, f).values()])
    lo, hi = points.min(axis=0), points.max(axis=0)
    centre = 0.5 * (lo + hi)
    return {"scale": 1.0, "centre": [float(centre[0]), float(centre[1])]}


# ------------------------------------------------------------------ planar arms


def planar_ik(shoulder, target, upper, fore, bend=1.0):
    """Shoulder and elbow Z angles (degrees, unwrapped over frames) putting the hand of a
    two-bone arm along local +x on each target point. Refuses a target out of reach."""
    shoulder = np.asarray(shoulder, float)
    target = np.asarray(target, float)
    d = target[:, :2] - shoulder[:2]
    dist = np.hypot(d[:, 0], d[:, 1])
    if dist.max() > (upper + fore) * 0.999 or dist.min() < abs(upper - fore) * 1.001 + 1e-9:
        raise ValueError(
            f"planar_ik: reach {dist.min():.3f}..{dist.max():.3f} mm, arm "
            f"{abs(upper - fore):.3f}..{upper + fore:.3f} mm"
        )
    cos2 = (dist**2 - upper**2 - fore**2) / (2 * upper * fore)
    elbow = bend * np.arccos(np.clip(cos2, -1, 1))
    first = np.arctan2(d[:, 1], d[:, 0]) - np.arctan2(
        fore * np.sin(elbow), upper + fore * np.cos(elbow)
    )
    return np.degrees(np.unwrap(first)), np.degrees(np.unwrap(elbow))


def arm(name, shoulder_offset, path, shoulder_world, upper, fore, z=0.0, bend=1.0):
    """A two-bone arm hanging at shoulder_offset from its parent, its hand's end site on `path`
    (N x 2 card points, z fixed). Returns (joint, motion)."""
    target = np.column_stack([path, np.full(len(path), z)])
    first, elbow = planar_ik(shoulder_world, target, upper, fore, bend)
    joint = Joint(
        name,
        shoulder_offset,
        JOINT_CHANNELS,
        [Joint(name + "Fore", (upper, 0, 0), JOINT_CHANNELS, end=(fore, 0, 0))],
    )
    return joint, {name: {"Zrotation": first}, name + "Fore": {"Zrotation": elbow}}


def reach_for(path, shoulder):
    """Equal bone lengths reaching every point of the path from the shoulder with slack."""
    d = np.hypot(*(np.asarray(path)[:, :2] - np.asarray(shoulder)[:2]).T)
    length = 0.5 * d.max() / 0.9
    if d.min() < 0.05 * length:
        raise ValueError("reach_for: the path passes through the shoulder")
    return length


def s_values(frames=FRAMES):
    return np.linspace(0.0, 1.0, frames)


# ------------------------------------------------------------------ mechanism closed forms
# docs/MATH.md, "Mechanisms on a base patch pair"; δ = θ/2 = 90°·s; all on the central fold.


def rotation_tip(p, s):
    """Rotation arm P (x, y): P_x = −h sin δ, P_y = offset + l(l² − w²c² − 2whc²)/(l² + w²c²)."""
    d = 0.5 * math.pi * np.asarray(s)
    l, w, h = p["spine"], p["run"], p["arm"]
    c2 = np.cos(d) ** 2
    return np.column_stack(
        [
            -h * np.sin(d),
            p["offset"] + l * (l * l - w * w * c2 - 2 * w * h * c2) / (l * l + w * w * c2),
        ]
    )


def rotation_off_fold_tip(p, s):
    """Rotation arm on a floating layer's side pair (docs/MATH.md, "A rotation arm on a floating
    layer's side"), hinge = ±support (+: ground side): the side pair opens at φ = θ/2 with its
    hinge at support·g(θ) and bisector U at angle θ/4 from z; in its frame the tip is the
    rotation arm's at φ (e = φ/2 = θ/4): R = l(cos t, sin t), tan(t/2) = w cos e / l,
    P = R + (h/w)(R − S), S = (w sin e, l, w cos e); card = H + P_x·X + P_y·ŷ + P_z·U."""
    theta = math.pi * np.asarray(s)
    d, e = 0.5 * theta, 0.25 * theta
    l, w, h, hinge = p["spine"], p["run"], p["arm"], p["hinge"]
    side, support = math.copysign(1.0, hinge), abs(hinge)
    t = 2 * np.arctan2(w * np.cos(e), l)
    p_x = -h * np.sin(e)
    p_y = l * np.cos(t) + (h / w) * (l * np.cos(t) - l)
    p_z = l * np.sin(t) + (h / w) * (l * np.sin(t) - w * np.cos(e))
    # X = (cos(θ/4), 0, −sin(θ/4)) and U = (sin(θ/4), 0, cos(θ/4)) on the ground side; the
    # backdrop side's frame is the mirror x → −x with its x axis (cos(θ/4), 0, sin(θ/4)).
    x = side * support * np.sin(d) + p_x * np.cos(e) + side * p_z * np.sin(e)
    return np.column_stack([x, p["offset"] + p_y])


def vertical_tip(p, s):
    """Vertical translation's corner: x = 0, y = offset − h sin α cos δ / √(cos²α + sin²α cos²δ)."""
    d = 0.5 * math.pi * np.asarray(s)
    h, a = p["height"], p["wall_angle"]
    y = p["offset"] - h * math.sin(a) * np.cos(d) / np.sqrt(
        math.cos(a) ** 2 + math.sin(a) ** 2 * np.cos(d) ** 2
    )
    return np.column_stack([np.zeros_like(d), y])


def horizontal_tip(p, s):
    """Horizontal translation's far end, mid-width: x = r(a − b) sin δ / √(a² + b² + 2ab cos θ)."""
    theta = math.pi * np.asarray(s)
    a, b, r = p["run_ground"], p["run_backdrop"], p["reach"]
    x = r * (a - b) * np.sin(0.5 * theta) / np.sqrt(a * a + b * b + 2 * a * b * np.cos(theta))
    return np.column_stack([x, np.full_like(x, p["offset"] + 0.5 * p["width"])])


def diagonal_tip(p, s):
    """Step nose on a vertical-spine v-fold's wings (popupcore.v_fold_wings + step_nose), at the
    middle of the step's width along the spine (the carried patch's middle, as for the
    horizontal translation): the composition of docs/MATH.md, Diagonal translation."""
    import popupcore

    v = popupcore.VFoldParams()
    for key in ("offset", "run", "hinge_angle", "spine", "spine_angle"):
        setattr(v, key, p["v_fold"][key])
    step = popupcore.StepFoldParams()
    for key in ("offset", "width", "run_ground", "run_backdrop"):
        setattr(step, key, p["step_fold"][key])
    out = []
    for value in np.asarray(s):
        wings = popupcore.v_fold_wings(v, math.pi, math.pi * float(value))
        nose = popupcore.step_nose(step, wings.opening)
        axis, up = np.array(wings.axis), np.array(wings.up)
        point = (
            np.array(wings.origin)
            + nose[0] * np.cross(axis, up)
            + (step.offset + 0.5 * step.width) * axis
            + nose[1] * up
        )
        out.append(point[:2])
    return np.array(out)


TIPS = {
    "rotation_arm": rotation_tip,
    "rotation_off_fold": rotation_off_fold_tip,
    "vertical_translation": vertical_tip,
    "horizontal_translation": horizontal_tip,
    "diagonal": diagonal_tip,
}

# The mechanisms of the synthetic rigs, in card mm and radians (each valid on the A4 card alone
# and all four together: tests/python/test_motion_pipeline.py builds them with popupcore).
MECHANISMS = {
    "rotation": {
        "mapping": "rotation",
        "type": "rotation_arm",
        "params": {"offset": 168.0, "spine": 40.0, "run": 22.0, "arm": 32.0},
    },
    # popupcore's motion rotation with hinge != 0: a floating layer from `offset`, as wide as
    # the spine, supports |hinge| from the fold, carrying the arm on its ground side pair.
    "rotation_off_fold": {
        "mapping": "rotation",
        "type": "rotation_off_fold",
        "params": {"offset": 150.0, "spine": 40.0, "run": 22.0, "arm": 30.0, "hinge": 30.0},
    },
    "vertical": {
        "mapping": "vertical",
        "type": "vertical_translation",
        "params": {"offset": 106.0, "side": 25.0, "height": 35.0, "wall_angle": math.radians(35.0)},
    },
    "horizontal": {
        "mapping": "horizontal",
        "type": "horizontal_translation",
        "params": {
            "offset": 150.0,
            "width": 14.0,
            "run_ground": 40.0,
            "run_backdrop": 15.0,
            "reach": 70.0,
        },
    },
    "diagonal": {
        "mapping": "diagonal",
        "type": "diagonal",
        "params": {
            "v_fold": {
                "offset": 40.0,
                "run": 60.0,
                "hinge_angle": math.radians(45.0),
                "spine": 55.0,
                "spine_angle": math.radians(90.0),
            },
            # Every glued crease at least the sheets' shortest tab (11.1 mm): the design the
            # pipeline may return (popupcore's motion mechanisms refuse shorter ones).
            "step_fold": {"offset": 6.0, "width": 12.0, "run_ground": 30.0, "run_backdrop": 12.0},
        },
    },
}


def identifiable(kind, p):
    """What the path of each mechanism determines (docs/MATH.md): a fit cannot be asked for more.
    Rotation: P_x = −h sin δ gives h; P_y(open) = offset + l; P_y − P_y(open) = −A u/(B + u)
    with u = cos²δ, A = 2l(w + h)/w, B = l²/w² gives l and w. Vertical: offset (open) and the
    travel h sin α; α from the shape. Horizontal: reach r (open), the far edge's y, and only
    k = 4ab/(a − b)² of the runs (P_x = r sin δ / √(1 + k cos²δ)). Diagonal: the nose's two end
    points (the path of two nested mechanisms has more parameters than its shape fixes)."""
    if kind == "rotation_arm":
        return {"arm": p["arm"], "spine": p["spine"], "run": p["run"], "offset": p["offset"]}
    if kind == "rotation_off_fold":
        # Sliding the arm's vertex O along its hinge O-S (a homothety about S) keeps the tip's
        # (x, y) (docs/MATH.md): the path fixes S along the fold, the tip's reach from S and, on
        # the ground side, S across the fold (|hinge| + run). The hinge's direction spine/run is
        # pinned only weakly (the pipeline's 1.996 for 1.818 costs 0.15 mm RMS on this rig).
        return {
            "s_along": p["offset"] + p["spine"],
            "reach": p["run"] + p["arm"],
            "s_across": abs(p["hinge"]) + p["run"],
        }
    if kind == "vertical_translation":
        return {
            "offset": p["offset"],
            "travel": p["height"] * math.sin(p["wall_angle"]),
            "height": p["height"],
            "wall_angle": p["wall_angle"],
        }
    if kind == "horizontal_translation":
        a, b = p["run_ground"], p["run_backdrop"]
        return {
            "reach": p["reach"],
            "y": p["offset"] + 0.5 * p["width"],
            "k": 4 * a * b / (a - b) ** 2,
        }
    ends = diagonal_tip(p, [0.0, 1.0])
    return {"closed": ends[0].tolist(), "open": ends[1].tolist()}


# ------------------------------------------------------------------ the animations


def _arm_rotation():
    """Hand on a circle: shoulder at (-40, 110) turning 0° → 90°, radius 40 (closed → open): it
    starts on the fold and swings onto the backdrop page, where a rotation arm moves."""
    s = s_values()
    centre, radius = (-40.0, 110.0), 40.0
    angle = 90.0 * s
    root = Joint("Shoulder", (0, 0, 0), ROOT_CHANNELS, end=(radius, 0, 0))
    motion = {
        "Shoulder": {
            "Xposition": np.full_like(s, centre[0]),
            "Yposition": np.full_like(s, centre[1]),
            "Zposition": np.zeros_like(s),
            "Zrotation": angle,
        }
    }
    known = {
        "Shoulder": {
            "kind": "circle",
            "centre": list(centre),
            "radius": radius,
            "degrees": [0.0, 90.0],
            "mapping": "rotation",
        }
    }
    return root, motion, known


def _line(start, end, s):
    start, end = np.asarray(start, float), np.asarray(end, float)
    return start + np.outer(s, end - start)


def _line_arm(name, start, end, shoulder, mapping):
    s = s_values()
    path = _line(start, end, s)
    length = reach_for(path, shoulder)
    limb, motion = arm("Arm", (0, 0, 0), path, (*shoulder, 0.0), length, length)
    root = Joint("Shoulder", (0, 0, 0), ROOT_CHANNELS, [limb.children[0]])
    motion = {
        "Shoulder": {
            "Xposition": np.full_like(s, shoulder[0]),
            "Yposition": np.full_like(s, shoulder[1]),
            "Zposition": np.zeros_like(s),
            "Zrotation": motion["Arm"]["Zrotation"],
        },
        "ArmFore": motion["ArmFore"],
    }
    known = {
        "ArmFore": {"kind": "line", "start": list(start), "end": list(end), "mapping": mapping}
    }
    return root, motion, known


def _line_vertical():
    """Hand up the central fold, (0, 60) → (0, 100), by shoulder and elbow rotations."""
    return _line_arm("line_vertical", (0.0, 60.0), (0.0, 100.0), (-70.0, 70.0), "vertical")


def _line_diagonal():
    """Hand from (0, 90) to (-24, 104), by shoulder and elbow rotations."""
    return _line_arm("line_diagonal", (0.0, 90.0), (-24.0, 104.0), (-80.0, 60.0), "diagonal")


def _line_horizontal():
    """Hand along x at y = 100 from the fold (0) to 60 mm out on the ground, by the root's
    translation channel (a bone 30 mm long hanging down from it)."""
    s = s_values()
    root = Joint("Slider", (0, 0, 0), ROOT_CHANNELS, end=(0, 30, 0))
    motion = {
        "Slider": {
            "Xposition": 60.0 * s,
            "Yposition": np.full_like(s, 70.0),
            "Zposition": np.zeros_like(s),
        }
    }
    known = {
        "Slider": {
            "kind": "line",
            "start": [0.0, 100.0],
            "end": [60.0, 100.0],
            "mapping": "horizontal",
        }
    }
    return root, motion, known


def _two_arms(paths, shoulders, known_kind):
    """A body at (0, 20) with two arms whose hands follow `paths` (name -> N x 2)."""
    s = s_values()
    body = (0.0, 20.0)
    children, motion = [], {
        "Body": {
            "Xposition": np.full_like(s, body[0]),
            "Yposition": np.full_like(s, body[1]),
            "Zposition": np.zeros_like(s),
        }
    }
    for (name, path), shoulder, z in zip(paths.items(), shoulders, (6.0, 12.0)):
        length = reach_for(path, shoulder)
        offset = (shoulder[0] - body[0], shoulder[1] - body[1], z)
        joint, m = arm(name, offset, path, (*shoulder, z), length, length)
        children.append(joint)
        motion.update(m)
    root = Joint("Body", (0, 0, 0), ROOT_CHANNELS, children, end=(0, 20, 0))
    known = {name + "Fore": known_kind(name) for name in paths}
    return root, motion, known


def _crossing_alike():
    """Left and right arms cross in front of the body; both hands rise along the fold side by side
    (x = ∓4, y 70 → 110) in step: mechanisms that would collide and move alike (to merge)."""
    s = s_values()
    paths = {
        "LeftArm": _line((4.0, 70.0), (4.0, 110.0), s),
        "RightArm": _line((-4.0, 70.0), (-4.0, 110.0), s),
    }
    # The left shoulder is on the character's left (card −x) and reaches to +x: the arms cross.
    root, motion, known = _two_arms(
        paths,
        [(-40.0, 40.0), (40.0, 40.0)],
        lambda n: {"kind": "line", "mapping": "vertical", "group": "alike"},
    )
    known["LeftArmFore"].update(start=[4.0, 70.0], end=[4.0, 110.0])
    known["RightArmFore"].update(start=[-4.0, 70.0], end=[-4.0, 110.0])
    return root, motion, known


def _conflicting():
    """Both hands leave the same point of the fold (0, 85) in opposite directions, one to x = −60
    and one to x = +60: whatever carries them stands on the same stretch of the fold, and the
    motions differ (one must stay). (A hand rising along the fold beside one sweeping across it,
    the first version, was resolved by a tall v-box passing over the extruding patch.)"""
    s = s_values()
    paths = {
        "LeftArm": _line((0.0, 85.0), (-60.0, 85.0), s),
        "RightArm": _line((0.0, 85.0), (60.0, 85.0), s),
    }
    root, motion, known = _two_arms(
        paths, [(-50.0, 50.0), (50.0, 50.0)], lambda n: {"kind": "line", "group": "conflict"}
    )
    known["LeftArmFore"].update(start=[0.0, 85.0], end=[-60.0, 85.0], mapping="horizontal")
    known["RightArmFore"].update(start=[0.0, 85.0], end=[60.0, 85.0], mapping="horizontal")
    return root, motion, known


def _character():
    """A standing figure: hips at (0, 70), spine to the chest (0, 120), head above; the right arm
    (card −x) waves about the shoulder, the left hand rises beside the body, the legs swing out
    and back. Five chains move or stay: Spine (to the chest), Head, two arms, two legs."""
    s = s_values()
    hips, chest = np.array([0.0, 70.0]), np.array([0.0, 120.0])
    wave = 150.0 + 60.0 * s  # the right forearm's angle in the card plane (degrees)
    motion = {
        "Hips": {
            "Xposition": np.full_like(s, hips[0]),
            "Yposition": np.full_like(s, hips[1]),
            "Zposition": np.zeros_like(s),
        },
        "Spine": {},
        "Neck": {},
        "RightArm": {"Zrotation": np.full_like(s, 180.0)},
        "RightFore": {"Zrotation": wave - 180.0},
        "LeftArm": {"Zrotation": -60.0 + 100.0 * s},
        "LeftFore": {"Zrotation": 30.0 - 30.0 * s},
        "RightLeg": {"Zrotation": -90.0 - 20.0 * s},
        "RightShin": {"Zrotation": 10.0 * s},
        "LeftLeg": {"Zrotation": -90.0 + 25.0 * s},
        "LeftShin": {"Zrotation": -10.0 * s},
    }
    root = Joint(
        "Hips",
        (0, 0, 0),
        ROOT_CHANNELS,
        [
            Joint(
                "Spine",
                (0, 10, 0),
                JOINT_CHANNELS,
                [
                    Joint("Neck", (0, 40, 0), JOINT_CHANNELS, [], end=(0, 30, 0)),
                    Joint(
                        "RightArm",
                        (-15, 35, 4),
                        JOINT_CHANNELS,
                        [Joint("RightFore", (30, 0, 0), JOINT_CHANNELS, end=(30, 0, 0))],
                    ),
                    Joint(
                        "LeftArm",
                        (15, 35, 4),
                        JOINT_CHANNELS,
                        [Joint("LeftFore", (30, 0, 0), JOINT_CHANNELS, end=(28, 0, 0))],
                    ),
                ],
            ),
            Joint(
                "RightLeg",
                (-10, 0, 2),
                JOINT_CHANNELS,
                [Joint("RightShin", (30, 0, 0), JOINT_CHANNELS, end=(30, 0, 0))],
            ),
            Joint(
                "LeftLeg",
                (10, 0, 2),
                JOINT_CHANNELS,
                [Joint("LeftShin", (30, 0, 0), JOINT_CHANNELS, end=(30, 0, 0))],
            ),
        ],
    )
    known = {"Neck_end": {"kind": "still"}}
    return root, motion, known


def carried_height(mech):
    """H of eq 6.7 for a known mechanism on A4 (h_max = 25 mm): the v-box's height, the diagonal
    nose's height on its standing spine (step offset + width/2), 0 for the flat rotation arm and
    extruding patch (which eq 6.5 does not charge)."""
    p = mech["params"]
    if mech["type"] == "vertical_translation":
        return min(1.0, p["height"] / 25.0)
    if mech["type"] == "diagonal":
        return min(1.0, (p["step_fold"]["offset"] + p["step_fold"]["width"] / 2) / 25.0)
    return 0.0


def _synthetic(names):
    """Hands driven by the closed forms of MECHANISMS[names], all on one body at (-100, 190)."""
    s = s_values()
    body = np.array([-110.0, 195.0])
    children, motion = [], {
        "Body": {
            "Xposition": np.full_like(s, body[0]),
            "Yposition": np.full_like(s, body[1]),
            "Zposition": np.zeros_like(s),
        }
    }
    known = {}
    for index, name in enumerate(names):
        mech = MECHANISMS[name]
        path = TIPS[mech["type"]](mech["params"], s)
        # Shoulder beside the path's chord, on the backdrop side away from the fold's mechanisms.
        mid = 0.5 * (path.min(axis=0) + path.max(axis=0))
        shoulder = np.array([mid[0] - 45.0, mid[1] - 12.0])
        length = reach_for(path, shoulder)
        # Depth: with several chains eq 6.5 charges |D − H| (D = the chain's depth over the
        # character's range, the body at 0; H = the carrying patch's height over h_max = 25 mm),
        # so each arm stands where its mechanism's carried patch does and the known design is the
        # cheapest (docs/DESIGN.md, "Tight collision volumes"). One chain has no depth term.
        z = 4.0 + 4.0 * index if len(names) == 1 else 16.0 * carried_height(mech)
        offset = (shoulder[0] - body[0], shoulder[1] - body[1], z)
        joint_name = name.capitalize() + "Arm"
        joint, m = arm(joint_name, offset, path, (*shoulder, z), length, length)
        children.append(joint)
        motion.update(m)
        known[joint_name + "Fore"] = {
            "kind": "mechanism",
            "mapping": mech["mapping"],
            "type": mech["type"],
            "params": mech["params"],
            "identifiable": identifiable(mech["type"], mech["params"]),
        }
    if len(names) == 1:  # one chain: the shoulder is the root, no body chain
        only = children[0]
        root = Joint(only.name, (0, 0, 0), ROOT_CHANNELS, only.children)
        motion[only.name].update(
            Xposition=np.full_like(s, body[0] + only.offset[0]),
            Yposition=np.full_like(s, body[1] + only.offset[1]),
            Zposition=np.full_like(s, only.offset[2]),
        )
        return root, motion, known
    return Joint("Body", (0, 0, 0), ROOT_CHANNELS, children, end=(0, 10, 0)), motion, known


ANIMATIONS = {
    "arm_rotation": (_arm_rotation, "a hand turning 90° about the shoulder, radius 40 mm"),
    "line_vertical": (_line_vertical, "a hand rising 40 mm along the central fold (rotations)"),
    "line_horizontal": (
        _line_horizontal,
        "a hand sliding 60 mm out across the fold (root channel)",
    ),
    "line_diagonal": (_line_diagonal, "a hand moving on a straight diagonal (rotations)"),
    "crossing_alike": (_crossing_alike, "two crossing arms whose hands rise side by side"),
    "conflicting_arms": (
        _conflicting,
        "two hands leaving one point of the fold in opposite directions",
    ),
    "character": (_character, "body, head, two arms, two legs (six chains)"),
    "rig_rotation": (lambda: _synthetic(["rotation"]), "hand on a rotation arm's closed form"),
    "rig_rotation_off_fold": (
        lambda: _synthetic(["rotation_off_fold"]),
        "hand on the closed form of a rotation arm on a floating layer's side",
    ),
    "rig_vertical": (
        lambda: _synthetic(["vertical"]),
        "hand on a vertical translation's closed form",
    ),
    "rig_horizontal": (lambda: _synthetic(["horizontal"]), "hand on a horizontal translation's"),
    "rig_diagonal": (lambda: _synthetic(["diagonal"]), "hand on a diagonal translation's"),
    "rig_four": (
        lambda: _synthetic(["rotation", "vertical", "horizontal", "diagonal"]),
        "four arms on the four mechanisms' closed forms",
    ),
}


def known_path(entry, s):
    """The known (x, y) card path of one entry of NAME.json's "known" at parameters s."""
    s = np.asarray(s, float)
    if entry["kind"] == "circle":
        a = np.radians(entry["degrees"][0] + (entry["degrees"][1] - entry["degrees"][0]) * s)
        c = np.asarray(entry["centre"])
        return c + entry["radius"] * np.column_stack([np.cos(a), np.sin(a)])
    if entry["kind"] == "line":
        return _line(entry["start"], entry["end"], s)
    if entry["kind"] == "mechanism":
        return TIPS[entry["type"]](entry["params"], s)
    raise ValueError(f"known_path: no closed path for kind {entry['kind']!r}")


def _jsonable(value):
    if isinstance(value, dict):
        return {k: _jsonable(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_jsonable(v) for v in value]
    if isinstance(value, (np.floating, float)):
        return float(value)
    return value


def build(name):
    """(bvh text, metadata dict) of one animation."""
    make, what = ANIMATIONS[name]
    root, motion, known = make()
    text = bvh_text(root, motion)
    positions = [joint_positions(root, motion, f) for f in range(FRAMES)]
    # Every known path must be what the file says at every frame.
    for bone, entry in known.items():
        if entry["kind"] == "still":
            continue
        end = bone + "_end" if bone + "_end" in positions[0] else bone
        got = np.array([p[end][:2] for p in positions])
        want = known_path(entry, s_values())
        if np.abs(got - want).max() > 1e-4:
            raise AssertionError(f"{name}: {bone} strays {np.abs(got - want).max():.2e} mm")
    meta = {
        "file": name + ".bvh",
        "description": what,
        "frames": FRAMES,
        "frame_time_s": FRAME_TIME,
        "view": view_for(root, motion),
        "card": {"width": CARD_WIDTH, "depth": CARD_DEPTH},
        "known": known,
    }
    return text, _jsonable(meta)


def write(name, out_dir):
    """Writes NAME.bvh and NAME.json into out_dir; returns the BVH's path."""
    if name == "trajectories":
        return write_trajectories(out_dir)
    text, meta = build(name)
    os.makedirs(out_dir, exist_ok=True)
    path = os.path.join(out_dir, name + ".bvh")
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    with open(os.path.join(out_dir, name + ".json"), "w", encoding="utf-8") as f:
        json.dump(meta, f, indent=1, sort_keys=True)
        f.write("\n")
    return path


def trajectories_document(frames=31):
    """The plain trajectory JSON (docs/ANIMATION_INPUT.md): a waving hand on a fixed shoulder,
    a foot stepping out from a moving hip, and a head hanging from the hip (parent)."""
    s = np.linspace(0.0, 1.0, frames)
    angle = np.radians(30.0 + 90.0 * s)
    hand = np.column_stack(
        [-20 + 60 * np.cos(angle), 110 + 60 * np.sin(angle), np.full(frames, 5.0)]
    )
    hip = np.column_stack([np.zeros(frames), 60 + 5 * s, np.zeros(frames)])
    foot = np.column_stack([40 * s, 20 + 5 * s])
    head = hip + np.array([0.0, 70.0, 0.0])
    r = lambda a: [[round(float(v), 6) for v in row] for row in a]  # noqa: E731
    return {
        "format": "popup-trajectories",
        "version": 1,
        "frame_rate": 30,
        "effectors": [
            {"name": "hand", "root": [-20.0, 110.0, 5.0], "points": r(hand)},
            {"name": "hip", "root": [0.0, 0.0, 0.0], "points": r(hip)},
            {"name": "foot", "root": r(hip[:, :2]), "points": r(foot)},
            {"name": "head", "parent": "hip", "points": r(head)},
        ],
    }


def write_trajectories(out_dir):
    os.makedirs(out_dir, exist_ok=True)
    path = os.path.join(out_dir, "trajectories.json")
    with open(path, "w", encoding="utf-8") as f:
        json.dump(trajectories_document(), f, indent=1)
        f.write("\n")
    return path


NAMES = list(ANIMATIONS) + ["trajectories"]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", required=True)
    parser.add_argument("names", nargs="*", help=f"default: all of {', '.join(NAMES)}")
    args = parser.parse_args(argv)
    for name in args.names or NAMES:
        if name not in NAMES:
            parser.error(f"unknown animation {name!r} (known: {', '.join(NAMES)})")
        print(write(name, args.out))


if __name__ == "__main__":
    sys.exit(main())
