#!/usr/bin/python3
"""Test and sample models for shape-from-model (issue 12 §5), made here, never taken elsewhere.

    /usr/bin/python3 tools/make_models.py --out DIR [--format stl|ast|obj|ply|off|3mf] [NAME ...]
    /usr/bin/python3 tools/make_models.py --out resources/samples --format stl truck

Each model is a FreeCAD Part solid (boxes, prisms, spheres, cylinders fused), meshed with
MeshPart.meshFromShape and written with FreeCAD's Mesh module, whose format follows the extension
(stl is binary STL, ast ASCII STL). Lengths are millimetres; z is up and the model's front faces
-y (FreeCAD's front view), so `popup fit --up 0,0,1 --facing 0,-1,0` keeps the intended view.
`defective` is written by hand as OBJ text: a cuboid with a hole, flipped faces, degenerate and
duplicate triangles, for the repair path.

BOXES gives the known answer of each blocky model (its boxes and prisms, min and max corners),
so tests compare fitted dimensions with what the model was made of, not with the fitter's output.
Importable: tests call write_model(name, path) into their tmp folders.
"""

import argparse
import os
import sys

sys.path.append(
    os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "Workbench")
)
from popupwb import freecad_version  # noqa: E402  (importable before FreeCAD)

FREECAD_LIB = freecad_version.freecad_lib_dir()
if FREECAD_LIB not in sys.path:
    sys.path.append(FREECAD_LIB)

import FreeCAD  # noqa: E402
import Mesh  # noqa: E402
import MeshPart  # noqa: E402
import Part  # noqa: E402

V = FreeCAD.Vector
FORMATS = ("stl", "ast", "obj", "ply", "off", "3mf")
LINEAR_DEFLECTION = 0.2  # mm: curved models tessellate finely enough to look round
ANGULAR_DEFLECTION = 0.3  # radians

# Known parts of the blocky models: (kind, (xmin, ymin, zmin), (xmax, ymax, zmax)); a "prism" is a
# triangular prism whose ridge runs along x over the middle of its y extent, apex at zmax.
BOXES = {
    "cuboid": [("box", (0, 0, 0), (60, 40, 30))],
    "house": [("box", (0, 0, 0), (60, 40, 30)), ("prism", (0, 0, 30), (60, 40, 50))],
    "truck": [
        ("box", (0, 0, 0), (100, 40, 12)),  # chassis
        ("box", (0, 0, 12), (62, 40, 48)),  # cargo box at the back
        ("box", (68, 0, 12), (100, 40, 38)),  # cab at the front (+x)
    ],
    "tent": [("prism", (0, 0, 0), (60, 40, 30))],
    "l_building": [("box", (0, 0, 0), (60, 20, 30)), ("box", (0, 0, 0), (20, 50, 30))],
    # A slab 0.4 mm thick: nothing on it stands up far enough to be a mechanism (no design).
    "plate": [("box", (0, 0, 0), (80, 60, 0.4))],
}


def _box(lo, hi):
    return Part.makeBox(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], V(*lo))


def _prism(lo, hi):
    """Triangular prism, ridge along x at the middle of y, apex at hi[2]."""
    mid = 0.5 * (lo[1] + hi[1])
    triangle = Part.makePolygon(
        [
            V(lo[0], lo[1], lo[2]),
            V(lo[0], hi[1], lo[2]),
            V(lo[0], mid, hi[2]),
            V(lo[0], lo[1], lo[2]),
        ]
    )
    return Part.Face(triangle).extrude(V(hi[0] - lo[0], 0, 0))


def _fuse(shapes):
    """The parts fused one by one; when that is no valid solid (OCCT 7.8, FreeCAD 1.0: the
    figure's spheres and cylinders), fused all at once, which OCCT 7.6 refuses for some models."""
    solid = shapes[0]
    for other in shapes[1:]:
        solid = solid.fuse(other)
    solid = solid.removeSplitter()
    if not solid.isValid():
        solid = shapes[0].multiFuse(shapes[1:]).removeSplitter()
    return solid


def blocky(name):
    """The solid of one of BOXES' models."""
    return _fuse(
        [_box(lo, hi) if kind == "box" else _prism(lo, hi) for kind, lo, hi in BOXES[name]]
    )


def blob():
    """Three overlapping ellipsoids: smooth, no flat face, no symmetry the fitter could lean on."""
    parts = []
    for centre, radii in (
        ((0, 0, 22), (30, 22, 20)),
        ((22, 6, 30), (18, 16, 16)),
        ((-18, -4, 16), (16, 14, 14)),
    ):
        sphere = Part.makeSphere(1.0)
        matrix = FreeCAD.Matrix()
        matrix.scale(*radii)
        matrix.move(V(*centre))
        parts.append(sphere.transformGeometry(matrix))
    return _fuse(parts)


