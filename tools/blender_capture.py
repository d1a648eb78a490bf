"""Capture-like takes WITH a skinned mesh, made in headless Blender and exported to glTF (.glb).

    blender -b --factory-startup --python-exit-code 1 --python tools/blender_capture.py -- \
        --out tests/data/animations
    blender -b --factory-startup --python-exit-code 1 --python tools/blender_capture.py -- \
        --out DIR walk

Blender (Debian 12's `apt-get install blender`, 3.4.1) is only needed to remake the files: the
small outputs are committed (tests/data/animations/capture_walk.glb, capture_wave.glb) with
capture_NAME.json, what they are known to contain, written here from Blender's own data and
independently of PopUp.

The skeleton is tools/make_captures.py's mocap suit (61 joints: body, neck and head, a face rig of
jaw, eyes, eyelids, brows and lips, two arms with a thumb and four fingers of three bones each,
two legs with toes), in metres, y up and facing +z in the .glb (Blender's z up and −y front,
exported y up as tools/blender_rig.py does). Its motions are make_captures.py's closed forms
(degrees per BVH channel, ZXY), turned into each bone's rest frame.

The mesh: primitives joined into one object, each part weighted to its bone and blended over a
few rings at the elbows, knees, wrists and finger joints (tubes along the limbs and fingers, an
elliptic tube for the torso, an ellipsoid head). The face bones own only the two or three head
vertices nearest to them, as a face rig's bones own a small patch of skin: far below thesis τp
(ChainOptions.prune_fraction, 0.09 of the mean vertices per bone), so pruning by skinned vertex
count is what folds them into the head. The fingers own tens of vertices each: τp keeps them, the
short-chain rule (ChainOptions.min_chain_size) folds them into the arms.

Takes (60 frames a second):
- `walk`: 180 frames, make_captures.walk: the legs stride, the arms swing against them, the spine
  and hips turn a little, the root travels forward (+z) at 1.3 m/s, the eyelids blink;
- `wave`: 240 frames, make_captures' wave of the right hand above the head about the elbow, the
  left arm rising a little, the knees bending a little in turn, the right hand's fingers curling,
  the face twitching (jaw, lips, brows, eyes, blinks).
Joints that move carry a seeded jitter of 0.3° (0.05 cm on the root), as a suit's; joints that do
not are left constant so the exporter keeps the files small.
"""

import argparse
import json
import math
import os
import sys

import bpy
import numpy as np
from mathutils import Matrix, Quaternion, Vector

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_captures as captures  # noqa: E402
from make_animations import joint_positions  # noqa: E402

FPS = 60
HIP_HEIGHT = 95.0  # cm: make_captures' standing root height
NOISE_DEGREES = captures.NOISE_DEGREES
# BVH (x, y up, z front) to Blender (x, −y front, z up): a rotation about x.
TO_BLENDER = Matrix(((1, 0, 0), (0, 0, -1), (0, 1, 0)))


# ------------------------------------------------------------------ skeleton


def rest_skeleton():
    """{joint: (parent, head, tail)} in Blender metres: the suit standing, each bone's tail at
    its main child (the spine, the neck, the middle finger) or its end site."""
    root = captures.humanoid()
    at = joint_positions(root, {"Hips": {"Yposition": [HIP_HEIGHT]}}, 0)
    bones = {}

    def visit(joint, parent):
        if joint.children:
            main = {"Hips": "Spine", "Spine2": "Neck"}.get(joint.name)
            child = next((c for c in joint.children if c.name == main), None)
            child = child or next(
                (c for c in joint.children if "Middle" in c.name), joint.children[0]
            )
            tail = at[child.name]
        if joint.end is not None and (not joint.children or joint.name == "Head"):
            tail = at[joint.name + "_end"]
        bones[joint.name] = (parent, _blender(at[joint.name]), _blender(tail))
        for child in joint.children:
            visit(child, joint.name)

    visit(root, None)
    return bones


def _blender(cm):
    return TO_BLENDER @ Vector([float(v) / 100.0 for v in cm])


def make_armature(bones):
    data = bpy.data.armatures.new("CaptureRig")
    rig = bpy.data.objects.new("Capture", data)
    bpy.context.scene.collection.objects.link(rig)
    bpy.context.view_layer.objects.active = rig
    bpy.ops.object.mode_set(mode="EDIT")
    for name, (parent, head, tail) in bones.items():
        bone = data.edit_bones.new(name)
        bone.head, bone.tail, bone.roll = head, tail, 0.0
        if parent:
            bone.parent = data.edit_bones[parent]
    bpy.ops.object.mode_set(mode="OBJECT")
    return rig


