"""File writers for tools/make_corpus.py: meshes as the exporters of real tools leave them.

Every writer takes a list of Piece (one per solid, sheet or part, never fused) and writes them
as they are: concatenated into one triangle list (STL, OFF, PLY: touching parts then share
corners only where positions coincide), or as one object per piece (OBJ `o`, glTF meshes and
nodes, Collada geometries, 3MF objects). Plain Python, numpy and PIL (python3-pil): no FreeCAD.
"""

import io
import json
import os
import struct
import zipfile

import numpy as np


class Piece:
    """One part of a model: vertices (N x 3, file units and axes), triangles (M x 3 indices),
    an RGB colour in [0, 1], optional per-vertex colours (N x 3) and texture coordinates (N x 2)."""

    def __init__(self, name, vertices, triangles, colour=(0.8, 0.8, 0.8), colours=None, uvs=None):
        self.name = name
        self.vertices = np.asarray(vertices, dtype=float).reshape(-1, 3)
        self.triangles = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
        self.colour = tuple(float(c) for c in colour)
        self.colours = None if colours is None else np.asarray(colours, dtype=float)
        self.uvs = None if uvs is None else np.asarray(uvs, dtype=float)


def concatenated(pieces):
    """(vertices, triangles, per-vertex colours) of all pieces, one after the other."""
    vertices, triangles, colours, offset = [], [], [], 0
    for p in pieces:
        vertices.append(p.vertices)
        triangles.append(p.triangles + offset)
        colours.append(
            p.colours if p.colours is not None else np.tile(p.colour, (len(p.vertices), 1))
        )
        offset += len(p.vertices)
    return np.vstack(vertices), np.vstack(triangles), np.vstack(colours)


def _normals(vertices, triangles):
    a, b, c = (vertices[triangles[:, i]] for i in range(3))
    n = np.cross(b - a, c - a)
    length = np.linalg.norm(n, axis=1, keepdims=True)
    return n / np.where(length > 0, length, 1)


def write_stl_binary(path, pieces):
    vertices, triangles, _ = concatenated(pieces)
    normals = _normals(vertices, triangles)
    record = np.zeros(len(triangles), dtype=[("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")])
    record["n"] = normals
    record["v"] = vertices[triangles]
    with open(path, "wb") as f:
        f.write(b"PopUp corpus binary STL".ljust(80, b" ") + struct.pack("<I", len(triangles)))
        f.write(record.tobytes())


def write_stl_ascii(path, pieces):
    """One `solid` block per piece, as CAD tools that export an assembly to ASCII STL do."""
    with open(path, "w") as f:
        for p in pieces:
            f.write(f"solid {p.name}\n")
            for t, n in zip(p.triangles, _normals(p.vertices, p.triangles)):
                f.write(f"  facet normal {n[0]:.6e} {n[1]:.6e} {n[2]:.6e}\n    outer loop\n")
                for v in p.vertices[t]:
                    f.write(f"      vertex {v[0]:.7e} {v[1]:.7e} {v[2]:.7e}\n")
                f.write("    endloop\n  endfacet\n")
            f.write(f"endsolid {p.name}\n")


def write_off(path, pieces):
    vertices, triangles, _ = concatenated(pieces)
    with open(path, "w") as f:
        f.write(f"OFF\n{len(vertices)} {len(triangles)} 0\n")
        np.savetxt(f, vertices, fmt="%.6f")
        np.savetxt(f, np.hstack([np.full((len(triangles), 1), 3), triangles]), fmt="%d")


def write_ply(path, pieces, binary=True, colours=True):
    vertices, triangles, rgb = concatenated(pieces)
    header = ["ply", f"format {'binary_little_endian' if binary else 'ascii'} 1.0"]
    header += ["comment PopUp corpus", f"element vertex {len(vertices)}"]
    header += [f"property float {a}" for a in "xyz"]
    if colours:
        header += [f"property uchar {c}" for c in ("red", "green", "blue")]
    header += [f"element face {len(triangles)}", "property list uchar int vertex_indices"]
    header += ["end_header"]
    rgb8 = np.clip(np.round(rgb * 255), 0, 255).astype(np.uint8)
    with open(path, "wb") as f:
        f.write(("\n".join(header) + "\n").encode())
        if binary:
            fields = [("p", "<f4", 3)] + ([("c", "u1", 3)] if colours else [])
            record = np.zeros(len(vertices), dtype=fields)
            record["p"] = vertices
            if colours:
                record["c"] = rgb8
            f.write(record.tobytes())
            faces = np.zeros(len(triangles), dtype=[("n", "u1"), ("i", "<i4", 3)])
            faces["n"], faces["i"] = 3, triangles
            f.write(faces.tobytes())
        else:
            for i, v in enumerate(vertices):
                extra = " %d %d %d" % tuple(rgb8[i]) if colours else ""
                f.write(f"{v[0]:.6f} {v[1]:.6f} {v[2]:.6f}{extra}\n".encode())
            for t in triangles:
                f.write(f"3 {t[0]} {t[1]} {t[2]}\n".encode())


