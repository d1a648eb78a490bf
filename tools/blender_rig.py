"""A skinned, animated figure made in headless Blender, exported to glTF (.glb), FBX and BVH.

    blender -b --factory-startup --python tools/blender_rig.py -- --out tests/data/animations
    blender -b --factory-startup --python tools/blender_rig.py -- --motion wave \\
        --out resources/samples --formats glb

Blender (Debian `blender`) is only needed to remake the files: the small outputs are committed
(tests/data/animations/figure.*, resources/samples/waving_figure.glb), and so is FIGURE.json, what
they are known to contain (bone lengths, the motion's angles, every chain tip's path per frame).

The figure: a box torso and head, cylinder limbs, one mesh skinned to an armature (each part fully
weighted to its bone, the elbows and knees blended over a ring of vertices). It stands in
Blender's frontal plane (x right, z up, facing −y) and every bone turns about the y axis only, so
each chain moves in the plane the viewer sees: the case where the issue asks for a weighted
motion error under 0.03. Frame 1 is the closed card, the last frame the open one.

Motions: `march` (test data; the arms swing up in opposite directions, the legs step apart) and
`wave` (the demo; the right hand waves twice about the elbow, the left arm rises). Axes in the
files: glTF and FBX are written y up (Blender's −y front becomes +z, toward the viewer, so
popupcore.MotionView()'s default view and up apply); BVH keeps Blender's z up (view (0, 1, 0),
up (0, 0, 1)). FIGURE.json records the view per file.
"""

import argparse
import json
import math
import os
import sys

import bpy
from mathutils import Matrix, Quaternion, Vector

FRAMES = 48

# name: (parent, head, tail) in metres, Blender axes (x right, z up, the figure faces −y).
BONES = {
    "Hips": (None, (0, 0, 0.95), (0, 0, 1.05)),
    "Spine": ("Hips", (0, 0, 1.05), (0, 0, 1.45)),
    "Neck": ("Spine", (0, 0, 1.45), (0, 0, 1.55)),
    "Head": ("Neck", (0, 0, 1.55), (0, 0, 1.80)),
    "UpperArm.R": ("Spine", (-0.20, 0, 1.42), (-0.48, 0, 1.42)),
    "ForeArm.R": ("UpperArm.R", (-0.48, 0, 1.42), (-0.74, 0, 1.42)),
    "Hand.R": ("ForeArm.R", (-0.74, 0, 1.42), (-0.84, 0, 1.42)),
    "UpperArm.L": ("Spine", (0.20, 0, 1.42), (0.48, 0, 1.42)),
    "ForeArm.L": ("UpperArm.L", (0.48, 0, 1.42), (0.74, 0, 1.42)),
    "Hand.L": ("ForeArm.L", (0.74, 0, 1.42), (0.84, 0, 1.42)),
    "Thigh.R": ("Hips", (-0.10, 0, 0.95), (-0.10, 0, 0.52)),
    "Shin.R": ("Thigh.R", (-0.10, 0, 0.52), (-0.10, 0, 0.10)),
    "Foot.R": ("Shin.R", (-0.10, 0, 0.10), (-0.10, -0.12, 0.03)),
    "Thigh.L": ("Hips", (0.10, 0, 0.95), (0.10, 0, 0.52)),
    "Shin.L": ("Thigh.L", (0.10, 0, 0.52), (0.10, 0, 0.10)),
    "Foot.L": ("Shin.L", (0.10, 0, 0.10), (0.10, -0.12, 0.03)),
}
TIPS = ["Head", "Hand.R", "Hand.L", "Foot.R", "Foot.L"]


def motion_angles(motion, s):
    """Bone -> rotation about Blender's +y (degrees, relative to the rest pose) at s in [0, 1].
    A positive turn about +y takes +z toward +x and −x toward +z: the right arm (along −x) rises,
    the left arm (along +x) comes down, a leg (along −z) swings toward −x."""
    if motion == "march":
        return {
            "UpperArm.R": 70.0 * s,  # the right arm rises (its hand turns up, toward +z)
            "ForeArm.R": 30.0 * s,
            "UpperArm.L": 70.0 * s,  # and the left arm comes down
            "ForeArm.L": 20.0 * s,
            "Thigh.R": 25.0 * s,  # the legs step apart
            "Shin.R": 10.0 * s,
            "Thigh.L": -25.0 * s,
            "Shin.L": -10.0 * s,
        }
    if motion == "wave":
        return {
            "UpperArm.R": 60.0 * s,
            "ForeArm.R": 45.0 + 35.0 * math.sin(4.0 * math.pi * s),  # two waves
            "UpperArm.L": -20.0 * s,
            "Thigh.R": 8.0 * s,
            "Thigh.L": -8.0 * s,
        }
    raise ValueError(f"motion {motion!r}: must be march or wave")


def clear_scene():
    bpy.ops.wm.read_factory_settings(use_empty=True)


