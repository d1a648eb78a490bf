#!/usr/bin/python3
"""Capture-like test animations for motion from a real capture (issue 26 item 6), made here.

    /usr/bin/python3 tools/make_captures.py --out DIR [NAME ...]

What motion-capture files have that tools/make_animations.py's clean rigs do not: a skeleton of
a mocap suit (centimetres, y up, the character facing +z, a six-channel root and three rotation
channels on every joint, ZXY order), full hands (five fingers of three bones each), a face rig
(jaw, eyes, eyelids, brows, lips), toes, a little noise on every channel, 120 frames a second,
root motion, and takes much longer than one gesture. Each NAME.bvh comes with NAME.json: what a
person would name in it (the chains, the bones each holds) and which of them move, for the tests
and the results table to check against:

- `walk`: a walk cycle, arms swinging against the legs, walking forward (root motion), blinks;
- `wave`: standing, the right hand waves above the head, the left arm rises a little;
- `fingers_only`: the body still, only the fingers curl and open;
- `long_take`: 4,500 frames (37.5 s): walking round a circle, stopping to wave, walking again;
- `gallop`: a quadruped (spine, neck, head with jaw and ears, tail, four legs with toes)
  galloping forward.

Every angle is a closed form of time, so a file can be remade bit for bit; the noise is seeded.
"""

import argparse
import json
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_animations import JOINT_CHANNELS, ROOT_CHANNELS, Joint, bvh_text  # noqa: E402

FPS = 120
NOISE_DEGREES = 0.3  # a suit's jitter on every rotation channel
FINGERS = ("Thumb", "Index", "Middle", "Ring", "Pinky")
FACE = ("Jaw", "LeftEye", "RightEye", "LeftEyelid", "RightEyelid", "LeftBrow", "RightBrow")
LIPS = ("UpperLip", "LowerLip")


# ------------------------------------------------------------------ skeletons


def _joint(name, offset, children=(), end=None):
    return Joint(name, offset, JOINT_CHANNELS, children, end)


def _chain(names, offsets, end):
    """Joints one under the other: names[0] holds names[1] ... the last ends at `end`."""
    joint = _joint(names[-1], offsets[-1], end=end)
    for name, offset in zip(reversed(names[:-1]), reversed(offsets[:-1])):
        joint = _joint(name, offset, [joint])
    return joint


def _hand(side, sign):
    """A hand in T-pose along sign·x with five fingers of three bones each."""
    fingers = []
    bases = {"Thumb": (2, 0, 3), "Index": (9, 0, 2.4), "Middle": (9.5, 0, 0.8)}
    bases.update({"Ring": (9, 0, -0.8), "Pinky": (8, 0, -2.4)})
    for finger in FINGERS:
        bx, by, bz = bases[finger]
        length = 3.0 if finger == "Thumb" else {"Pinky": 2.2, "Middle": 3.6}.get(finger, 3.2)
        names = [f"{side}Hand{finger}{k}" for k in (1, 2, 3)]
        offsets = [(sign * bx, by, bz), (sign * length, 0, 0), (sign * 0.8 * length, 0, 0)]
        fingers.append(_chain(names, offsets, (sign * 0.7 * length, 0, 0)))
    return _joint(f"{side}Hand", (sign * 25, 0, 0), fingers)


def _arm(side, sign):
    forearm = _joint(f"{side}ForeArm", (sign * 28, 0, 0), [_hand(side, sign)])
    upper = _joint(f"{side}Arm", (sign * 14, 0, 0), [forearm])
    return _joint(f"{side}Shoulder", (sign * 4, 10, 0), [upper])


def _leg(side, sign):
    names = [f"{side}UpLeg", f"{side}Leg", f"{side}Foot", f"{side}ToeBase"]
    offsets = [(sign * 9, -5, 0), (0, -42, 0), (0, -42, 0), (0, -6, 13)]
    return _chain(names, offsets, (0, 0, 6))


def _face():
    """The face's bones under the head: short, each its own end."""
    places = {
        "Jaw": ((0, -3, 4), (0, -5, 5)),
        "LeftEye": ((3, 6, 8), (0, 0, 1)),
        "RightEye": ((-3, 6, 8), (0, 0, 1)),
        "LeftEyelid": ((3, 7.5, 8.5), (0, 0, 1)),
        "RightEyelid": ((-3, 7.5, 8.5), (0, 0, 1)),
        "LeftBrow": ((3, 9, 9), (1.5, 0, 0)),
        "RightBrow": ((-3, 9, 9), (-1.5, 0, 0)),
        "UpperLip": ((0, 1, 10), (0, 0, 0.8)),
        "LowerLip": ((0, -1, 10), (0, 0, 0.8)),
    }
    return [_joint(name, offset, end=end) for name, (offset, end) in places.items()]