def write_obj(path, pieces, texture=None, vertex_colours=False, groups=True):
    """OBJ + MTL beside it: one `o` and material per piece (or all pieces in one object when
    `groups` is False); `texture` is the file name map_Kd names, for pieces that have uvs."""
    stem = os.path.splitext(os.path.basename(path))[0]
    with open(os.path.join(os.path.dirname(path), stem + ".mtl"), "w") as mtl:
        for p in pieces:
            mtl.write(
                f"newmtl {p.name}\nKd {p.colour[0]:.4f} {p.colour[1]:.4f} {p.colour[2]:.4f}\n"
            )
            mtl.write("Ka 0 0 0\nKs 0 0 0\nd 1\nillum 1\n")
            if texture and p.uvs is not None:
                mtl.write(f"map_Kd {texture}\n")
            mtl.write("\n")
    with open(path, "w") as f:
        f.write(f"# PopUp corpus\nmtllib {stem}.mtl\n")
        offset, uv_offset = 1, 1
        if not groups:
            f.write(f"o {stem}\n")
        for p in pieces:
            if groups:
                f.write(f"o {p.name}\n")
            rgb = p.colours if p.colours is not None else np.tile(p.colour, (len(p.vertices), 1))
            for v, c in zip(p.vertices, rgb):
                colour = f" {c[0]:.4f} {c[1]:.4f} {c[2]:.4f}" if vertex_colours else ""
                f.write(f"v {v[0]:.6f} {v[1]:.6f} {v[2]:.6f}{colour}\n")
            if p.uvs is not None:
                for uv in p.uvs:
                    f.write(f"vt {uv[0]:.6f} {uv[1]:.6f}\n")
            f.write(f"usemtl {p.name}\n")
            for t in p.triangles:
                if p.uvs is not None:
                    i, j = t + offset, t + uv_offset
                    f.write(f"f {i[0]}/{j[0]} {i[1]}/{j[1]} {i[2]}/{j[2]}\n")
                else:
                    i = t + offset
                    f.write(f"f {i[0]} {i[1]} {i[2]}\n")
            offset += len(p.vertices)
            uv_offset += 0 if p.uvs is None else len(p.uvs)


def write_tga(path, rgb):
    """Uncompressed 24-bit TGA (type 2), rows from the bottom: rgb is H x W x 3 uint8, top row first."""
    h, w, _ = rgb.shape
    header = struct.pack("<BBBHHBHHHHBB", 0, 0, 2, 0, 0, 0, 0, 0, w, h, 24, 0)
    with open(path, "wb") as f:
        f.write(header + np.ascontiguousarray(rgb[::-1, :, ::-1]).tobytes())


def write_bmp(path, rgb):
    from PIL import Image

    Image.fromarray(rgb, "RGB").save(path, format="BMP")


def png_bytes(rgb):
    from PIL import Image

    buffer = io.BytesIO()
    Image.fromarray(rgb, "RGB").save(buffer, format="PNG")
    return buffer.getvalue()


class _Buffer:
    """The binary chunk of a GLB: accessors appended 4-byte aligned."""

    def __init__(self):
        self.data, self.views, self.accessors = bytearray(), [], []

    def view(self, raw, target=None):
        while len(self.data) % 4:
            self.data.append(0)
        view = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(raw)}
        if target:
            view["target"] = target
        self.views.append(view)
        self.data += raw
        return len(self.views) - 1

    def accessor(self, array, kind, component, target, bounds=False):
        view = self.view(array.tobytes(), target)
        entry = {"bufferView": view, "componentType": component, "count": len(array), "type": kind}
        if bounds:
            entry["min"] = array.min(axis=0).tolist()
            entry["max"] = array.max(axis=0).tolist()
        self.accessors.append(entry)
        return len(self.accessors) - 1


