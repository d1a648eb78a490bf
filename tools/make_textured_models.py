#!/usr/bin/python3
"""Textured test models and texture files (issue 25 item 6), made here, never taken elsewhere.

    /usr/bin/python3 tools/make_textured_models.py --out tests/data/textures

One 32 x 16 texture of four solid 16 x 8 blocks (BLOCKS: red top-left, green top-right, blue
bottom-left, yellow bottom-right) written by Pillow in every format the tests decode: TGA
uncompressed (bottom-up, RGB) and RLE (top-down, RGBA), BMP, PNG, JPEG (quality 95, no chroma
subsampling), GIF and PPM. The blocks tell a flipped or mirrored decoding from a right one, and
solid blocks survive JPEG within a few levels at their centres.

Models: the cuboid [0, 60] x [0, 40] x [0, 30] mm (make_models.py's `cuboid`) whose six faces
each show the whole texture, upright seen from outside (uv (0, 0) at the face's lower-left):
OBJ + MTL naming the TGA, the BMP, a missing file and a corrupt PNG, and a binary glTF (.glb)
holding the PNG inside it (glTF's uv origin is the image's top-left, so v is written as 1 - v).

expected.json gives each image's size and the texels the tests compare (x, y from the top-left,
RGBA as written, and how far a decoder may stray: 0, or 4 for JPEG), so tests check decoders
against what was written, not against another decoder. Importable: tests call write_all(folder).
"""

import argparse
import json
import os
import re
import struct

import numpy as np
from PIL import Image

WIDTH, HEIGHT = 32, 16
# (column range, row range from the top, RGB) of each block.
BLOCKS = {
    "top_left": ((0, 16), (0, 8), (220, 40, 30)),
    "top_right": ((16, 32), (0, 8), (30, 170, 60)),
    "bottom_left": ((0, 16), (8, 16), (40, 60, 210)),
    "bottom_right": ((16, 32), (8, 16), (230, 200, 40)),
}
LOW, HIGH = (0.0, 0.0, 0.0), (60.0, 40.0, 30.0)  # the cuboid's corners, mm
JPEG_TOLERANCE = 4
# Block centres, the image's corners and both sides of each block edge.
PROBES = [(8, 4), (24, 4), (8, 12), (24, 12), (0, 0), (31, 0), (0, 15), (31, 15)]
EDGE_PROBES = [(15, 3), (16, 3), (5, 7), (5, 8), (15, 8), (16, 7)]
IMAGES = {
    # file: (Pillow save keywords, tolerance, probes)
    "texture.tga": ({}, 0, PROBES + EDGE_PROBES),
    "texture_rle.tga": ({"compression": "tga_rle", "orientation": 1}, 0, PROBES + EDGE_PROBES),
    "texture.bmp": ({}, 0, PROBES + EDGE_PROBES),
    "texture.png": ({}, 0, PROBES + EDGE_PROBES),
    "texture.jpg": ({"quality": 95, "subsampling": 0}, JPEG_TOLERANCE, PROBES[:4]),
    "texture.gif": ({}, 0, PROBES + EDGE_PROBES),
    "texture.ppm": ({}, 0, PROBES + EDGE_PROBES),
}
RGBA_IMAGES = {"texture_rle.tga"}  # written with an alpha channel (all 255)
CORRUPT_PNG = b"\x89PNG\r\n\x1a\n" + b"not the chunks of a PNG" * 4
# model file: (texture named by its material, what the test expects of it)
OBJ_MODELS = {
    "cube_tga.obj": "texture.tga",
    "cube_bmp.obj": "texture.bmp",
    "cube_missing.obj": "missing.tga",
    "cube_corrupt.obj": "corrupt.png",
}


def texels():
    """HEIGHT x WIDTH x 3 uint8, row 0 at the top."""
    image = np.zeros((HEIGHT, WIDTH, 3), dtype=np.uint8)
    for (x0, x1), (y0, y1), rgb in BLOCKS.values():
        image[y0:y1, x0:x1] = rgb
    return image


def write_images(folder):
    """Every IMAGES file and the corrupt PNG; returns expected.json's "images"."""
    rgb = texels()
    expected = {}
    for name, (keywords, tolerance, probes) in IMAGES.items():
        image = Image.fromarray(rgb, "RGB")
        if name in RGBA_IMAGES:
            image = image.convert("RGBA")
        elif name.endswith(".gif"):
            image = image.quantize(colors=4)  # the four block colours, exactly
        image.save(os.path.join(folder, name), **keywords)
        expected[name] = {
            "width": WIDTH,
            "height": HEIGHT,
            "tolerance": tolerance,
            "texels": [[x, y, *map(int, rgb[y, x]), 255] for x, y in probes],
        }
    with open(os.path.join(folder, "corrupt.png"), "wb") as f:
        f.write(CORRUPT_PNG)
    return expected


