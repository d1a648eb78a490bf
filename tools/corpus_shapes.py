"""FreeCAD Part helpers for tools/make_corpus.py: solids built z up, meshed one by one into
corpus_writers.Piece, then turned into the file's axes (`up`) and moved off-centre (`offset`).

Every solid stays its own piece: nothing here fuses parts the recipe keeps apart.
"""

import math
import os
import sys

import numpy as np

sys.path.append(
    os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "Workbench")
)
from popupwb import freecad_version  # noqa: E402  (importable before FreeCAD)

FREECAD_LIB = freecad_version.freecad_lib_dir()
if FREECAD_LIB not in sys.path:
    sys.path.append(FREECAD_LIB)

import FreeCAD  # noqa: E402
import MeshPart  # noqa: E402
import Part  # noqa: E402

from corpus_writers import Piece  # noqa: E402

V = FreeCAD.Vector
Z = V(0, 0, 1)

# Rotations taking the design frame (z up, front -y) to a file's axes: +y up is the glTF and
# OBJ habit (front +z), +x up an exporter that got the axis wrong.
AXES = {
    "+z": np.eye(3),
    "+y": np.array([[1, 0, 0], [0, 0, 1], [0, -1, 0]], dtype=float),
    "+x": np.array([[0, 0, 1], [0, 1, 0], [-1, 0, 0]], dtype=float),
}


def to_file(points, up="+z", offset=(0, 0, 0)):
    """Design-frame points (N x 3) in the file's axes, moved by `offset` (file axes)."""
    return np.asarray(points, dtype=float) @ AXES[up].T + np.asarray(offset, dtype=float)


def box_to_file(lo, hi, up="+z", offset=(0, 0, 0)):
    """A design-frame box's (min, max) corners in the file's axes, rounded to 6 decimals; a NaN
    (a side the recipe does not know) stays NaN on the axis it turns into."""
    lo_out, hi_out = [], []
    for row, shift in zip(AXES[up], offset):
        j = int(np.argmax(np.abs(row)))
        a, b = (lo[j], hi[j]) if row[j] > 0 else (-hi[j], -lo[j])
        lo_out.append(round(a + shift, 6))
        hi_out.append(round(b + shift, 6))
    return tuple(lo_out), tuple(hi_out)


def box(lo, hi):
    return Part.makeBox(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], V(*lo))


def cut(solid, holes):
    """`solid` with every box of `holes` ((lo, hi) pairs) cut through it: real openings."""
    if not holes:
        return solid
    tools = [box(lo, hi) for lo, hi in holes]
    return solid.cut(tools[0] if len(tools) == 1 else Part.Compound(tools))


def polyhedron(points, faces):
    """A solid from corner points and faces (index lists, any orientation)."""
    polygons = []
    for face in faces:
        loop = [V(*points[i]) for i in face]
        polygons.append(Part.Face(Part.makePolygon(loop + [loop[0]])))
    solid = Part.Solid(Part.Shell(polygons))
    if solid.Volume < 0:
        solid.reverse()
    return solid


def extrude_yz(profile, x0, length):
    """A prism whose section in the plane x = x0 is `profile` ((y, z) points), along +x."""
    loop = [V(x0, y, z) for y, z in profile]
    return Part.Face(Part.makePolygon(loop + [loop[0]])).extrude(V(length, 0, 0))


def extrude_xz(profile, y0, length):
    """A prism whose section in the plane y = y0 is `profile` ((x, z) points), along +y."""
    loop = [V(x, y0, z) for x, z in profile]
    return Part.Face(Part.makePolygon(loop + [loop[0]])).extrude(V(0, length, 0))


def hip_roof(lo, hi, z0, rise):
    """A solid hip roof over the rectangle lo..hi (x, y) from z0: the ridge runs along x, the
    four slopes at the same pitch, so the ridge is (hi - lo).x - (hi - lo).y long."""
    half = 0.5 * (hi[1] - lo[1])
    ym, zt = lo[1] + half, z0 + rise
    p = [
        (lo[0], lo[1], z0),
        (hi[0], lo[1], z0),
        (hi[0], hi[1], z0),
        (lo[0], hi[1], z0),
        (lo[0] + half, ym, zt),
        (hi[0] - half, ym, zt),
    ]
    return polyhedron(p, [(0, 1, 2, 3), (0, 1, 5, 4), (3, 2, 5, 4), (0, 4, 3), (1, 2, 5)])


def ellipsoid(centre, radii):
    matrix = FreeCAD.Matrix()
    matrix.scale(*radii)
    matrix.move(V(*centre))
    return Part.makeSphere(1.0).transformGeometry(matrix)


def rod(p0, p1, radius):
    """A cylinder from p0 to p1."""
    a, b = V(*p0), V(*p1)
    return Part.makeCylinder(radius, (b - a).Length, a, b - a)


