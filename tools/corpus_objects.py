"""Vehicles, machines, figures, furniture and scans of tools/make_corpus.py.

Each recipe returns {"pieces": [...]} (with "nodes" when the file places a mesh several times,
"texture" when it has one) in the file's units and axes; the constants are CORPUS's answers.
"""

import math

import numpy as np

from corpus_shapes import (
    Piece,
    box,
    ellipsoid,
    extrude_xz,
    extrude_yz,
    frustum,
    fuse,
    piece,
    rod,
    rotation_quaternion,
    sheet,
    textured_piece,
    to_file,
)

import FreeCAD  # noqa: E402  (on the path through corpus_shapes)
import Part  # noqa: E402

V = FreeCAD.Vector
STEEL, DARK, RED = (0.6, 0.62, 0.65), (0.12, 0.12, 0.12), (0.75, 0.1, 0.1)
CONCRETE_BRIDGE, TILE_WM = (0.72, 0.72, 0.7), (0.45, 0.2, 0.15)

# vehicle, metres: a car 4.2 m long, wheels of radius 0.35 at x 0.8 and 3.4, track 1.6 m.
WHEEL_CENTRES = [(x, y, 0.35) for x in (0.8, 3.4) for y in (-0.8, 0.8)]
VEHICLE = {
    "wheel_front_right": ((3.05, -0.9, 0), (3.75, -0.7, 0.7)),
    "cabin_top": ((1.6, -0.75, 1.5), (2.8, 0.75, 1.5)),
}


def vehicle(up="+y"):
    """Body and cabin (overlapping solids), two headlights, and one wheel mesh (tyre and hub)
    placed four times by glTF nodes, the left pair turned half round."""
    body = extrude_xz(
        [(0, 0.3), (4.2, 0.3), (4.2, 0.8), (3.9, 1.0), (0.1, 1.0), (0, 0.8)], -0.85, 1.7
    )
    cabin = extrude_xz([(1.2, 0.95), (3.3, 0.95), (2.8, 1.5), (1.6, 1.5)], -0.75, 1.5)
    tyre = Part.makeTorus(0.25, 0.1, V(0, 0, 0), V(0, 1, 0))
    hub = Part.makeCylinder(0.2, 0.18, V(0, -0.09, 0), V(0, 1, 0))
    pieces = [
        piece("body", body, RED, 0.01, up),
        piece("cabin", cabin, (0.3, 0.4, 0.5), 0.01, up),
        piece("headlight_r", box((4.15, -0.7, 0.65), (4.25, -0.45, 0.8)), (1, 1, 0.8), 0.01, up),
        piece("headlight_l", box((4.15, 0.45, 0.65), (4.25, 0.7, 0.8)), (1, 1, 0.8), 0.01, up),
        piece("wheel", fuse([tyre, hub]), DARK, 0.01, up),
    ]
    turn = rotation_quaternion(to_file([(0, 0, 1)], up)[0], 180)
    nodes = [(i, None, None) for i in range(4)]
    nodes += [(4, to_file([c], up)[0], turn if c[1] > 0 else None) for c in WHEEL_CENTRES]
    return {"pieces": pieces, "nodes": nodes}


# engine, millimetres: a four-cylinder block; the crankcase is hollow and holds the inner parts.
ENGINE = {
    "crankcase": ((0, 0, 0), (400, 200, 250)),
    "crank_axis": ((-60, 100, 120), (430, 100, 120)),
}
BORES = (70, 160, 250, 340)


