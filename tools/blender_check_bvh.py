"""Reads each BVH of tools/make_animations.py with Blender's own BVH importer and compares the
end sites' paths with the known paths in NAME.json: a second reader, independent of assimp and
of popupcore, that agrees with the files' meaning (BVH semantics, channel order, end sites).

    blender -b --factory-startup --python tools/blender_check_bvh.py -- tests/data/animations

Prints the largest distance (mm) per file and exits 1 if one exceeds 1e-3 mm. Only known paths
are compared ("still" entries are skipped); file (x, y) is Blender's (x, z) after the importer's
default Y-up conversion.
"""

import glob
import json
import os
import sys

import bpy

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import make_animations  # noqa: E402  (numpy only; the diagonal's law is not evaluated here)


def _importer_open_without_u():
    """Debian's Blender 3.4 importer opens files with mode "rU", which Python 3.11 refuses: give
    its module an open() that drops the obsolete U (nothing else changes)."""
    import builtins

    from io_anim_bvh import import_bvh

    def open_text(file, mode="r", *args, **kwargs):
        return builtins.open(file, mode.replace("U", ""), *args, **kwargs)

    import_bvh.open = open_text


def end_paths(path, frames):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    _importer_open_without_u()
    bpy.ops.import_anim.bvh(
        filepath=path,
        global_scale=1.0,
        use_fps_scale=False,
        update_scene_fps=False,
        update_scene_duration=True,
    )
    rig = bpy.context.view_layer.objects.active
    scene = bpy.context.scene
    out = {}
    for frame in range(1, frames + 1):  # the importer starts at frame 1
        scene.frame_set(frame)
        for pose_bone in rig.pose.bones:
            world = rig.matrix_world @ pose_bone.tail
            out.setdefault(pose_bone.name, []).append((world.x, world.z))
    return out


def main(directory):
    worst_overall = 0.0
    for meta_path in sorted(glob.glob(os.path.join(directory, "*.json"))):
        with open(meta_path, encoding="utf-8") as f:
            meta = json.load(f)
        if "known" not in meta or not meta.get("file", "").endswith(".bvh"):
            continue
        paths = end_paths(os.path.join(directory, meta["file"]), meta["frames"])
        worst = 0.0
        for bone, entry in meta["known"].items():
            if entry["kind"] in ("still",) or entry.get("type") == "diagonal":
                continue
            got = paths[bone]
            s = [i / (len(got) - 1) for i in range(len(got))]
            want = make_animations.known_path(entry, s)
            for (gx, gy), (wx, wy) in zip(got, want):
                worst = max(worst, abs(gx - wx), abs(gy - wy))
        print(f"{meta['file']}: {len(paths)} bones, largest distance {worst:.2e} mm")
        worst_overall = max(worst_overall, worst)
    return 1 if worst_overall > 1e-3 else 0


if __name__ == "__main__":
    args = sys.argv[sys.argv.index("--") + 1 :] if "--" in sys.argv else []
    sys.exit(main(args[0] if args else os.path.join(HERE, "..", "tests", "data", "animations")))
