#!/usr/bin/python3
"""Pictures of the corpus (tools/make_corpus.py) as popupcore reads it back: one PNG per model
and a contact sheet of them all (docs/images/corpus.png).

    PYTHONPATH=build/python /usr/bin/python3 tools/corpus_previews.py --corpus build/corpus \
        --out build/corpus/previews [--sheet docs/images/corpus.png] [NAME ...]

Each model is turned back to z up (CORPUS's `up`), shaded by a light from the upper left, and
coloured as the file says: texture looked up at each triangle's mean uv, else vertex colours,
else the material's colour. matplotlib (python3-matplotlib) draws; PIL (python3-pil) composes.
"""

import argparse
import io
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402
from PIL import Image  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import popupcore  # noqa: E402

from corpus_shapes import AXES  # noqa: E402
from make_corpus import CORPUS, NAMES  # noqa: E402

LIGHT = np.array([-0.4, -0.6, 0.7]) / np.linalg.norm([-0.4, -0.6, 0.7])


def _texture_image(mesh):
    if mesh.texture_bytes:
        return np.asarray(Image.open(io.BytesIO(mesh.texture_bytes)).convert("RGB")) / 255.0
    if mesh.texture and os.path.exists(mesh.texture):
        return np.asarray(Image.open(mesh.texture).convert("RGB")) / 255.0
    return None


def face_colours(mesh):
    """One RGB per triangle: texture at the mean uv, else mean vertex colour, else base colour."""
    triangles = mesh.triangles
    image = _texture_image(mesh)
    if image is not None and len(mesh.uvs):
        uv = np.nan_to_num(mesh.uvs[triangles].mean(axis=1), nan=0.5) % 1.0
        h, w, _ = image.shape
        rows = np.clip(((1 - uv[:, 1]) * h).astype(int), 0, h - 1)
        cols = np.clip((uv[:, 0] * w).astype(int), 0, w - 1)
        return image[rows, cols]
    if len(mesh.colours):
        return mesh.colours[triangles].mean(axis=1)
    return np.tile(np.asarray(mesh.base_colour, dtype=float), (len(triangles), 1))


def render(name, path, out_png, size_px=480):
    """The model at `path` drawn z up from the front left, saved as out_png."""
    entry = CORPUS[name]
    mesh = popupcore.load_model(path)
    vertices = mesh.vertices @ AXES[entry["up"]]  # file axes back to z up
    corners = vertices[mesh.triangles]
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    length = np.linalg.norm(normals, axis=1, keepdims=True)
    normals = normals / np.where(length > 0, length, 1)
    shade = 0.35 + 0.65 * np.abs(normals @ LIGHT)  # single-sided sheets lit from both sides
    colours = np.clip(face_colours(mesh) * shade[:, None], 0, 1)
    figure = plt.figure(figsize=(size_px / 100, size_px / 100), dpi=100)
    axes = figure.add_subplot(projection="3d")
    axes.add_collection3d(Poly3DCollection(corners, facecolors=colours, edgecolors="none"))
    low, high = vertices.min(axis=0), vertices.max(axis=0)
    centre, half = (low + high) / 2, (high - low).max() / 2
    for set_limits, c in zip((axes.set_xlim, axes.set_ylim, axes.set_zlim), centre):
        set_limits(c - half, c + half)
    axes.set_box_aspect((1, 1, 1))
    axes.view_init(elev=22, azim=-60)
    axes.set_axis_off()
    axes.set_title(f"{name} ({entry['file']}, {entry['unit']}, up {entry['up']})", fontsize=9)
    figure.subplots_adjust(0, 0, 1, 1)
    figure.savefig(out_png)
    plt.close(figure)
    return out_png


def contact_sheet(pngs, out_png, columns=6, tile=200):
    """All previews in a grid of tile x tile thumbnails, as a palette PNG (small enough for git)."""
    rows = (len(pngs) + columns - 1) // columns
    sheet = Image.new("RGB", (columns * tile, rows * tile), "white")
    for k, png in enumerate(pngs):
        thumb = Image.open(png).convert("RGB").resize((tile, tile), Image.LANCZOS)
        sheet.paste(thumb, ((k % columns) * tile, (k // columns) * tile))
    sheet.quantize(colors=128, method=Image.MEDIANCUT).save(out_png, optimize=True)
    return out_png


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("names", nargs="*", metavar="NAME", help=f"models (default all): {NAMES}")
    parser.add_argument("--corpus", required=True, metavar="DIR", help="make_corpus.py's --out")
    parser.add_argument("--out", required=True, metavar="DIR")
    parser.add_argument("--sheet", metavar="PNG", help="also write the contact sheet here")
    args = parser.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    pngs = []
    for name in args.names or NAMES:
        if name not in CORPUS:
            print(
                f"corpus_previews: unknown model {name!r}: one of {', '.join(NAMES)}",
                file=sys.stderr,
            )
            return 2
        path = os.path.join(args.corpus, f"{name}.{CORPUS[name]['file']}")
        pngs.append(render(name, path, os.path.join(args.out, f"{name}.png")))
        print(f"drew {pngs[-1]}")
    if args.sheet:
        os.makedirs(os.path.dirname(os.path.abspath(args.sheet)), exist_ok=True)
        print(f"wrote {contact_sheet(pngs, args.sheet)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