def write_glb(path, pieces, nodes=None, texture_png=None):
    """Binary glTF 2.0: one mesh per piece, materials from colours, COLOR_0 where a piece has
    vertex colours, TEXCOORD_0 and the embedded PNG `texture_png` where it has uvs. `nodes`:
    (piece index, translation, rotation quaternion xyzw) per node, so a mesh may be placed twice
    (default one node per piece, unmoved)."""
    buffer, meshes, materials = _Buffer(), [], []
    for i, p in enumerate(pieces):
        attributes = {
            "POSITION": buffer.accessor(p.vertices.astype("<f4"), "VEC3", 5126, 34962, True)
        }
        material = {"name": p.name, "pbrMetallicRoughness": {"metallicFactor": 0.0}}
        material["pbrMetallicRoughness"]["baseColorFactor"] = list(p.colour) + [1.0]
        if p.colours is not None:
            attributes["COLOR_0"] = buffer.accessor(p.colours.astype("<f4"), "VEC3", 5126, 34962)
        if p.uvs is not None and texture_png is not None:
            flipped = np.column_stack([p.uvs[:, 0], 1.0 - p.uvs[:, 1]])  # glTF's v runs down
            attributes["TEXCOORD_0"] = buffer.accessor(flipped.astype("<f4"), "VEC2", 5126, 34962)
            material["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
            material["pbrMetallicRoughness"]["baseColorFactor"] = [1.0, 1.0, 1.0, 1.0]
        indices = buffer.accessor(p.triangles.astype("<u4").ravel(), "SCALAR", 5125, 34963)
        primitive = {"attributes": attributes, "indices": indices, "material": i, "mode": 4}
        meshes.append({"name": p.name, "primitives": [primitive]})
        materials.append(material)
    gltf = {"asset": {"version": "2.0", "generator": "PopUp tools/make_corpus.py"}}
    node_rows = nodes if nodes is not None else [(i, None, None) for i in range(len(pieces))]
    gltf["nodes"] = []
    for mesh, translation, rotation in node_rows:
        node = {"mesh": mesh, "name": pieces[mesh].name}
        if translation is not None:
            node["translation"] = [float(x) for x in translation]
        if rotation is not None:
            node["rotation"] = [float(x) for x in rotation]
        gltf["nodes"].append(node)
    gltf["scenes"] = [{"nodes": list(range(len(node_rows)))}]
    gltf["scene"] = 0
    gltf["meshes"], gltf["materials"] = meshes, materials
    if texture_png is not None:
        image_view = buffer.view(texture_png)
        gltf["images"] = [{"bufferView": image_view, "mimeType": "image/png"}]
        gltf["samplers"] = [{"magFilter": 9729, "minFilter": 9729}]
        gltf["textures"] = [{"source": 0, "sampler": 0}]
    while len(buffer.data) % 4:
        buffer.data.append(0)
    gltf["buffers"] = [{"byteLength": len(buffer.data)}]
    gltf["bufferViews"], gltf["accessors"] = buffer.views, buffer.accessors
    text = json.dumps(gltf, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    total = 12 + 8 + len(text) + 8 + len(buffer.data)
    with open(path, "wb") as f:
        f.write(struct.pack("<III", 0x46546C67, 2, total))
        f.write(struct.pack("<II", len(text), 0x4E4F534A) + text)
        f.write(struct.pack("<II", len(buffer.data), 0x004E4942) + bytes(buffer.data))


def _floats(values):
    return " ".join(f"{x:.6g}" for x in np.asarray(values).ravel())


def write_dae(path, pieces, unit_name, unit_metres, up_axis, nodes=None):
    """Collada 1.4 text: a geometry, effect and material per piece; `nodes` as (piece index,
    4 x 4 matrix) lets one geometry be placed several times (default each once, unmoved)."""
    effects, materials, geometries = [], [], []
    for i, p in enumerate(pieces):
        c = _floats(list(p.colour) + [1.0])
        effects.append(
            f'<effect id="fx{i}"><profile_COMMON><technique sid="common"><lambert>'
            f"<diffuse><color>{c}</color></diffuse></lambert></technique></profile_COMMON></effect>"
        )
        materials.append(
            f'<material id="mat{i}" name="{p.name}"><instance_effect url="#fx{i}"/></material>'
        )
        n = len(p.vertices)
        geometries.append(
            f'<geometry id="geo{i}" name="{p.name}"><mesh>'
            f'<source id="geo{i}-pos"><float_array id="geo{i}-pos-array" count="{3 * n}">'
            f"{_floats(p.vertices)}</float_array><technique_common>"
            f'<accessor source="#geo{i}-pos-array" count="{n}" stride="3">'
            '<param name="X" type="float"/><param name="Y" type="float"/>'
            '<param name="Z" type="float"/></accessor></technique_common></source>'
            f'<vertices id="geo{i}-vtx"><input semantic="POSITION" source="#geo{i}-pos"/></vertices>'
            f'<triangles material="m{i}" count="{len(p.triangles)}">'
            f'<input semantic="VERTEX" source="#geo{i}-vtx" offset="0"/>'
            f"<p>{' '.join(str(int(x)) for x in p.triangles.ravel())}</p></triangles>"
            "</mesh></geometry>"
        )
    scene = []
    for k, (i, matrix) in enumerate(
        nodes if nodes is not None else [(i, None) for i in range(len(pieces))]
    ):
        transform = "" if matrix is None else f"<matrix>{_floats(np.asarray(matrix))}</matrix>"
        scene.append(
            f'<node id="node{k}" name="{pieces[i].name}">{transform}'
            f'<instance_geometry url="#geo{i}"><bind_material><technique_common>'
            f'<instance_material symbol="m{i}" target="#mat{i}"/>'
            "</technique_common></bind_material></instance_geometry></node>"
        )
    text = (
        '<?xml version="1.0" encoding="utf-8"?>\n'
        '<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">\n'
        "<asset><contributor><authoring_tool>PopUp tools/make_corpus.py</authoring_tool>"
        f'</contributor><unit name="{unit_name}" meter="{unit_metres}"/>'
        f"<up_axis>{up_axis}</up_axis></asset>\n"
        f"<library_effects>{''.join(effects)}</library_effects>\n"
        f"<library_materials>{''.join(materials)}</library_materials>\n"
        f"<library_geometries>\n{chr(10).join(geometries)}\n</library_geometries>\n"
        f'<library_visual_scenes><visual_scene id="scene">{"".join(scene)}</visual_scene>'
        '</library_visual_scenes>\n<scene><instance_visual_scene url="#scene"/></scene>\n'
        "</COLLADA>\n"
    )
    with open(path, "w") as f:
        f.write(text)


def write_3mf(path, pieces, unit="millimeter"):
    """3MF package: one mesh object per piece, each placed once by the build."""
    objects, items = [], []
    for i, p in enumerate(pieces, start=1):
        vertices = "".join(
            f'<vertex x="{v[0]:.5f}" y="{v[1]:.5f}" z="{v[2]:.5f}"/>' for v in p.vertices
        )
        triangles = "".join(f'<triangle v1="{a}" v2="{b}" v3="{c}"/>' for a, b, c in p.triangles)
        objects.append(
            f'<object id="{i}" name="{p.name}" type="model"><mesh><vertices>{vertices}</vertices>'
            f"<triangles>{triangles}</triangles></mesh></object>"
        )
        items.append(f'<item objectid="{i}"/>')
    model = (
        '<?xml version="1.0" encoding="UTF-8"?>\n'
        f'<model unit="{unit}" xml:lang="en-US" '
        'xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02">'
        f"<resources>{''.join(objects)}</resources><build>{''.join(items)}</build></model>\n"
    )
    content_types = (
        '<?xml version="1.0" encoding="UTF-8"?>\n'
        '<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">'
        '<Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/>'
        '<Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/>'
        "</Types>\n"
    )
    rels = (
        '<?xml version="1.0" encoding="UTF-8"?>\n'
        '<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">'
        '<Relationship Target="/3D/3dmodel.model" Id="rel0" '
        'Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>\n'
    )
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as z:
        for name, text in (
            ("[Content_Types].xml", content_types),
            ("_rels/.rels", rels),
            ("3D/3dmodel.model", model),
        ):
            entry = zipfile.ZipInfo(name, date_time=(2024, 1, 1, 0, 0, 0))  # same bytes each run
            z.writestr(entry, text, zipfile.ZIP_DEFLATED)
