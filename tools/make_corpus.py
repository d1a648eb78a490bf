#!/usr/bin/python3
"""A realistic corpus for shape-from-model (issue 25 item 1): models with the defects real files
have, made here from FreeCAD solids and hand-written files, never taken elsewhere.

    /usr/bin/python3 tools/make_corpus.py --out DIR [NAME ...]      (`make corpus`: build/corpus)

Unlike tools/make_models.py's clean solids, every model keeps its parts apart (walls, roof, slabs,
wheels, inner parts written one after the other, unfused), sits on a ground larger than itself,
is open, single-sided or duplicated, or comes in metres, centimetres or inches, y or x up, far
from the origin, huge or tiny, textured from a TGA, a BMP, an embedded PNG or vertex colours.
docs/CORPUS.md describes each model. Importable: write_corpus_model(name, path) and CORPUS.

CORPUS[name] holds what the recipe knows: `file` (extension), `unit` and `up` of the file,
`defects` (tags, docs/CORPUS.md lists them), `parts` (pieces the recipe wrote; glTF and Collada
nodes count once per placement), `min_components` (connected parts assimp's mesh must show at
least: pieces in a file that keeps objects apart, fewer where a concatenated STL, PLY or OFF
joins touching corners), `open` (border edges expected), `texture` (the image file written
beside the model, or None), `bbox` (min and max corners as assimp gives them, NaN where the
recipe does not know the value, e.g. a random tree crown), `scale` (assimp's unit conversion:
Collada's <unit> is applied, so the windmill loads in metres) and `answers` (walls box, roof
ridge, slab ...: (min, max) corners in the file's own units and axes).
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import corpus_buildings as buildings  # noqa: E402
import corpus_objects as objects  # noqa: E402
import corpus_writers as writers  # noqa: E402
from corpus_shapes import box_to_file  # noqa: E402

NAN = math.nan


def _entry(build, file, unit, up, defects, parts, components, bbox, **extra):
    """One CORPUS row; `bbox` and `answers` are design-frame (z up) boxes, turned into the
    file's axes and moved by `offset` here."""
    offset = extra.pop("offset", (0, 0, 0))
    answers = extra.pop("answers", {})
    return {
        "build": build,
        "file": file,
        "unit": unit,
        "up": up,
        "defects": tuple(defects.split()),
        "parts": parts,
        "min_components": components,
        "open": extra.pop("open", False),
        "texture": extra.pop("texture", None),
        "scale": extra.pop("scale", 1.0),
        "bbox": box_to_file(bbox[0], bbox[1], up, offset),
        "answers": {k: box_to_file(lo, hi, up, offset) for k, (lo, hi) in answers.items()},
        "summary": extra.pop("summary"),
    }