def make_armature():
    data = bpy.data.armatures.new("FigureRig")
    rig = bpy.data.objects.new("Figure", data)
    bpy.context.scene.collection.objects.link(rig)
    bpy.context.view_layer.objects.active = rig
    bpy.ops.object.mode_set(mode="EDIT")
    for name, (parent, head, tail) in BONES.items():
        bone = data.edit_bones.new(name)
        bone.head, bone.tail = Vector(head), Vector(tail)
        bone.roll = 0.0
        if parent:
            bone.parent = data.edit_bones[parent]
            bone.use_connect = (Vector(head) - data.edit_bones[parent].tail).length < 1e-9
    bpy.ops.object.mode_set(mode="OBJECT")
    return rig


def _part(name, verts, faces, bone_weights):
    """A mesh object whose vertices carry vertex groups {bone: weight function(v)}."""
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(verts, [], faces)
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    for bone, weight in bone_weights.items():
        group = obj.vertex_groups.new(name=bone)
        for i, v in enumerate(verts):
            w = weight(Vector(v))
            if w > 0:
                group.add([i], w, "REPLACE")
    return obj


def box(name, lo, hi, bone):
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    verts = [(x, y, z) for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)]
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    return _part(name, verts, faces, {bone: lambda v: 1.0})


def cylinder(name, head, tail, radius, bones, rings=4, sides=10):
    """A capped cylinder from head to tail; `bones` = (first, second): the first weighs the upper
    half, the second the lower, blended linearly over the middle ring (the elbow or knee)."""
    head, tail = Vector(head), Vector(tail)
    axis = (tail - head).normalized()
    side = axis.orthogonal().normalized()
    other = axis.cross(side)
    verts, faces = [], []
    for r in range(rings + 1):
        centre = head + (tail - head) * (r / rings)
        for k in range(sides):
            a = 2 * math.pi * k / sides
            verts.append(tuple(centre + radius * (math.cos(a) * side + math.sin(a) * other)))
    for r in range(rings):
        for k in range(sides):
            a, b = r * sides + k, r * sides + (k + 1) % sides
            faces.append((a, b, b + sides, a + sides))
    faces.append(tuple(range(sides - 1, -1, -1)))
    faces.append(tuple(rings * sides + k for k in range(sides)))
    length = (tail - head).length
    first, second = bones

    def t(v):
        return max(0.0, min(1.0, (Vector(v) - head).dot(axis) / length))

    if first == second:  # one bone: every vertex fully its own (none left unweighted)
        return _part(name, verts, faces, {first: lambda v: 1.0})
    blend = {first: lambda v: 1.0 - _ramp(t(v)), second: lambda v: _ramp(t(v))}
    return _part(name, verts, faces, blend)


def _ramp(t):
    """0 on the upper part, 1 on the lower, linear over the middle 20 %."""
    return max(0.0, min(1.0, (t - 0.4) / 0.2))


def make_mesh(rig):
    parts = [
        box("Torso", (-0.18, -0.10, 0.95), (0.18, 0.10, 1.45), "Spine"),
        box("Pelvis", (-0.17, -0.09, 0.88), (0.17, 0.09, 1.05), "Hips"),
        box("HeadBox", (-0.11, -0.11, 1.55), (0.11, 0.11, 1.80), "Head"),
        cylinder("NeckCyl", (0, 0, 1.45), (0, 0, 1.56), 0.05, ("Neck", "Neck"), rings=1),
        cylinder("ArmR", (-0.20, 0, 1.42), (-0.74, 0, 1.42), 0.045, ("UpperArm.R", "ForeArm.R")),
        cylinder("ArmL", (0.20, 0, 1.42), (0.74, 0, 1.42), 0.045, ("UpperArm.L", "ForeArm.L")),
        box("HandR", (-0.84, -0.03, 1.38), (-0.74, 0.03, 1.46), "Hand.R"),
        box("HandL", (0.74, -0.03, 1.38), (0.84, 0.03, 1.46), "Hand.L"),
        cylinder("LegR", (-0.10, 0, 0.95), (-0.10, 0, 0.10), 0.06, ("Thigh.R", "Shin.R")),
        cylinder("LegL", (0.10, 0, 0.95), (0.10, 0, 0.10), 0.06, ("Thigh.L", "Shin.L")),
        box("FootR", (-0.15, -0.16, 0.0), (-0.05, 0.04, 0.10), "Foot.R"),
        box("FootL", (0.05, -0.16, 0.0), (0.15, 0.04, 0.10), "Foot.L"),
    ]
    bpy.ops.object.select_all(action="DESELECT")
    for p in parts:
        p.select_set(True)
    bpy.context.view_layer.objects.active = parts[0]
    bpy.ops.object.join()
    body = bpy.context.view_layer.objects.active
    body.name = body.data.name = "FigureMesh"
    body.parent = rig
    modifier = body.modifiers.new("Armature", "ARMATURE")
    modifier.object = rig
    return body