def humanoid():
    """A mocap suit's skeleton, 180 cm tall, arms in T-pose along ±x, facing +z."""
    head = _joint("Head", (0, 10, 0), _face(), end=(0, 18, 0))
    neck = _joint("Neck", (0, 15, 0), [head])
    chest = _joint("Spine2", (0, 12, 0), [neck, _arm("Left", 1), _arm("Right", -1)])
    spine = _chain(["Spine", "Spine1"], [(0, 10, 0), (0, 12, 0)], None)
    spine.children[0].children.append(chest)
    root = Joint("Hips", (0, 0, 0), ROOT_CHANNELS, [spine, _leg("Left", 1), _leg("Right", -1)])
    return root


def quadruped():
    """A horse-like skeleton, 150 cm to the withers, facing +z."""
    ears = [
        _joint(f"{s}Ear", (sx * 4, 8, -2), end=(sx, 7, 0)) for s, sx in (("Left", 1), ("Right", -1))
    ]
    head = _joint(
        "Head", (0, 10, 20), [_joint("Jaw", (0, -6, 4), end=(0, -2, 20))] + ears, (0, -5, 30)
    )
    neck = _chain(["Neck", "Neck1"], [(0, 15, 20), (0, 20, 15)], None)
    neck.children[0].children.append(head)

    def leg(prefix, side, sign, at):
        names = [
            f"{side}{prefix}UpLeg",
            f"{side}{prefix}Leg",
            f"{side}{prefix}Foot",
            f"{side}{prefix}Toe",
        ]
        offsets = [(sign * 18, at[1], at[2]), (0, -40, 0), (0, -38, 0), (0, -20, 3)]
        return _chain(names, offsets, (0, -8, 4))

    chest = _joint(
        "Chest",
        (0, 0, 40),
        [neck, leg("Front", "Left", 1, (0, -10, 5)), leg("Front", "Right", -1, (0, -10, 5))],
    )
    spine = _chain(["Spine", "Spine1"], [(0, 3, 25), (0, 2, 30)], None)
    spine.children[0].children.append(chest)
    tail = _chain(
        ["Tail", "Tail1", "Tail2"], [(0, 5, -20), (0, -8, -15), (0, -12, -12)], (0, -12, -8)
    )
    hind = [leg("Hind", "Left", 1, (0, -10, -10)), leg("Hind", "Right", -1, (0, -10, -10))]
    return Joint("Hips", (0, 0, 0), ROOT_CHANNELS, [spine, tail] + hind)


# ------------------------------------------------------------------ motions


def _smooth(x):
    """0 before 0, 1 after 1, a smooth step between."""
    x = np.clip(x, 0.0, 1.0)
    return x * x * (3 - 2 * x)


def _standing(t):
    """The humanoid at rest: arms hanging, fingers relaxed (degrees per channel)."""
    zero = np.zeros_like(t)
    motion = {
        "Hips": {"Yposition": zero + 95.0},
        "LeftArm": {"Zrotation": zero - 75.0},
        "RightArm": {"Zrotation": zero + 75.0},
    }
    for side, sign in (("Left", -1), ("Right", 1)):
        for finger in FINGERS:
            for k in (1, 2, 3):
                motion[f"{side}Hand{finger}{k}"] = {"Zrotation": zero + sign * 12.0}
    return motion


def _set(motion, joint, channel, values):
    motion.setdefault(joint, {})[channel] = values


def _add(motion, joint, channel, values):
    channels = motion.setdefault(joint, {})
    channels[channel] = channels.get(channel, 0.0) + values


def _walk_limbs(motion, phase, weight):
    """Legs, arms and spine of a walk at `phase` (radians), scaled by `weight` (0 stands)."""
    s, c = np.sin(phase), np.cos(phase)
    for side, sign in (("Left", -1.0), ("Right", 1.0)):
        leg_s = sign * s  # the left leg leads when sin > 0
        _add(motion, f"{side}UpLeg", "Xrotation", weight * 25.0 * leg_s)
        _add(motion, f"{side}Leg", "Xrotation", weight * (5.0 + 30.0 * (0.5 - 0.5 * sign * c)))
        _add(motion, f"{side}Foot", "Xrotation", weight * -10.0 * leg_s)
        _add(motion, f"{side}Arm", "Yrotation", weight * 20.0 * s)
        _add(motion, f"{side}ForeArm", "Yrotation", weight * sign * (15.0 + 10.0 * (0.5 + 0.5 * s)))
    _add(motion, "Spine1", "Yrotation", weight * -5.0 * s)
    _add(motion, "Hips", "Yrotation", weight * 4.0 * s)
    _add(motion, "Hips", "Yposition", weight * 1.5 * np.cos(2 * phase))