def engine(up="+z"):
    """Crankcase (a hollow solid), cylinder block with four open bores, head, oil pan, flywheel and
    crankshaft sticking out through the case, and inside: four pistons, rods and crank webs."""
    p = lambda name, shape, colour: piece(name, shape, colour, 0.8, up)  # noqa: E731
    case = box(*ENGINE["crankcase"]).cut(box((15, 15, 15), (385, 185, 235)))
    block = box((20, 20, 250), (380, 180, 450))
    block = block.cut(Part.Compound([rod((x, 100, 249), (x, 100, 451), 40) for x in BORES]))
    pieces = [
        p("crankcase", case, STEEL),
        p("cylinder_block", block, STEEL),
        p("head", box((20, 20, 450), (380, 180, 500)), (0.5, 0.5, 0.55)),
        p("oil_pan", box((30, 30, -60), (370, 170, 0)), DARK),
        p("crankshaft", rod(*ENGINE["crank_axis"], 15), (0.8, 0.8, 0.8)),
        p("flywheel", rod((-60, 100, 120), (-30, 100, 120), 110), DARK),
    ]
    for k, x in enumerate(BORES):
        pieces += [
            p(f"piston_{k}", rod((x, 100, 330), (x, 100, 390), 38), (0.85, 0.85, 0.8)),
            p(f"rod_{k}", box((x - 8, 92, 140), (x + 8, 108, 350)), (0.7, 0.7, 0.7)),
            p(f"web_{k}", box((x - 30, 80, 95), (x - 20, 120, 165)), (0.7, 0.7, 0.7)),
        ]
    return {"pieces": pieces}


# statue_pedestal, inches, moved to (40, 25, 0) in the room's plan.
STATUE_OFFSET = (40.0, 25.0, 0.0)
STATUE = {
    "pedestal": ((-8, -8, 0), (8, 8, 4)),
    "plinth": ((-6, -6, 4), (6, 6, 10)),
    "staff": ((5.2, 0, 10), (5.2, 0, 36)),
}


def statue_pedestal(up="+z"):
    """A robed figure with a raised staff on a stepped pedestal wider than it: every primitive
    (robe, torso, head, neck, arms, staff) its own solid, overlapping, unfused."""
    p = lambda name, shape: piece(
        name, shape, (0.78, 0.76, 0.72), 0.03, up, STATUE_OFFSET
    )  # noqa: E731
    return {
        "pieces": [
            p("pedestal", box(*STATUE["pedestal"])),
            p("plinth", box(*STATUE["plinth"])),
            p("robe", frustum(4.0, 2.6, 10.0, (0, 0, 10))),
            p("torso", ellipsoid((0, 0, 23), (3.0, 2.0, 4.5))),
            p("neck", rod((0, 0, 26.5), (0, 0, 28.5), 0.8)),
            p("head", ellipsoid((0, 0, 29.8), (1.6, 1.8, 2.0))),
            p("arm_raised", rod((2.6, 0, 25.5), (5.0, 0, 30.5), 0.7)),
            p("arm_down", rod((-2.6, 0, 25.5), (-4.2, 0.6, 19.0), 0.7)),
            p("staff", rod(*STATUE["staff"], 0.25)),
        ]
    }


# dog, centimetres, y up (design z up): standing on the ground at 0, facing +x.
def dog(up="+y"):
    """One fused solid of ellipsoids, spheres and cylinders: body, head, snout, ears, four legs
    with paws and a thin tail."""
    parts = [
        ellipsoid((0, 0, 45), (30, 13, 14)),
        ellipsoid((36, 0, 62), (10, 9, 10)),
        ellipsoid((46, 0, 58), (8, 5, 5)),
        ellipsoid((33, 6, 71), (3, 2, 6)),
        ellipsoid((33, -6, 71), (3, 2, 6)),
        rod((28, 0, 50), (36, 0, 60), 7),
        rod((-28, 0, 50), (-44, 0, 66), 1.6),
    ]
    for x in (-18, 18):
        for y in (-7, 7):
            parts += [rod((x, y, 46), (x, y, 3), 4), ellipsoid((x + 2, y, 3), (6, 4.5, 3))]
    body = parts[0].multiFuse(parts[1:]).removeSplitter()
    return {"pieces": [piece("dog", body, (0.6, 0.45, 0.3), 0.4, up)]}