def animate(rig, motion):
    scene = bpy.context.scene
    scene.frame_start, scene.frame_end = 1, FRAMES
    scene.render.fps = 24
    world_y = Vector((0, 1, 0))
    for pose_bone in rig.pose.bones:
        pose_bone.rotation_mode = "QUATERNION"
    for frame in range(1, FRAMES + 1):
        s = (frame - 1) / (FRAMES - 1)
        angles = motion_angles(motion, s)
        for pose_bone in rig.pose.bones:
            # world y in the bone's rest frame: parents only turn about y, so this axis is the
            # same in the posed parent's frame.
            axis = rig.data.bones[pose_bone.name].matrix_local.to_3x3().inverted() @ world_y
            angle = math.radians(angles.get(pose_bone.name, 0.0))
            pose_bone.rotation_quaternion = Quaternion(axis, angle)
            pose_bone.keyframe_insert("rotation_quaternion", frame=frame)
    for fcurve in rig.animation_data.action.fcurves:
        for key in fcurve.keyframe_points:
            key.interpolation = "LINEAR"
    rig.animation_data.action.name = motion


def tip_paths(rig):
    """Blender world head and tail of every tip bone at every frame (metres, z up)."""
    out = {name: {"head": [], "tail": []} for name in TIPS}
    for frame in range(1, FRAMES + 1):
        bpy.context.scene.frame_set(frame)
        for name in TIPS:
            pose_bone = rig.pose.bones[name]
            for key, point in (("head", pose_bone.head), ("tail", pose_bone.tail)):
                world = rig.matrix_world @ point
                out[name][key].append([round(c, 6) for c in world])
    return out


def export(rig, body, out_dir, stem, formats):
    written = {}
    bpy.ops.object.select_all(action="DESELECT")
    rig.select_set(True)
    body.select_set(True)
    bpy.context.view_layer.objects.active = rig
    if "glb" in formats:
        path = os.path.join(out_dir, stem + ".glb")
        bpy.ops.export_scene.gltf(
            filepath=path,
            export_format="GLB",
            use_selection=True,
            export_animations=True,
            export_skins=True,
            export_yup=True,
            export_apply=False,
            export_force_sampling=True,
            export_frame_range=True,
            export_materials="NONE",
        )
        written["glb"] = {"file": stem + ".glb", "view": [0, 0, -1], "up": [0, 1, 0]}
    if "fbx" in formats:
        path = os.path.join(out_dir, stem + ".fbx")
        bpy.ops.export_scene.fbx(
            filepath=path,
            use_selection=True,
            object_types={"ARMATURE", "MESH"},
            add_leaf_bones=False,
            bake_anim=True,
            bake_anim_use_all_actions=False,
            bake_anim_use_nla_strips=False,
            bake_anim_simplify_factor=0.0,
            axis_forward="-Z",
            axis_up="Y",
            apply_scale_options="FBX_SCALE_UNITS",
            embed_textures=False,
        )
        written["fbx"] = {"file": stem + ".fbx", "view": [0, 0, -1], "up": [0, 1, 0]}
    if "bvh" in formats:
        path = os.path.join(out_dir, stem + ".bvh")
        bpy.ops.object.select_all(action="DESELECT")
        rig.select_set(True)
        bpy.ops.export_anim.bvh(
            filepath=path,
            frame_start=1,
            frame_end=FRAMES,
            rotate_mode="NATIVE",
            root_transform_only=True,
        )
        written["bvh"] = {"file": stem + ".bvh", "view": [0, 1, 0], "up": [0, 0, 1]}
    return written


def main(argv):
    parser = argparse.ArgumentParser(description="Skinned figure for issue 13 test data")
    parser.add_argument("--out", required=True)
    parser.add_argument("--motion", default="march", choices=["march", "wave"])
    parser.add_argument(
        "--stem", default=None, help="file name stem (default: figure / waving_figure)"
    )
    parser.add_argument("--formats", default="glb,fbx,bvh")
    args = parser.parse_args(argv)
    stem = args.stem or ("figure" if args.motion == "march" else "waving_figure")
    formats = set(args.formats.split(","))
    os.makedirs(args.out, exist_ok=True)
    clear_scene()
    rig = make_armature()
    body = make_mesh(rig)
    animate(rig, args.motion)
    paths = tip_paths(rig)
    written = export(rig, body, args.out, stem, formats)
    bpy.context.scene.frame_set(1)
    meta = {
        "description": f"skinned figure, motion {args.motion!r}, made by tools/blender_rig.py",
        "frames": FRAMES,
        "fps": 24,
        "units": "metre",
        "bones": {name: {"parent": p, "head": h, "tail": t} for name, (p, h, t) in BONES.items()},
        "angles_deg_about_y": {
            name: [
                round(motion_angles(args.motion, (f - 1) / (FRAMES - 1)).get(name, 0.0), 6)
                for f in range(1, FRAMES + 1)
            ]
            for name in BONES
        },
        "tips_blender_world": paths,
        "files": written,
        "mesh_vertices": len(body.data.vertices),
    }
    with open(os.path.join(args.out, stem + ".json"), "w", encoding="utf-8") as f:
        json.dump(meta, f, indent=1, sort_keys=True)
        f.write("\n")
    print("blender_rig: wrote", ", ".join(w["file"] for w in written.values()))


if __name__ == "__main__":
    main(sys.argv[sys.argv.index("--") + 1 :] if "--" in sys.argv else [])