def cuboid_faces():
    """[(four corners counter-clockwise seen from outside, starting at the face's lower-left)]:
    the sides upright (z up), the top seen from above with +y up, the bottom from below."""
    (x0, y0, z0), (x1, y1, z1) = LOW, HIGH
    return [
        [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)],  # front, -y
        [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)],  # right, +x
        [(x1, y1, z0), (x0, y1, z0), (x0, y1, z1), (x1, y1, z1)],  # back, +y
        [(x0, y1, z0), (x0, y0, z0), (x0, y0, z1), (x0, y1, z1)],  # left, -x
        [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)],  # top, +z
        [(x0, y1, z0), (x1, y1, z0), (x1, y0, z0), (x0, y0, z0)],  # bottom, -z
    ]


CORNER_UVS = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]


def write_obj(folder, name, texture):
    """name (OBJ) and its MTL, whose one material's diffuse map is `texture`."""
    stem = os.path.splitext(name)[0]
    with open(os.path.join(folder, stem + ".mtl"), "w") as f:
        f.write(f"newmtl painted\nKd 0.8 0.8 0.8\nmap_Kd {texture}\n")
    lines = [f"mtllib {stem}.mtl", "usemtl painted"]
    lines += [f"vt {u:g} {v:g}" for u, v in CORNER_UVS]
    for face in cuboid_faces():
        lines += [f"v {x:g} {y:g} {z:g}" for x, y, z in face]
    for k in range(6):
        lines.append("f " + " ".join(f"{4 * k + i + 1}/{i + 1}" for i in range(4)))
    with open(os.path.join(folder, name), "w") as f:
        f.write("\n".join(lines) + "\n")


def padded(data, fill=b"\0"):
    return data + fill * (-len(data) % 4)


def write_glb(folder, name, image_bytes):
    """A binary glTF 2.0 of the cuboid with `image_bytes` (a PNG) as its embedded base colour."""
    positions, uvs, indices = [], [], []
    for face in cuboid_faces():
        k = len(positions)
        positions += face
        uvs += [(u, 1.0 - v) for u, v in CORNER_UVS]  # glTF: v = 0 is the image's top row
        indices += [k, k + 1, k + 2, k, k + 2, k + 3]
    views = [
        struct.pack(f"<{3 * len(positions)}f", *(c for p in positions for c in p)),
        struct.pack(f"<{2 * len(uvs)}f", *(c for uv in uvs for c in uv)),
        padded(struct.pack(f"<{len(indices)}H", *indices)),
        padded(image_bytes),
    ]
    offsets = np.cumsum([0] + [len(v) for v in views]).tolist()
    sizes = [len(views[0]), len(views[1]), 2 * len(indices), len(image_bytes)]
    gltf = {
        "asset": {"version": "2.0", "generator": "PopUp tools/make_textured_models.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [
            {
                "primitives": [
                    {"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}
                ]
            }
        ],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"wrapS": 10497, "wrapT": 10497}],
        "images": [{"bufferView": 3, "mimeType": "image/png"}],
        "buffers": [{"byteLength": offsets[-1]}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": offsets[i], "byteLength": sizes[i]} for i in range(4)
        ],
        "accessors": [
            {
                "bufferView": 0,
                "componentType": 5126,
                "count": len(positions),
                "type": "VEC3",
                "min": list(LOW),
                "max": list(HIGH),
            },
            {"bufferView": 1, "componentType": 5126, "count": len(uvs), "type": "VEC2"},
            {"bufferView": 2, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
        ],
    }
    text = padded(json.dumps(gltf, separators=(",", ":")).encode(), b" ")
    binary = b"".join(views)
    chunks = struct.pack("<I4s", len(text), b"JSON") + text
    chunks += struct.pack("<I4s", len(binary), b"BIN\0") + binary
    with open(os.path.join(folder, name), "wb") as f:
        f.write(struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks)


def write_all(folder):
    """Every image, model and expected.json into `folder` (made if missing); returns the path of
    expected.json."""
    os.makedirs(folder, exist_ok=True)
    expected = {"blocks": {k: list(v[2]) for k, v in BLOCKS.items()}}
    expected["images"] = write_images(folder)
    for name, texture in OBJ_MODELS.items():
        write_obj(folder, name, texture)
    with open(os.path.join(folder, "texture.png"), "rb") as f:
        write_glb(folder, "cube_png.glb", f.read())
    expected["models"] = {**OBJ_MODELS, "cube_png.glb": "*0"}
    path = os.path.join(folder, "expected.json")
    text = json.dumps(expected, indent=1)
    text = re.sub(r"\[[\d,\s]+\]", lambda m: " ".join(m.group(0).split()), text)  # a list a line
    with open(path, "w") as f:
        f.write(text + "\n")
    return path


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", required=True, help="folder to write into")
    args = parser.parse_args(argv)
    print(f"wrote {write_all(args.out)} and the files it describes")


if __name__ == "__main__":
    main()