HOUSE = "separate-solids overlapping-solids window-holes ground-plate overhang "
CORPUS = {
    "house_gable": _entry(
        buildings.house_gable,
        "obj",
        "m",
        "+y",
        HOUSE + "gable-roof chimney material-colours",
        parts=9,
        components=9,
        bbox=((-7, -6, -0.5), (17, 14, 6.4)),
        answers=buildings.GABLE,
        summary="house, gable roof, terrain slab, walls apart",
    ),
    "house_hip": _entry(
        buildings.house_hip,
        "ply",
        "cm",
        "+z",
        HOUSE + "hip-roof porch chimney non-manifold vertex-colours",
        parts=12,
        components=9,
        bbox=((-600, -800, -40), (1800, 1400, 700)),
        answers=buildings.HIP,
        summary="house, hip roof, porch, terrain slab, walls apart",
    ),
    "shed_cabin": _entry(
        buildings.shed_cabin,
        "stl",
        "m",
        "+z",
        "separate-solids overlapping-solids window-holes shed-roof overhang thin-protrusions "
        "off-centre ascii-stl no-texture",
        parts=8,
        components=3,
        bbox=((-0.4, -2, 0), (6.4, 4.5, 3.6)),
        offset=buildings.SHED_OFFSET,
        answers=buildings.SHED,
        summary="cabin with a shed roof, 1.8 km from the origin",
    ),
    "apartment_blocks": _entry(
        buildings.apartment_blocks,
        "stl",
        "mm",
        "+z",
        "separate-solids several-blocks window-holes non-manifold duplicated-faces huge-scale "
        "no-texture",
        parts=69,
        components=1,
        bbox=((0, 0, 0), (36000, 30000, 16150)),
        answers=buildings.APARTMENT,
        summary="three blocks storey by storey (IFC-like)",
    ),
    "terrain_village": _entry(
        buildings.terrain_village,
        "glb",
        "m",
        "+y",
        "open-shell ground-plate separate-solids gable-roof vertex-colours",
        parts=9,
        components=9,
        bbox=((-120, -120, NAN), (120, 120, NAN)),
        open=True,
        summary="open terrain 240 m square, three houses and a tower",
    ),
    "open_roof_game": _entry(
        buildings.open_roof_game,
        "obj",
        "m",
        "+y",
        "open-shell single-sided inconsistent-winding gable-roof overhang vertex-colours",
        parts=2,
        components=2,
        bbox=((-0.4, -0.5, 0), (8.4, 6.5, 5.05)),
        open=True,
        summary="game cottage: quads for walls, the roof one sheet of triangles",
    ),
    "cottage_tga": _entry(
        buildings.cottage_tga,
        "obj",
        "cm",
        "+y",
        "texture-tga gable-roof overhang chimney separate-solids",
        parts=3,
        components=3,
        bbox=((-30, -30, 0), (630, 430, 520)),
        texture="cottage.tga",
        answers=buildings.COTTAGE,
        summary="cottage textured from a TGA (OBJ + MTL)",
    ),
    "barn_bmp": _entry(
        buildings.barn_bmp,
        "obj",
        "in",
        "+z",
        "texture-bmp gable-roof overhang separate-solids",
        parts=4,
        components=4,
        bbox=((-12, -12, 0), (672, 372, 492)),
        texture="barn.bmp",
        answers=buildings.BARN,
        summary="barn in inches textured from a BMP, a silo beside it",
    ),
    "vehicle": _entry(
        objects.vehicle,
        "glb",
        "m",
        "+y",
        "separate-wheels instanced-meshes overlapping-solids material-colours",
        parts=8,
        components=8,
        bbox=((0, -0.9, 0), (4.25, 0.9, 1.5)),
        answers=objects.VEHICLE,
        summary="car: body, cabin, lights, one wheel mesh placed 4 times",
    ),
    "engine": _entry(
        objects.engine,
        "3mf",
        "mm",
        "+z",
        "inner-parts hollow separate-solids overlapping-solids non-manifold no-texture",
        parts=18,
        components=18,
        bbox=((-60, -10, -60), (430, 210, 500)),
        answers=objects.ENGINE,
        summary="four-cylinder engine, hollow crankcase, parts inside",
    ),
    "statue_pedestal": _entry(
        objects.statue_pedestal,
        "stl",
        "in",
        "+z",
        "organic overlapping-solids ground-plate thin-protrusions off-centre ascii-stl",
        parts=9,
        components=9,
        bbox=((-8, -8, 0), (8, 8, 36)),
        offset=objects.STATUE_OFFSET,
        answers=objects.STATUE,
        summary="robed figure with a staff on a pedestal, unfused",
    ),
    "dog": _entry(
        objects.dog,
        "off",
        "cm",
        "+y",
        "organic thin-protrusions seam-cracks no-texture",
        parts=1,
        components=1,
        bbox=((-45.2, -13, 0), (54, 13, 77)),
        summary="dog of fused ellipsoids and cylinders",
    ),
    "spider": _entry(
        objects.spider,
        "stl",
        "mm",
        "+z",
        "organic thin-protrusions overlapping-solids no-texture",
        parts=18,
        components=10,
        bbox=((-15, -22.2, 0), (21.4, 22.2, 11.4)),
        summary="spider, eight legs of thin rods",
    ),
    "bust_scan": _entry(
        objects.bust_scan,
        "ply",
        "mm",
        "+z",
        "organic open-shell holes scan-noise vertex-colours",
        parts=1,
        components=1,
        bbox=((NAN, NAN, 0), (NAN, NAN, 320)),
        open=True,
        summary="scanned bust, open below, three holes, noise",
    ),
    "bust_scan_dense": _entry(
        objects.bust_scan_dense,
        "ply",
        "mm",
        "+z",
        "organic open-shell holes scan-noise vertex-colours dense-scan",
        parts=1,
        components=1,
        bbox=((NAN, NAN, 0), (NAN, NAN, 320)),
        open=True,
        summary="the bust as a modern scanner gives it: 30,529 vertices",
    ),
    "tree_cards": _entry(
        objects.tree_cards,
        "ply",
        "m",
        "+z",
        "many-border-edges single-sided open-shell vertex-colours ascii-ply",
        parts=2,
        components=601,
        bbox=((NAN, NAN, 0), (NAN, NAN, NAN)),
        open=True,
        summary="game tree: open trunk tube and 600 leaf cards",
    ),
    "print_bed_bracket": _entry(
        objects.print_bed_bracket,
        "stl",
        "mm",
        "+z",
        "ground-plate off-centre window-holes no-texture",
        parts=2,
        components=2,
        bbox=((0, 0, -3), (220, 220, 40)),
        answers={"bed": objects.BED, "bracket": objects.BRACKET},
        summary="L bracket on a 220 mm print bed",
    ),
    "watch_gear": _entry(
        objects.watch_gear,
        "obj",
        "m",
        "+z",
        "tiny-scale separate-solids no-texture",
        parts=3,
        components=3,
        bbox=((-0.006, -0.006, -0.002), (0.006, 0.006, 0.003)),
        summary="watch wheel 12 mm across, in metres",
    ),
    "bridge": _entry(
        objects.bridge,
        "ply",
        "mm",
        "+z",
        "huge-scale thin-protrusions separate-solids ascii-ply vertex-colours",
        parts=8,
        components=8,
        bbox=((-5000, -8000, -2000), (125000, 8000, 11100)),
        answers={"deck": objects.BRIDGE["deck"]},
        summary="road bridge 120 m long in millimetres",
    ),
    "windmill": _entry(
        objects.windmill,
        "dae",
        "cm",
        "+y",
        "thin-protrusions instanced-meshes unit-declared material-colours",
        parts=8,
        components=8,
        bbox=((NAN, -300, 0), (NAN, 300, NAN)),
        scale=0.01,
        summary="windmill, Collada in centimetres, four blades placed by matrices",
    ),
    "chair_x_up": _entry(
        objects.chair_x_up,
        "stl",
        "cm",
        "+x",
        "x-up separate-solids non-manifold no-texture",
        parts=8,
        components=2,
        bbox=((0, 0, 0), (45, 45, 95)),
        summary="chair exported with +x up",
    ),
    "bookshelf": _entry(
        objects.bookshelf,
        "obj",
        "cm",
        "+z",
        "duplicated-faces separate-solids one-object",
        parts=10,
        components=10,
        bbox=((0, 0, 0), (80, 31, 180)),
        summary="bookshelf, a shelf and the back written twice",
    ),
    "lighthouse": _entry(
        objects.lighthouse,
        "glb",
        "m",
        "+y",
        "texture-embedded ground-plate separate-solids",
        parts=5,
        components=5,
        bbox=((-14, -11, -3), (14, 11, 24.6)),
        answers=objects.LIGHTHOUSE,
        summary="striped lighthouse on a rock, PNG inside the GLB",
    ),
}
NAMES = tuple(CORPUS)