def frustum(r0, r1, height, base=(0, 0, 0)):
    return Part.makeCone(r0, r1, height, V(*base), Z)


def fuse(shapes):
    solid = shapes[0]
    for other in shapes[1:]:
        solid = solid.fuse(other)
    return solid.removeSplitter()


def mesh_arrays(shape, deflection, angular=0.35):
    mesh = MeshPart.meshFromShape(
        Shape=shape, LinearDeflection=deflection, AngularDeflection=angular, Relative=False
    )
    points, facets = mesh.Topology
    return np.array([(p.x, p.y, p.z) for p in points], dtype=float), np.array(
        facets, dtype=np.int64
    )


def piece(name, shape, colour, deflection, up="+z", offset=(0, 0, 0)):
    """The solid meshed on its own, in the file's axes."""
    if not shape.isValid():
        raise RuntimeError(f"corpus piece {name}: the Part shape is not valid")
    vertices, triangles = mesh_arrays(shape, deflection)
    return Piece(name, to_file(vertices, up, offset), triangles, colour)


def sheet(name, quads, colour, up="+z", offset=(0, 0, 0), flip=()):
    """Single-sided quads ((4 corner points) each, two triangles), no thickness: game and scan
    geometry. Quads whose index is in `flip` wind the other way (inconsistent normals)."""
    vertices, triangles = [], []
    for k, quad in enumerate(quads):
        base = len(vertices)
        vertices.extend(quad)
        tris = [(0, 1, 2), (0, 2, 3)] if len(quad) == 4 else [(0, 1, 2)]
        for t in tris:
            t = t[::-1] if k in flip else t
            triangles.append(tuple(base + i for i in t))
    return Piece(name, to_file(vertices, up, offset), triangles, colour)


def box_uvs(design_vertices, scale, v_range=(0.0, 1.0)):
    """Planar uvs per triangle from the design-frame corners: each face projected on the plane
    its normal is closest to, `scale` units to one texture repeat, v squeezed into v_range."""
    corners = design_vertices.reshape(-1, 3, 3)
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    dominant = np.argmax(np.abs(normals), axis=1)
    uv = np.zeros((len(design_vertices), 2))
    planes = {0: (1, 2), 1: (0, 2), 2: (0, 1)}
    for t, axis in enumerate(dominant):
        a, b = planes[int(axis)]
        rows = slice(3 * t, 3 * t + 3)
        uv[rows, 0] = design_vertices[rows, a] / scale
        uv[rows, 1] = design_vertices[rows, b] / scale
    uv = uv - np.floor(uv.min(axis=0))
    span = max(uv[:, 1].max(), 1e-9)
    uv[:, 1] = v_range[0] + (v_range[1] - v_range[0]) * uv[:, 1] / span
    uv[:, 0] = np.mod(uv[:, 0], 1.0)
    return uv


def textured_piece(name, shape, deflection, scale, v_range, up="+z", offset=(0, 0, 0)):
    """A solid meshed with a corner per triangle and planar uvs in v_range of the texture."""
    vertices, triangles = mesh_arrays(shape, deflection)
    design = vertices[triangles.reshape(-1)]
    uvs = box_uvs(design, scale, v_range)
    return Piece(
        name, to_file(design, up, offset), np.arange(len(design)).reshape(-1, 3), (1, 1, 1), uvs=uvs
    )


def heightfield(name, lo, hi, cells, height, colour_of, up="+z", offset=(0, 0, 0)):
    """An open terrain surface over lo..hi (x, y) in `cells` x `cells` squares, z = height(x, y),
    coloured per vertex by colour_of(z): one sheet, border edges all round."""
    xs = np.linspace(lo[0], hi[0], cells + 1)
    ys = np.linspace(lo[1], hi[1], cells + 1)
    gx, gy = np.meshgrid(xs, ys, indexing="ij")
    gz = height(gx, gy)
    vertices = np.column_stack([gx.ravel(), gy.ravel(), gz.ravel()])
    index = np.arange((cells + 1) ** 2).reshape(cells + 1, cells + 1)
    a, b = index[:-1, :-1].ravel(), index[1:, :-1].ravel()
    c, d = index[1:, 1:].ravel(), index[:-1, 1:].ravel()
    triangles = np.vstack([np.column_stack([a, b, c]), np.column_stack([a, c, d])])
    colours = np.array([colour_of(z) for z in vertices[:, 2]])
    return Piece(
        name, to_file(vertices, up, offset), triangles, colours.mean(axis=0), colours=colours
    )


def rotation_quaternion(axis, degrees):
    """(x, y, z, w) of a rotation by `degrees` about `axis`."""
    axis = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    half = math.radians(degrees) / 2
    return tuple(axis * math.sin(half)) + (math.cos(half),)