def _blinks(motion, t, every=3.1):
    closed = (np.mod(t, every) < 0.12) * 40.0
    for side in ("Left", "Right"):
        _set(motion, f"{side}Eyelid", "Xrotation", closed)


def _wave_arms(motion, t, weight):
    """The right hand waving above the head about the elbow, the left arm rising a little."""
    raised = weight * _smooth(t / 1.0)
    _add(motion, "RightArm", "Zrotation", -125.0 * raised)
    _add(motion, "RightForeArm", "Zrotation", raised * (-30.0 + 35.0 * np.sin(2 * np.pi * 1.4 * t)))
    _add(motion, "LeftArm", "Zrotation", 25.0 * raised * (0.5 - 0.5 * np.cos(2 * np.pi * t / 3)))
    _add(motion, "Head", "Yrotation", 10.0 * weight * np.sin(2 * np.pi * t / 4))
    _add(motion, "Jaw", "Xrotation", 8.0 * weight * (0.5 + 0.5 * np.sin(2 * np.pi * 3 * t)))


def walk(t, speed=130.0, cycle=1.1):
    motion = _standing(t)
    _walk_limbs(motion, 2 * np.pi * t / cycle, 1.0)
    _set(motion, "Hips", "Zposition", speed * t)
    _blinks(motion, t)
    return motion


def wave(t):
    motion = _standing(t)
    _wave_arms(motion, t, 1.0)
    _add(motion, "Hips", "Xposition", 1.5 * np.sin(2 * np.pi * t / 2))
    _blinks(motion, t)
    return motion


def fingers_only(t):
    motion = _standing(t)
    for side, sign in (("Left", -1), ("Right", 1)):
        for i, finger in enumerate(FINGERS):
            curl = 10.0 + 60.0 * (0.5 - 0.5 * np.cos(2 * np.pi * t / 2.0 - 0.3 * i))
            for k in (1, 2, 3):
                _set(motion, f"{side}Hand{finger}{k}", "Zrotation", sign * curl)
    return motion


def long_take(t, radius=250.0, speed=130.0, cycle=1.1):
    """Walking round a circle, stopping to wave from 15 s to 25 s, walking on."""
    walking = 1.0 - _smooth((t - 14.0) / 1.0) + _smooth((t - 25.0) / 1.0)
    waving = 1.0 - walking
    dt = np.diff(t, prepend=t[0])
    travelled = np.cumsum(speed * walking * dt)
    motion = _standing(t)
    _walk_limbs(motion, 2 * np.pi * travelled / (speed * cycle), walking)
    _wave_arms(motion, np.maximum(t - 15.0, 0.0), waving)
    angle = travelled / radius
    _set(motion, "Hips", "Xposition", radius * np.sin(angle))
    _set(motion, "Hips", "Zposition", radius * (1 - np.cos(angle)))
    _add(motion, "Hips", "Yrotation", np.degrees(angle))
    _blinks(motion, t)
    return motion


def gallop(t, speed=600.0, cycle=0.45):
    phase = 2 * np.pi * t / cycle
    motion = {"Hips": {"Yposition": 115.0 + 5.0 * np.sin(2 * phase), "Zposition": speed * t}}
    lags = {"LeftHind": 0.0, "RightHind": 0.1, "LeftFront": 0.55, "RightFront": 0.65}
    for leg, lag in lags.items():
        side, end = ("Left", leg[4:]) if leg.startswith("Left") else ("Right", leg[5:])
        p = phase - 2 * np.pi * lag
        _set(motion, f"{side}{end}UpLeg", "Xrotation", -35.0 * np.sin(p))
        _set(motion, f"{side}{end}Leg", "Xrotation", 20.0 + 25.0 * (0.5 + 0.5 * np.cos(p)))
        _set(motion, f"{side}{end}Foot", "Xrotation", -20.0 * np.sin(p))
    _set(motion, "Spine1", "Xrotation", 6.0 * np.sin(phase))
    _set(motion, "Neck", "Xrotation", 8.0 * np.sin(phase + 1.0))
    _set(motion, "Tail", "Xrotation", 20.0 + 10.0 * np.sin(phase))
    _set(motion, "LeftEar", "Zrotation", 10.0 * np.sin(3 * phase))
    return motion


# ------------------------------------------------------------------ takes and what they hold