def _write_texture(folder, texture):
    name, rgb = texture
    path = os.path.join(folder, name)
    if name.endswith(".tga"):
        writers.write_tga(path, rgb)
    elif name.endswith(".bmp"):
        writers.write_bmp(path, rgb)
    return name


def write_corpus_model(name, path):
    """Writes corpus model `name` to `path` (its extension must be CORPUS[name]["file"]), with
    the texture image and MTL beside it where it has them; returns the path."""
    if name not in CORPUS:
        raise ValueError(f"corpus model {name!r}: must be one of {', '.join(NAMES)}")
    entry = CORPUS[name]
    extension = os.path.splitext(path)[1].lstrip(".").lower()
    if extension != entry["file"]:
        raise ValueError(
            f"{path}: corpus model {name} is written as .{entry['file']}, not .{extension}"
        )
    model = entry["build"]()
    pieces, folder = model["pieces"], os.path.dirname(os.path.abspath(path))
    texture = model.get("texture")
    if extension == "obj":
        image = _write_texture(folder, texture) if texture else None
        writers.write_obj(
            path,
            pieces,
            texture=image,
            vertex_colours="vertex-colours" in entry["defects"],
            groups="one-object" not in entry["defects"],
        )  # noqa: E501
    elif extension == "stl":
        (writers.write_stl_ascii if "ascii-stl" in entry["defects"] else writers.write_stl_binary)(
            path, pieces
        )
    elif extension == "ply":
        binary = "ascii-ply" not in entry["defects"]
        writers.write_ply(path, pieces, binary=binary, colours="vertex-colours" in entry["defects"])
    elif extension == "off":
        writers.write_off(path, pieces)
    elif extension == "glb":
        png = writers.png_bytes(texture[1]) if texture else None
        writers.write_glb(path, pieces, nodes=model.get("nodes"), texture_png=png)
    elif extension == "dae":
        writers.write_dae(path, pieces, "centimeter", 0.01, "Y_UP", nodes=model.get("nodes"))
    elif extension == "3mf":
        writers.write_3mf(path, pieces)
    return path


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("names", nargs="*", metavar="NAME", help=f"models (default all): {NAMES}")
    parser.add_argument("--out", required=True, metavar="DIR")
    args = parser.parse_args(argv)
    unknown = [n for n in args.names if n not in CORPUS]
    if unknown:
        print(
            f"make_corpus: unknown model {unknown[0]!r}: must be one of {', '.join(NAMES)}",
            file=sys.stderr,
        )
        return 2
    os.makedirs(args.out, exist_ok=True)
    for name in args.names or NAMES:
        path = write_corpus_model(name, os.path.join(args.out, f"{name}.{CORPUS[name]['file']}"))
        print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