def spider(up="+z"):
    """Abdomen and cephalothorax ellipsoids and eight legs of two thin segments (radius 0.4 mm)
    each, as separate solids: thin protrusions over 50 mm, millimetres."""
    p = lambda name, shape: piece(name, shape, DARK, 0.05, up)  # noqa: E731
    pieces = [
        p("abdomen", ellipsoid((-8, 0, 6), (7, 5.5, 5))),
        p("cephalothorax", ellipsoid((3, 0, 5), (4.5, 3.8, 3))),
    ]
    for k, angle in enumerate((35, 70, 105, 140)):
        for side in (-1, 1):
            a = math.radians(angle)
            root = (3 + 2.0 * math.cos(a), side * 2.5, 5)
            out = (math.cos(a), side * math.sin(a))
            knee = (root[0] + 9 * out[0], root[1] + 9 * out[1], 11)
            foot = (root[0] + 20 * out[0], root[1] + 20 * out[1], 0.4)
            pieces.append(p(f"femur_{k}_{side}", rod(root, knee, 0.4)))
            pieces.append(p(f"tibia_{k}_{side}", rod(knee, foot, 0.4)))
    return {"pieces": pieces}


def _bust_profile(density=1.0):
    """(r, z) of the bust's surface of revolution from the crown down: head, neck, shoulders;
    `density` times the rings of the plain scan."""
    heads, necks, shoulders_n = (round(n * density) for n in (40, 5, 12))
    phi = np.linspace(0, 0.8 * math.pi, heads)
    head = np.column_stack([80 * np.sin(phi), 220 + 100 * np.cos(phi)])
    neck_z = np.linspace(132, 96, necks)
    neck = np.column_stack([np.full(necks, 44.0), neck_z])
    shoulder_z = np.linspace(88, 0, shoulders_n)
    shoulders = np.column_stack(
        [44 + 110 * np.sin(0.5 * math.pi * (88 - shoulder_z) / 88), shoulder_z]
    )
    return np.vstack([head, neck, shoulders])


def bust_scan(up="+z"):
    """A scanned bust, millimetres: a surface of revolution (head, neck, shoulders) with a nose,
    ears and scan noise, open at the bottom cut and with three dropped patches (holes), vertex
    colours; the crown is one vertex, every ring below has `segments` of them."""
    return _bust(up, density=1.0, segments=96)


def bust_scan_dense(up="+z"):
    """bust_scan as a modern scanner gives it: about 30,000 vertices (159 rings of 192 below the
    crown), the same
    head, noise and holes (each as large on the surface as the plain scan's)."""
    return _bust(up, density=2.8, segments=192)


def _bust(up, density, segments):
    """The bust with `density` times the plain scan's rings and `segments` around each."""
    rng = np.random.default_rng(7)
    profile = _bust_profile(density)
    theta = np.linspace(0, 2 * math.pi, segments, endpoint=False)
    rr, tt = np.meshgrid(profile[1:, 0], theta, indexing="ij")
    zz = np.repeat(profile[1:, 1][:, None], segments, axis=1)
    front = np.exp(-((tt - 1.5 * math.pi) ** 2) / 0.04)
    rr = (
        rr
        + 22 * front * np.exp(-((zz - 205) ** 2) / 150)
        + 10 * front * np.exp(-((zz - 160) ** 2) / 200)
    )
    ears = np.exp(-(np.minimum(tt, 2 * math.pi - tt) ** 2) / 0.03) + np.exp(
        -((tt - math.pi) ** 2) / 0.03
    )
    rr = rr + 9 * ears * np.exp(-((zz - 215) ** 2) / 300) + rng.normal(0, 0.3, rr.shape)
    squash = np.where(zz < 100, 0.55, 0.92)  # shoulders wide along x, the head a little
    x, y = rr * np.cos(tt), rr * np.sin(tt) * squash
    vertices = np.vstack(
        [[(0.0, 0.0, profile[0, 1])], np.column_stack([x.ravel(), y.ravel(), zz.ravel()])]
    )
    rings = len(profile) - 1
    index = 1 + np.arange(rings * segments).reshape(rings, segments)
    nxt = np.roll(index, -1, axis=1)
    crown = np.column_stack([np.zeros(segments, dtype=int), index[0], nxt[0]])
    a, b, c, d = index[:-1], index[1:], nxt[1:], nxt[:-1]
    quads = [
        np.column_stack([a.ravel(), b.ravel(), c.ravel()]),
        np.column_stack([a.ravel(), c.ravel(), d.ravel()]),
    ]
    keep = np.ones(len(quads[0]), dtype=bool)
    across, down = segments // 96, round(density)  # a hole's size in segments and rings
    for ring, segment in ((12, 10), (33, 60), (50, 30)):  # occluded spots the scanner missed
        ring, segment = round(ring * density), segment * across
        for dr in range(2 * down):
            start = (ring + dr) * segments + segment
            keep[start : start + 3 * across] = False
    triangles = np.vstack([crown, quads[0][keep], quads[1][keep]])
    grey = 0.62 + 0.05 * rng.standard_normal(len(vertices))
    colours = np.clip(np.column_stack([grey, grey * 0.97, grey * 0.92]), 0, 1)
    return {"pieces": [Piece("scan", to_file(vertices, up), triangles, (0.62, 0.6, 0.57), colours)]}