# ------------------------------------------------------------------ mesh


def _part(name, verts, faces, weights):
    """A mesh object; weights: per vertex {bone: weight}."""
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([tuple(v) for v in verts], [], faces)
    for polygon in mesh.polygons:
        polygon.use_smooth = True  # one normal per vertex: glTF keeps Blender's vertex count
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    groups = {}
    for i, vertex_weights in enumerate(weights):
        for bone, w in vertex_weights.items():
            if bone not in groups:
                groups[bone] = obj.vertex_groups.new(name=bone)
            groups[bone].add([i], w, "REPLACE")
    return obj


def _ring_faces(loops, sides):
    faces = []
    for r in range(loops - 1):
        for k in range(sides):
            a, b = r * sides + k, r * sides + (k + 1) % sides
            faces.append((a, b, b + sides, a + sides))
    faces.append(tuple(range(sides - 1, -1, -1)))
    faces.append(tuple((loops - 1) * sides + k for k in range(sides)))
    return faces


def tube(name, joints, bones, radii, width, sides, rings, blend=0.25):
    """A capped tube along the polyline `joints` (Blender points), segment i weighted to
    bones[i] and blended linearly into the next over ±blend of a segment about each inner joint.
    radii = (along `width`, across it); `rings` rings per segment, half a step off the joints, so
    none sits on one (where two bones would weigh the same)."""
    joints = [Vector(j) for j in joints]
    verts, weights = [], []
    for i, bone in enumerate(bones):
        head, tail = joints[i], joints[i + 1]
        axis = (tail - head).normalized()
        u = (width - width.dot(axis) * axis).normalized()
        v = axis.cross(u)
        places = [(r + 0.5) / rings for r in range(rings)]
        places = ([0.0] if i == 0 else []) + places + ([1.0] if i == len(bones) - 1 else [])
        for s in places:
            centre = head + (tail - head) * s
            for k in range(sides):
                a = 2 * math.pi * k / sides
                verts.append(centre + radii[0] * math.cos(a) * u + radii[1] * math.sin(a) * v)
                weights.append(_blend(bones, i, s, blend))
    return _part(name, verts, _ring_faces(len(verts) // sides, sides), weights)


def _blend(bones, i, s, blend):
    """{bone: weight} at fraction s of segment i: 50/50 at the joints, one bone away from them."""
    if i + 1 < len(bones) and s > 1 - blend:
        w = 0.5 + 0.5 * (s - 1) / blend
        return {bones[i]: 1 - w, bones[i + 1]: w}
    if i > 0 and s < blend:
        w = 0.5 + 0.5 * s / blend
        return {bones[i - 1]: 1 - w, bones[i]: w}
    return {bones[i]: 1.0}


def ellipsoid(name, centre, radii, bone, segments=20, rings=12):
    verts = [centre + Vector((0, 0, -radii[2]))]
    for r in range(1, rings):
        polar = math.pi * r / rings
        for k in range(segments):
            a = 2 * math.pi * k / segments
            d = Vector((math.sin(polar) * math.cos(a), math.sin(polar) * math.sin(a), 0))
            d.z = -math.cos(polar)
            verts.append(centre + Vector([d[j] * radii[j] for j in range(3)]))
    verts.append(centre + Vector((0, 0, radii[2])))
    faces = [(0, (k + 1) % segments + 1, k + 1) for k in range(segments)]
    for r in range(rings - 2):
        for k in range(segments):
            a, b = 1 + r * segments + k, 1 + r * segments + (k + 1) % segments
            faces.append((a, b, b + segments, a + segments))
    top, last = len(verts) - 1, 1 + (rings - 2) * segments
    faces += [(last + k, last + (k + 1) % segments, top) for k in range(segments)]
    return _part(name, verts, faces, [{bone: 1.0} for _ in verts])


# The face bones and how many head vertices each owns (the nearest to its head, not shared).
FACE_VERTICES = {"Jaw": 3, "UpperLip": 2, "LowerLip": 2}
FACE_VERTICES.update({f"{s}{p}": 2 for s in ("Left", "Right") for p in ("Eye", "Eyelid", "Brow")})


def give_face_vertices(head, bones):
    """The head's vertices nearest each face bone become that bone's (a face rig's skin)."""
    taken = set()
    for name, count in FACE_VERTICES.items():
        where = bones[name][1]
        order = sorted(
            range(len(head.data.vertices)), key=lambda i: (head.data.vertices[i].co - where).length
        )
        mine = [i for i in order if i not in taken][:count]
        taken.update(mine)
        head.vertex_groups["Head"].remove(mine)
        head.vertex_groups.new(name=name).add(mine, 1.0, "REPLACE")


def make_mesh(rig, bones):
    """The body's parts, joined into one mesh skinned to the rig."""
    at = {name: head for name, (_, head, _) in bones.items()}
    end = {name: tail for name, (_, _, tail) in bones.items()}
    x, y = Vector((1, 0, 0)), Vector((0, 1, 0))
    torso = ["Hips", "Spine", "Spine1", "Spine2"]
    parts = [
        tube("Torso", [at[b] for b in torso] + [at["Neck"]], torso, (0.16, 0.10), x, 24, 5),
        tube("Neck", [at["Neck"], at["Head"]], ["Neck"], (0.05, 0.05), x, 12, 3),
    ]
    head = ellipsoid(
        "Head", (at["Head"] + end["Head"]) / 2 + Vector((0, -0.01, 0)), (0.09, 0.10, 0.11), "Head"
    )
    give_face_vertices(head, bones)
    parts.append(head)
    for side in ("Left", "Right"):
        arm = [f"{side}Arm", f"{side}ForeArm"]
        hand = f"{side}Hand"
        parts.append(
            tube(f"{side}ArmMesh", [at[b] for b in arm] + [at[hand]], arm, (0.045, 0.04), y, 14, 7)
        )
        parts.append(
            tube(f"{side}HandMesh", [at[hand], end[hand]], [hand], (0.035, 0.015), y, 10, 3)
        )
        for finger in captures.FINGERS:
            names = [f"{hand}{finger}{k}" for k in (1, 2, 3)]
            points = [at[n] for n in names] + [end[names[-1]]]
            parts.append(tube(f"{hand}{finger}Mesh", points, names, (0.008, 0.007), y, 6, 3))
        leg = [f"{side}UpLeg", f"{side}Leg"]
        parts.append(
            tube(
                f"{side}LegMesh",
                [at[b] for b in leg] + [at[f"{side}Foot"]],
                leg,
                (0.07, 0.065),
                y,
                16,
                11,
            )
        )
        foot = [f"{side}Foot", f"{side}ToeBase"]
        parts.append(
            tube(
                f"{side}FootMesh",
                [at[b] for b in foot] + [end[foot[-1]]],
                foot,
                (0.045, 0.035),
                x,
                10,
                3,
            )
        )
    bpy.ops.object.select_all(action="DESELECT")
    for p in parts:
        p.select_set(True)
    bpy.context.view_layer.objects.active = parts[0]
    bpy.ops.object.join()
    body = bpy.context.view_layer.objects.active
    body.name = body.data.name = "CaptureMesh"
    body.parent = rig
    body.modifiers.new("Armature", "ARMATURE").object = rig
    return body


# ------------------------------------------------------------------ motions


def walk(t):
    """make_captures' walk: the limbs' stride, the root forward 130 cm/s, blinks."""
    return captures.walk(t)


def wave(t):
    """make_captures' wave, with the knees bending in turn, the right hand's fingers curling and
    the face twitching."""
    motion = captures.wave(t)
    for side, lag in (("Left", 0.0), ("Right", math.pi)):
        bend = 0.5 - 0.5 * np.cos(2 * np.pi * t / 2.0 + lag)
        captures._add(motion, f"{side}UpLeg", "Xrotation", -10.0 * bend)
        captures._add(motion, f"{side}Leg", "Xrotation", 20.0 * bend)
    for i, finger in enumerate(captures.FINGERS):
        curl = 50.0 * (0.5 - 0.5 * np.cos(2 * np.pi * t / 1.5 - 0.4 * i))
        for k in (1, 2, 3):
            captures._add(motion, f"RightHand{finger}{k}", "Zrotation", curl)
    for side, sign in (("Left", 1.0), ("Right", -1.0)):
        captures._add(motion, f"{side}Brow", "Zrotation", sign * 12.0 * np.sin(2 * np.pi * 0.8 * t))
        captures._add(motion, f"{side}Eye", "Yrotation", 15.0 * np.sin(2 * np.pi * 0.5 * t))
    captures._add(motion, "UpperLip", "Xrotation", -10.0 * np.sin(2 * np.pi * 2.0 * t) ** 2)
    captures._add(motion, "LowerLip", "Xrotation", 12.0 * np.sin(2 * np.pi * 2.0 * t) ** 2)
    captures._blinks(motion, t, every=1.7)
    return motion


LIMBS = captures.LIMBS
# name: (motion, frames, view, root motion, the chains that move, note)
TAKES = {
    "walk": (walk, 180, captures.SIDE, True, LIMBS, "the face moves only by blinks"),
    "wave": (
        wave,
        240,
        captures.FRONT,
        False,
        ["right arm", "left arm", "head", "left leg", "right leg"],
        "the right hand waves about the elbow above the head; its fingers curl; the face twitches",
    ),
}


def channels(name, frames, rng):
    """{joint: {channel: degrees or cm per frame}}, with a suit's jitter on what moves."""
    motion_of = TAKES[name][0]
    t = np.arange(frames) / FPS
    motion = motion_of(t)
    out = {}
    for joint, values in motion.items():
        out[joint] = {}
        for channel, series in values.items():
            series = np.broadcast_to(np.asarray(series, dtype=float), (frames,)).copy()
            if np.ptp(series) > 0:
                sigma = NOISE_DEGREES if channel.endswith("rotation") else 0.05
                series += rng.normal(0.0, sigma, frames)
            out[joint][channel] = series
    return out


def _rotation(values, frame):
    """A BVH joint's rotation (its ZXY channels in order) at a frame, in BVH axes."""
    out = Matrix.Identity(3)
    for channel in ("Zrotation", "Xrotation", "Yrotation"):
        angle = math.radians(float(values[channel][frame])) if channel in values else 0.0
        out = out @ Matrix.Rotation(angle, 3, channel[0])
    return out


def animate(rig, motion, frames):
    """Keys every bone's rotation (and the root's place) at every frame. A BVH rotation R (rest
    frames along the axes) is R' = C R Cᵀ in Blender's axes and B⁻¹ R' B in the bone's rest
    frame B; the root's place p is B⁻¹ C (p − p_rest) in it."""
    scene = bpy.context.scene
    scene.frame_start, scene.frame_end = 0, frames - 1
    scene.render.fps = FPS
    rig.animation_data_create()
    action = bpy.data.actions.new("take")
    rig.animation_data.action = action
    rest_root = Vector((0.0, HIP_HEIGHT, 0.0))
    for pose_bone in rig.pose.bones:
        pose_bone.rotation_mode = "QUATERNION"
        rest = rig.data.bones[pose_bone.name].matrix_local.to_3x3()
        values = motion.get(pose_bone.name, {})
        keys, previous = [], Quaternion()
        for f in range(frames):
            q = (
                rest.transposed()
                @ TO_BLENDER
                @ _rotation(values, f)
                @ TO_BLENDER.transposed()
                @ rest
            ).to_quaternion()
            if q.dot(previous) < 0:  # the same turn, kept continuous for the keys
                q.negate()
            keys.append(q)
            previous = q
        path = f'pose.bones["{pose_bone.name}"]'
        _key(action, path + ".rotation_quaternion", [list(q) for q in keys], pose_bone.name)
        if pose_bone.name == "Hips":
            places = []
            for f in range(frames):
                p = Vector(
                    [
                        float(values[c][f]) if c in values else 0.0
                        for c in ("Xposition", "Yposition", "Zposition")
                    ]
                )
                places.append(list(rest.transposed() @ TO_BLENDER @ ((p - rest_root) / 100.0)))
            _key(action, path + ".location", places, "Hips")


def _key(action, data_path, per_frame, group):
    """One F-curve per component, a linear key at every frame from 0 (the .glb's times then
    start at 0 s, where assimp puts the rest scale's one key: no frame is added)."""
    for index in range(len(per_frame[0])):
        curve = action.fcurves.new(data_path, index=index, action_group=group)
        curve.keyframe_points.add(len(per_frame))
        co = [c for f, value in enumerate(per_frame) for c in (float(f), value[index])]
        curve.keyframe_points.foreach_set("co", co)
        for point in curve.keyframe_points:
            point.interpolation = "LINEAR"
        curve.update()


# ------------------------------------------------------------------ what is known, and export


def _gltf(point):
    """Blender (x, −y front, z up) to the .glb's axes (x, y up, z front)."""
    return [round(point.x, 6), round(point.z, 6), round(-point.y, 6)]


def vertices_per_bone(body):
    """Per bone: the mesh vertices whose largest weight is its (PopUp's rule, counted here)."""
    names = {g.index: g.name for g in body.vertex_groups}
    counts = {}
    for vertex in body.data.vertices:
        weights = sorted(((g.weight, names[g.group]) for g in vertex.groups), reverse=True)
        assert len(weights) == 1 or weights[0][0] > weights[1][0] + 1e-3, weights
        counts[weights[0][1]] = counts.get(weights[0][1], 0) + 1
    return counts


TRACKED = ["Hips", "Head", "LeftHand", "RightHand", "LeftFoot", "RightFoot"]
TRACK_EVERY = 30


def tracked_points(rig, frames):
    """Blender's posed world heads of a few bones every TRACK_EVERY frames (the .glb's axes)."""
    out = {name: [] for name in TRACKED}
    for frame in range(0, frames, TRACK_EVERY):
        bpy.context.scene.frame_set(frame)
        for name in TRACKED:
            out[name].append(_gltf(rig.matrix_world @ rig.pose.bones[name].head))
    bpy.context.scene.frame_set(0)
    return out


def check_against_bvh(tracked, motion):
    """Blender's pose is the BVH's: make_captures' joints placed by make_animations' BVH reading
    of the same channels (cm, y up) agree with the tracked heads within 0.1 mm."""
    root = captures.humanoid()
    for i in range(len(tracked["Hips"])):
        at = joint_positions(root, motion, i * TRACK_EVERY)
        for name, heads in tracked.items():
            gap = np.linalg.norm(np.asarray(heads[i]) - np.asarray(at[name]) / 100.0)
            assert gap < 1e-4, (name, i * TRACK_EVERY, gap)


def _root(rig, frame):
    """The root's posed world place at a frame (the .glb's axes)."""
    bpy.context.scene.frame_set(frame)
    place = _gltf(rig.matrix_world @ rig.pose.bones["Hips"].head)
    bpy.context.scene.frame_set(0)
    return place


def export_glb(rig, body, path):
    bpy.ops.object.select_all(action="DESELECT")
    rig.select_set(True)
    body.select_set(True)
    bpy.context.view_layer.objects.active = rig
    bpy.ops.export_scene.gltf(
        filepath=path,
        export_format="GLB",
        use_selection=True,
        export_animations=True,
        export_skins=True,
        export_yup=True,
        export_apply=False,
        export_force_sampling=True,
        export_optimize_animation_size=True,
        export_frame_range=True,
        export_materials="NONE",
        export_texcoords=False,
    )


def known_answers(name, rig, body, frames):
    _, _, view, root_motion, moving, note = TAKES[name]
    counts = vertices_per_bone(body)
    bones = [b.name for b in rig.data.bones]
    points = tracked_points(rig, frames)
    face = [b for b in bones if b in FACE_VERTICES]
    return {
        "name": f"capture_{name}",
        "made_by": "tools/blender_capture.py (Blender " + bpy.app.version_string + ")",
        "skeleton": "humanoid",
        "units": "m",
        "up": [0.0, 1.0, 0.0],
        "facing": [0.0, 0.0, 1.0],
        "view": view,
        "fps": FPS,
        "frames": frames,
        "bones": len(bones),
        "root_motion": root_motion,
        "root_travel_m": [round(b - a, 6) for a, b in zip(_root(rig, 0), _root(rig, frames - 1))],
        "chains": captures._humanoid_chains(),
        "moving": moving,
        "face_bones": face,
        "finger_bones": [b for b in bones if "Hand" in b and b[-1] in "123"],
        "mesh_vertices": len(body.data.vertices),
        "vertices_per_bone": {b: counts.get(b, 0) for b in bones},
        "mean_vertices_per_bone": round(len(body.data.vertices) / len(bones), 6),
        "tracked_every": TRACK_EVERY,
        "tracked_heads": points,
        "note": note,
    }


def write(name, out_dir):
    _, frames, _, _, _, _ = TAKES[name]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bones = rest_skeleton()
    rig = make_armature(bones)
    body = make_mesh(rig, bones)
    rng = np.random.default_rng(sum(map(ord, "blender_" + name)))
    motion = channels(name, frames, rng)
    animate(rig, motion, frames)
    known = known_answers(name, rig, body, frames)
    check_against_bvh(known["tracked_heads"], motion)
    path = os.path.join(out_dir, f"capture_{name}.glb")
    export_glb(rig, body, path)
    with open(os.path.join(out_dir, f"capture_{name}.json"), "w", encoding="utf-8") as f:
        json.dump(known, f, indent=1)
        f.write("\n")
    return path


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", required=True, help="folder for capture_NAME.glb and .json")
    parser.add_argument("names", nargs="*", help=f"takes (default all): {', '.join(TAKES)}")
    args = parser.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    for name in args.names or TAKES:
        if name not in TAKES:
            parser.error(f"no take {name!r}: one of {', '.join(TAKES)}")
        print("blender_capture: wrote", write(name, args.out))


if __name__ == "__main__":
    main(sys.argv[sys.argv.index("--") + 1 :] if "--" in sys.argv else [])