def _humanoid_chains():
    chains = {
        "body": ["Hips", "Spine", "Spine1", "Spine2"],
        "head": ["Neck", "Head", *FACE, *LIPS],
    }
    for side in ("Left", "Right"):
        fingers = [f"{side}Hand{f}{k}" for f in FINGERS for k in (1, 2, 3)]
        arm = [f"{side}Shoulder", f"{side}Arm", f"{side}ForeArm", f"{side}Hand"]
        chains[f"{side.lower()} arm"] = arm + fingers
        chains[f"{side.lower()} leg"] = [f"{side}{b}" for b in ("UpLeg", "Leg", "Foot", "ToeBase")]
    return chains


def _quadruped_chains():
    chains = {
        "body": ["Hips", "Spine", "Spine1", "Chest"],
        "head": ["Neck", "Neck1", "Head", "Jaw", "LeftEar", "RightEar"],
        "tail": ["Tail", "Tail1", "Tail2"],
    }
    for side in ("Left", "Right"):
        for end in ("Front", "Hind"):
            bones = [f"{side}{end}{b}" for b in ("UpLeg", "Leg", "Foot", "Toe")]
            chains[f"{side.lower()} {end.lower()} leg"] = bones
    return chains


# popup animate's --view: the direction from the eye toward the character.
SIDE = [-1.0, 0.0, 0.0]  # from the character's left: a walk's swing lies in the view
FRONT = [0.0, 0.0, -1.0]  # from the front: a wave lies in the view
LIMBS = ["left arm", "right arm", "left leg", "right leg"]
# name: (skeleton, motion, seconds, view, root motion, chains that move)
TAKES = {
    "walk": ("humanoid", walk, 4.0, SIDE, True, LIMBS),
    "wave": ("humanoid", wave, 6.0, FRONT, False, ["right arm", "left arm", "head"]),
    "fingers_only": ("humanoid", fingers_only, 4.0, FRONT, False, ["left arm", "right arm"]),
    "long_take": ("humanoid", long_take, 4500 / FPS, SIDE, True, LIMBS + ["head"]),
    "gallop": (
        "quadruped",
        gallop,
        2.0,
        SIDE,
        True,
        ["left front leg", "right front leg", "left hind leg", "right hind leg", "head", "tail"],
    ),
}
NOTES = {
    "fingers_only": "only the fingers move: finger chains are then all that moves",
    "long_take": "walks round a circle (root motion), stops to wave from 15 s to 25 s, walks on",
    "walk": "the face moves only by blinks: no face chain should be offered",
}


def _noisy(root, motion, frames, rng):
    """Every channel of every joint with a suit's jitter (rotations in degrees, positions cm)."""
    out = {}
    for joint in root.walk():
        channels = {}
        for channel in joint.channels:
            series = np.broadcast_to(motion.get(joint.name, {}).get(channel, 0.0), (frames,))
            sigma = NOISE_DEGREES if channel.endswith("rotation") else 0.05
            channels[channel] = series + rng.normal(0.0, sigma, frames)
        out[joint.name] = channels
    return out


def build(name):
    """(BVH text, what it holds) of take `name`."""
    skeleton, motion_of, seconds, view, root_motion, moving = TAKES[name]
    root = humanoid() if skeleton == "humanoid" else quadruped()
    frames = int(round(seconds * FPS))
    t = np.arange(frames) / FPS
    rng = np.random.default_rng(sum(map(ord, name)))
    motion = _noisy(root, motion_of(t), frames, rng)
    chains = _humanoid_chains() if skeleton == "humanoid" else _quadruped_chains()
    bones = [j.name for j in root.walk()]
    assert sorted(b for c in chains.values() for b in c) == sorted(bones), name
    known = {
        "name": name,
        "skeleton": skeleton,
        "units": "cm",
        "up": [0.0, 1.0, 0.0],
        "facing": [0.0, 0.0, 1.0],
        "view": view,
        "fps": FPS,
        "frames": frames,
        "bones": len(bones),
        "root_motion": root_motion,
        "chains": chains,
        "moving": moving,
        "note": NOTES.get(name, ""),
    }
    return bvh_text(root, motion, frames, 1.0 / FPS), known


def write(name, out_dir):
    text, known = build(name)
    os.makedirs(out_dir, exist_ok=True)
    path = os.path.join(out_dir, f"{name}.bvh")
    with open(path, "w") as f:
        f.write(text)
    with open(os.path.join(out_dir, f"{name}.json"), "w") as f:
        json.dump(known, f, indent=1)
    return path


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", required=True, help="folder for NAME.bvh and NAME.json")
    parser.add_argument("names", nargs="*", help=f"takes (default all): {', '.join(TAKES)}")
    args = parser.parse_args(argv)
    for name in args.names or TAKES:
        if name not in TAKES:
            parser.error(f"no take {name!r}: one of {', '.join(TAKES)}")
        print(write(name, args.out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