def tree_cards(up="+z"):
    """A game tree, metres: an open trunk tube (16 sides, no caps) and 600 single-sided leaf cards
    (two triangles each, 2400 border edges), vertex colours."""
    rng = np.random.default_rng(11)
    angles = np.linspace(0, 2 * math.pi, 17)
    trunk = []
    for z0, z1, r0, r1 in ((0, 2, 0.3, 0.22), (2, 4.5, 0.22, 0.12)):
        for a0, a1 in zip(angles[:-1], angles[1:]):
            trunk.append(
                [
                    (r0 * math.cos(a0), r0 * math.sin(a0), z0),
                    (r0 * math.cos(a1), r0 * math.sin(a1), z0),
                    (r1 * math.cos(a1), r1 * math.sin(a1), z1),
                    (r1 * math.cos(a0), r1 * math.sin(a0), z1),
                ]
            )  # noqa: E501
    cards = []
    for _ in range(600):
        centre = np.array([0, 0, 6.0]) + rng.normal(0, 1, 3) * (2.2, 2.2, 1.6)
        u, v = rng.normal(0, 1, 3), rng.normal(0, 1, 3)
        u = 0.3 * u / np.linalg.norm(u)
        v = np.cross(u, v)
        v = 0.3 * v / np.linalg.norm(v)
        cards.append(
            [
                tuple(centre - u - v),
                tuple(centre + u - v),
                tuple(centre + u + v),
                tuple(centre - u + v),
            ]
        )
    bark = sheet("trunk", trunk, (0.4, 0.28, 0.18), up)
    leaves = sheet("leaves", cards, (0.2, 0.5, 0.2), up)
    leaves.colours = np.repeat(
        np.column_stack(
            [0.15 + 0.1 * rng.random(600), 0.4 + 0.25 * rng.random(600), 0.15 * np.ones(600)]
        ),
        4,
        axis=0,
    )  # noqa: E501
    bark.colours = np.tile(bark.colour, (len(bark.vertices), 1))
    return {"pieces": [bark, leaves]}


# print_bed_bracket, millimetres, origin at the bed's corner as a slicer's export has it.
BED = ((0, 0, -3), (220, 220, 0))
BRACKET = ((80, 95, 0), (140, 125, 40))


def print_bed_bracket(up="+z"):
    """An L bracket with three bolt holes and a gusset standing on a 220 x 220 mm print bed."""
    base = box((80, 95, 0), (140, 125, 5))
    holes = [rod((x, 110, -1), (x, 110, 6), 3) for x in (100, 125)]
    upright = box((80, 95, 5), (85, 125, 40))
    gusset = extrude_xz([(85, 5), (120, 5), (85, 35)], 107.5, 5)
    bracket = fuse([base, upright, gusset]).cut(
        Part.Compound(holes + [rod((79, 110, 28), (86, 110, 28), 3)])
    )
    return {
        "pieces": [
            piece("print_bed", box(*BED), (0.2, 0.2, 0.22), 0.2, up),
            piece("bracket", bracket, (1.0, 0.55, 0.1), 0.05, up),
        ]
    }