def figure():
    """A standing figure of spheres and cylinders: legs, body, arms and head."""
    z_axis, x_axis = V(0, 0, 1), V(1, 0, 0)
    parts = [
        Part.makeCylinder(5, 40, V(-8, 0, 0), z_axis),  # legs
        Part.makeCylinder(5, 40, V(8, 0, 0), z_axis),
        Part.makeCylinder(14, 35, V(0, 0, 38), z_axis),  # body
        Part.makeCylinder(4, 56, V(-28, 0, 66), x_axis),  # arms, straight out
        Part.makeSphere(11, V(0, 0, 84)),  # head
        Part.makeSphere(6, V(-8, 0, 0)),  # feet
        Part.makeSphere(6, V(8, 0, 0)),
    ]
    return _fuse(parts)


def truck_with_wheels():
    """The sample: the truck of BOXES on four wheels (the round outlines profiles should keep)."""
    body = blocky("truck")
    body.translate(V(0, 0, 8))  # the chassis rides on the wheels' axles
    wheels = [Part.makeCylinder(10, 6, V(x, y, 10), V(0, 1, 0)) for x in (18, 82) for y in (-4, 38)]
    return _fuse([body] + wheels)


def arched_block():
    """A 40 x 60 x 40 block whose bottom corners along y are rounded (radius 10): a known outline
    for profiles (seen along x, a rectangle with two quarter circles cut out)."""
    top = _box((0, 0, 10), (40, 60, 40))
    middle = _box((0, 10, 0), (40, 50, 10))
    arches = [Part.makeCylinder(10, 40, V(0, y, 10), V(1, 0, 0)) for y in (10, 50)]
    return _fuse([top, middle] + arches)


SOLIDS = {
    "arched_block": arched_block,
    "cuboid": lambda: blocky("cuboid"),
    "house": lambda: blocky("house"),
    "truck": lambda: blocky("truck"),
    "tent": lambda: blocky("tent"),
    "l_building": lambda: blocky("l_building"),
    "plate": lambda: blocky("plate"),
    "blob": blob,
    "figure": figure,
    "truck_with_wheels": truck_with_wheels,
}

# A unit-free cuboid 60 x 40 x 30 as OBJ text with every defect the cleaning step repairs:
# the top's two triangles missing (a hole), two side triangles flipped, a zero-area triangle with
# a repeated vertex, a collinear (needle) one, a duplicated triangle and duplicated vertices.
DEFECTIVE_OBJ = """\
# PopUp defective test mesh: hole, flipped faces, degenerate and duplicate triangles
v 0 0 0
v 60 0 0
v 60 40 0
v 0 40 0
v 0 0 30
v 60 0 30
v 60 40 30
v 0 40 30
v 60 0 0
v 30 0 0
# bottom (z = 0), outward normal -z
f 1 3 2
f 1 4 3
# top (z = 30) left out: a hole
# front (y = 0), outward -y; the second triangle flipped
f 1 2 6
f 1 5 6
# back (y = 40), outward +y
f 4 7 3
f 4 8 7
# left (x = 0), outward -x; the first triangle flipped
f 1 8 4
f 1 5 8
# right (x = 60), outward +x, the second through a duplicated vertex (9 = 2)
f 2 3 7
f 9 7 6
# a zero-area triangle (repeated vertex), a needle (collinear) and a duplicated face
f 1 1 2
f 1 10 2
f 4 7 3
"""


def mesh_of(shape):
    return MeshPart.meshFromShape(
        Shape=shape,
        LinearDeflection=LINEAR_DEFLECTION,
        AngularDeflection=ANGULAR_DEFLECTION,
        Relative=False,
    )


NAMES = tuple(SOLIDS) + ("defective",)


def write_model(name, path):
    """Writes model `name` to `path` (format from the extension); returns the path."""
    if name == "defective":
        if not path.lower().endswith(".obj"):
            raise ValueError(f"defective: path {path!r} must end in .obj (it is written by hand)")
        with open(path, "w") as f:
            f.write(DEFECTIVE_OBJ)
        return path
    if name not in SOLIDS:
        raise ValueError(f"model {name!r}: must be one of {', '.join(NAMES)}")
    extension = os.path.splitext(path)[1].lstrip(".").lower()
    if extension not in FORMATS:
        raise ValueError(f"{path}: extension .{extension}, must be one of {', '.join(FORMATS)}")
    shape = SOLIDS[name]()
    if not shape.isValid() or shape.Volume <= 0:
        raise RuntimeError(f"model {name}: the Part solid is not valid")
    mesh_of(shape).write(path)
    return path


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("names", nargs="*", metavar="NAME", help=f"models (default all): {NAMES}")
    parser.add_argument("--out", required=True, metavar="DIR")
    parser.add_argument("--format", default="stl", choices=FORMATS)
    args = parser.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    for name in args.names or NAMES:
        extension = "obj" if name == "defective" else args.format
        try:
            path = write_model(name, os.path.join(args.out, f"{name}.{extension}"))
        except ValueError as e:
            print(f"make_models: {e}", file=sys.stderr)
            return 2
        print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