def watch_gear(up="+z"):
    """A watch wheel in metres (12 mm across): a 20-tooth gear with a centre hole, an arbor through
    it (not touching) and a pinion: tiny numbers for a model whose unit is taken as mm."""
    teeth, outer, root = 20, 0.006, 0.0052
    points = []
    for k in range(teeth):
        a = 2 * math.pi * k / teeth
        for da, r in ((-0.07, root), (-0.035, outer), (0.035, outer), (0.07, root)):
            points.append(V(r * math.cos(a + da), r * math.sin(a + da), 0))
    wheel = Part.Face(Part.makePolygon(points + [points[0]])).extrude(V(0, 0, 0.0008))
    wheel = wheel.cut(rod((0, 0, -0.001), (0, 0, 0.002), 0.001))
    return {
        "pieces": [
            piece("wheel", wheel, (0.85, 0.7, 0.3), 0.00003, up),
            piece("arbor", rod((0, 0, -0.002), (0, 0, 0.003), 0.00095), STEEL, 0.00003, up),
            piece("pinion", rod((0, 0, 0.0015), (0, 0, 0.0025), 0.002), STEEL, 0.00003, up),
        ]
    }


BRIDGE = {"deck": ((0, -6000, 9000), (120000, 6000, 10000)), "span": 120000}


def bridge(up="+z"):
    """A road bridge 120 m long in millimetres: deck, two piers, an arch between them, abutments
    and thin railings (60 mm): huge numbers and thin parts."""
    p = lambda name, shape, colour: piece(name, shape, colour, 40.0, up)  # noqa: E731
    ring = rod((60000, -4000, -19500), (60000, 4000, -19500), 30000)
    ring = ring.cut(rod((60000, -4001, -19500), (60000, 4001, -19500), 28500))
    arch = ring.common(box((31500, -4000, 0), (88500, 4000, 9000)))
    pieces = [
        p("deck", box(*BRIDGE["deck"]), CONCRETE_BRIDGE),
        p("pier_0", box((28500, -4000, 0), (31500, 4000, 9000)), CONCRETE_BRIDGE),
        p("pier_1", box((88500, -4000, 0), (91500, 4000, 9000)), CONCRETE_BRIDGE),
        p("arch", arch, CONCRETE_BRIDGE),
        p("abutment_0", box((-5000, -8000, -2000), (5000, 8000, 9000)), (0.5, 0.45, 0.4)),
        p("abutment_1", box((115000, -8000, -2000), (125000, 8000, 9000)), (0.5, 0.45, 0.4)),
    ]
    for side, y in (("s", -6000), ("n", 5940)):
        pieces.append(p(f"railing_{side}", box((0, y, 10000), (120000, y + 60, 11100)), STEEL))
    return {"pieces": pieces}


# windmill, centimetres in a Collada file that says so (<unit meter="0.01"/>), y up.
WINDMILL = {"tower_height": 1200, "hub": (0, -260, 1300), "blade_length": 900}


def windmill():
    """Tower (frustum), cap (box and roof prism), hub, and one blade geometry placed four times by
    Collada node matrices: the blades are thin (10 cm) and long (9 m). Built y up directly."""
    up = "+y"
    hub = WINDMILL["hub"]
    pieces = [
        piece("tower", frustum(300, 180, WINDMILL["tower_height"]), (0.85, 0.82, 0.75), 2.0, up),
        piece("cap", box((-200, -230, 1200), (200, 230, 1380)), (0.4, 0.3, 0.2), 2.0, up),
        piece(
            "cap_roof",
            extrude_yz([(-250, 1380), (250, 1380), (0, 1500)], -220, 440),
            TILE_WM,
            2.0,
            up,
        ),
        piece("hub", rod((0, -230, 1300), hub, 40), (0.3, 0.3, 0.3), 2.0, up),
    ]
    blade = box(
        (-30, -10, 40), (30, 0, 40 + WINDMILL["blade_length"])
    )  # along design z, at the origin
    pieces.append(piece("blade", blade, (0.9, 0.9, 0.88), 2.0, up))
    centre = to_file([hub], up)[0]
    nodes = [(i, None) for i in range(4)]
    for k in range(4):
        a = math.radians(15 + 90 * k)
        matrix = np.eye(4)
        matrix[:2, :2] = [[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]]  # about file z
        matrix[:3, 3] = centre
        nodes.append((4, matrix))
    return {"pieces": pieces, "nodes": nodes}


def chair_x_up(up="+x"):
    """A chair, centimetres, exported with +x up: seat, four legs, two back posts and a back
    panel, eight touching solids."""
    p = lambda name, lo, hi: piece(name, box(lo, hi), (0.55, 0.38, 0.22), 0.5, up)  # noqa: E731
    pieces = [p("seat", (0, 0, 45), (45, 45, 49))]
    for i, (x, y) in enumerate(((0, 0), (41, 0), (0, 41), (41, 41))):
        pieces.append(p(f"leg_{i}", (x, y, 0), (x + 4, y + 4, 45)))
    pieces += [
        p("post_0", (0, 41, 49), (4, 45, 95)),
        p("post_1", (41, 41, 49), (45, 45, 95)),
        p("back", (4, 41.5, 70), (41, 44.5, 92)),
    ]
    return {"pieces": pieces}


def bookshelf(up="+z"):
    """A bookshelf, centimetres, in one OBJ object: two sides, five shelves between them, a back
    panel; the middle shelf and the back panel are written twice (duplicated faces)."""
    p = lambda name, lo, hi: piece(name, box(lo, hi), (0.8, 0.65, 0.45), 0.5, up)  # noqa: E731
    pieces = [p("side_l", (0, 0, 0), (2, 30, 180)), p("side_r", (78, 0, 0), (80, 30, 180))]
    pieces += [
        p(f"shelf_{k}", (2, 0, z), (78, 30, z + 2)) for k, z in enumerate((0, 44, 88, 132, 178))
    ]
    pieces += [p("back", (0, 30, 0), (80, 31, 180))]
    pieces += [
        p("shelf_2_again", (2, 0, 88), (78, 30, 90)),
        p("back_again", (0, 30, 0), (80, 31, 180)),
    ]
    return {"pieces": pieces}


def lighthouse_texture():
    """16 x 64: red and white bands of 8 rows (the tower's v runs bottom to top)."""
    image = np.zeros((64, 16, 3), dtype=np.uint8)
    for band in range(8):
        image[band * 8 : band * 8 + 8] = (200, 30, 30) if band % 2 else (240, 240, 235)
    return image


LIGHTHOUSE = {"rock": ((-14, -11, -3), (14, 11, 3)), "dome_top": ((0, 0, 24.6), (0, 0, 24.6))}


def lighthouse(up="+y"):
    """A lighthouse on a rock, metres: the striped tower (uvs by height into an embedded PNG),
    gallery, lantern and dome as separate solids, the rock an ellipsoid wider than all."""
    tower = frustum(3.0, 1.8, 18.0, (0, 0, 1.5))
    striped = textured_piece("tower", tower, 0.03, 1.0, (0, 1), up)
    heights = striped.vertices[:, "xyz".index(up[1])]
    striped.uvs = np.column_stack([np.full(len(heights), 0.5), (heights - 1.5) / 18.0])
    return {
        "pieces": [
            piece("rock", ellipsoid((0, 0, 0), (14, 11, 3)), (0.45, 0.42, 0.38), 0.05, up),
            striped,
            piece("gallery", rod((0, 0, 19.5), (0, 0, 19.9), 2.6), DARK, 0.03, up),
            piece("lantern", rod((0, 0, 19.9), (0, 0, 22.3), 1.3), (0.9, 0.9, 0.6), 0.03, up),
            piece(
                "dome",
                ellipsoid((0, 0, 22.3), (1.4, 1.4, 2.3)).common(box((-2, -2, 22.3), (2, 2, 25))),
                RED,
                0.03,
                up,
            ),
        ],
        "texture": ("lighthouse.png", lighthouse_texture()),
    }
