"""Buildings of tools/make_corpus.py, each solid its own piece as BIM and CAD exporters leave them.

Each recipe returns {"pieces": [...]} (and "texture" when it has one) in the file's units and
axes; the dimensions below are the known answers CORPUS quotes (design frame: z up, front -y).
"""

import numpy as np

from corpus_shapes import (
    box,
    cut,
    ellipsoid,
    extrude_xz,
    extrude_yz,
    heightfield,
    hip_roof,
    piece,
    rod,
    sheet,
    textured_piece,
)

GRASS = (0.35, 0.6, 0.3)
CREAM = (0.93, 0.88, 0.75)
TILE = (0.6, 0.2, 0.15)
BRICK = (0.55, 0.25, 0.2)
CONCRETE = (0.7, 0.7, 0.7)

# house_gable, metres: walls 0.3 thick on a 0.2 m floor slab, eaves at 3.0, ridge (roof top) 5.8.
GABLE = {
    "terrain": ((-7, -6, -0.5), (17, 14, 0)),
    "walls": ((0, 0, 0.2), (10, 8, 3.0)),
    "ridge": ((-0.5, 4, 5.8), (10.5, 4, 5.8)),
    "chimney": ((6.8, 5.2, 3.0), (7.6, 6.0, 6.4)),
}


def house_gable(up="+y"):
    """Terrain slab, floor slab, four walls (gable ends up to the roof), two roof planes with
    0.5 m overhang, a chimney: nine solids, windows and a door cut through the walls."""
    p = lambda name, shape, colour: piece(name, shape, colour, 0.05, up)  # noqa: E731
    window = lambda x, y0, y1, z0=1.1, z1=2.3: ((x - 0.7, y0, z0), (x + 0.7, y1, z1))  # noqa: E731
    front = cut(
        box((0, 0, 0.2), (10, 0.3, 3.0)),
        [window(2.0, -0.1, 0.4), window(8.0, -0.1, 0.4), ((4.4, -0.1, 0.2), (5.6, 0.4, 2.4))],
    )
    back = cut(box((0, 7.7, 0.2), (10, 8, 3.0)), [window(2.5, 7.6, 8.1), window(7.5, 7.6, 8.1)])
    gable = [(0, 0.2), (8, 0.2), (8, 3.0), (4, 5.6), (0, 3.0)]
    side_hole = lambda x: [
        ((x - 0.1, 3.3, 1.1), (x + 0.4, 4.7, 2.3)),
        ((x - 0.1, 3.6, 3.4), (x + 0.4, 4.4, 4.3)),
    ]  # noqa: E731,E501
    left = cut(extrude_yz(gable, 0, 0.3), side_hole(0))
    right = cut(extrude_yz(gable, 9.7, 0.3), side_hole(9.7))
    slope_front = extrude_yz([(-0.5, 2.675), (4, 5.6), (4, 5.8), (-0.5, 2.875)], -0.5, 11)
    slope_back = extrude_yz([(8.5, 2.675), (4, 5.6), (4, 5.8), (8.5, 2.875)], -0.5, 11)
    return {
        "pieces": [
            p("terrain", box(*GABLE["terrain"]), GRASS),
            p("floor_slab", box((0, 0, 0), (10, 8, 0.2)), CONCRETE),
            p("wall_front", front, CREAM),
            p("wall_back", back, CREAM),
            p("wall_left", left, CREAM),
            p("wall_right", right, CREAM),
            p("roof_front", slope_front, TILE),
            p("roof_back", slope_back, TILE),
            p("chimney", box(*GABLE["chimney"]), BRICK),
        ]
    }


# house_hip, centimetres: a hip roof (45 % overhang of 50 cm), porch with posts and a shed roof.
HIP = {
    "terrain": ((-600, -800, -40), (1800, 1400, 0)),
    "walls": ((0, 0, 20), (1200, 800, 300)),
    "ridge": ((400, 400, 625), (800, 400, 625)),
    "roof": ((-50, -50, 300), (1250, 850, 625)),
    "chimney": ((900, 500, 300), (960, 560, 700)),
}


def house_hip(up="+z"):
    """Terrain slab, floor slab, four walls with windows and a door, a hip roof, a porch (slab,
    two posts, a shed roof), a chimney: eleven solids, per-vertex colours in the file."""
    p = lambda name, shape, colour: piece(name, shape, colour, 3.0, up)  # noqa: E731
    win_y = lambda x, y0, y1: ((x - 60, y0, 100), (x + 60, y1, 230))  # noqa: E731
    win_x = lambda y, x0, x1: ((x0, y - 60, 100), (x1, y + 60, 230))  # noqa: E731
    door = ((560, -10, 20), (640, 40, 240))
    walls = [
        cut(
            box((0, 0, 20), (1200, 30, 300)), [win_y(x, -10, 40) for x in (200, 400, 900)] + [door]
        ),
        cut(box((0, 770, 20), (1200, 800, 300)), [win_y(x, 760, 810) for x in (250, 600, 950)]),
        cut(box((0, 30, 20), (30, 770, 300)), [win_x(400, -10, 40)]),
        cut(box((1170, 30, 20), (1200, 770, 300)), [win_x(400, 1160, 1210)]),
    ]
    porch_roof = extrude_yz([(0, 290), (-280, 250), (-280, 262), (0, 302)], 380, 440)
    pieces = [
        p("terrain", box(*HIP["terrain"]), GRASS),
        p("floor_slab", box((0, 0, 0), (1200, 800, 20)), CONCRETE),
    ]
    pieces += [p(f"wall_{i}", w, CREAM) for i, w in enumerate(walls)]
    pieces += [
        p("roof", hip_roof(HIP["roof"][0][:2], HIP["roof"][1][:2], 300, 325), TILE),
        p("porch_slab", box((400, -250, 0), (800, 0, 15)), CONCRETE),
        p("porch_post_0", rod((420, -230, 15), (420, -230, 265), 12), CREAM),
        p("porch_post_1", rod((780, -230, 15), (780, -230, 265), 12), CREAM),
        p("porch_roof", porch_roof, TILE),
        p("chimney", box(*HIP["chimney"]), BRICK),
    ]
    return {"pieces": pieces}


# shed_cabin, metres, moved to (1520, -860, 212) as a survey-referenced export would be.
SHED_OFFSET = (1520.0, -860.0, 212.0)
SHED = {
    "front_wall": ((0, 0, 0.25), (6, 0.2, 3.2)),
    "back_wall": ((0, 3.8, 0.25), (6, 4, 2.4)),
    "roof_high_edge": ((-0.4, -0.6, 3.47), (6.4, -0.6, 3.47)),
}


def shed_cabin(up="+z"):
    """A cabin with a shed (mono-pitch) roof overhanging 0.6 m, walls as separate solids with
    windows, a front deck and a thin stove pipe: eight solids, far from the origin."""
    p = lambda name, shape, colour: piece(name, shape, colour, 0.03, up, SHED_OFFSET)  # noqa: E731
    side = [(0, 0.25), (4, 0.25), (4, 2.4), (0, 3.2)]
    pieces = [
        p("floor", box((0, 0, 0), (6, 4, 0.25)), CONCRETE),
        p("deck", box((0, -2, 0.1), (6, 0, 0.25)), (0.55, 0.4, 0.25)),
        p(
            "wall_front",
            cut(
                box((0, 0, 0.25), (6, 0.2, 3.2)),
                [((0.6, -0.1, 0.9), (2.6, 0.3, 2.8)), ((3.2, -0.1, 0.25), (4.2, 0.3, 2.3))],
            ),
            (0.6, 0.45, 0.3),
        ),  # noqa: E501
        p(
            "wall_back",
            cut(box((0, 3.8, 0.25), (6, 4, 2.4)), [((2.5, 3.7, 1.2), (3.5, 4.1, 1.9))]),
            (0.6, 0.45, 0.3),
        ),
        p(
            "wall_left",
            cut(extrude_yz(side, 0, 0.2), [((-0.1, 1.5, 1.0), (0.3, 2.5, 2.0))]),
            (0.6, 0.45, 0.3),
        ),
        p("wall_right", extrude_yz(side, 5.8, 0.2), (0.6, 0.45, 0.3)),
        p(
            "roof",
            extrude_yz([(-0.6, 3.32), (4.5, 2.3), (4.5, 2.45), (-0.6, 3.47)], -0.4, 6.8),
            (0.3, 0.3, 0.32),
        ),
        p("stove_pipe", rod((5.0, 3.0, 2.0), (5.0, 3.0, 3.6), 0.08), (0.15, 0.15, 0.15)),
    ]
    return {"pieces": pieces}


# apartment_blocks, millimetres: three blocks of 3, 5 and 2 storeys, 3 m each, 250 mm walls.
STOREY, SLAB, WALL = 3000, 250, 250
APARTMENT = {
    "block_a": ((0, 0, 0), (24000, 12000, 9000)),
    "block_b": ((24000, 0, 0), (36000, 12000, 15000)),
    "block_c": ((24000, 12000, 0), (36000, 30000, 6000)),
}
BLOCKS = (
    ("a", (0, 0), (24000, 12000), 3, "y"),
    ("b", (24000, 0), (36000, 12000), 5, "y"),
    ("c", (24000, 12000), (36000, 30000), 2, "x"),
)


def _storey(name, lo, hi, z, facade, p):
    """One storey of a block: its floor slab and four walls, windows every 3 m on two faces."""
    (x0, y0), (x1, y1) = lo, hi
    top = z + STOREY
    windows = []
    if facade == "y":
        for x in np.arange(x0 + 1500, x1 - 1000, 3000):
            for y in (y0 - 10, y1 - WALL - 10):
                windows.append(((x - 600, y, z + 1000), (x + 600, y + WALL + 20, z + 2400)))
    else:
        for y in np.arange(y0 + 1500, y1 - 1000, 3000):
            for x in (x0 - 10, x1 - WALL - 10):
                windows.append(((x, y - 600, z + 1000), (x + WALL + 20, y + 600, z + 2400)))
    along_y = [w for w in windows if w[1][1] - w[0][1] < 1000]
    along_x = [w for w in windows if w[1][1] - w[0][1] >= 1000]
    return [
        p(f"{name}_slab", box((x0, y0, z), (x1, y1, z + SLAB)), CONCRETE),
        p(
            f"{name}_wall_s",
            cut(
                box((x0, y0, z + SLAB), (x1, y0 + WALL, top)),
                [w for w in along_y if w[0][1] < y0 + WALL],
            ),
            CREAM,
        ),  # noqa: E501
        p(
            f"{name}_wall_n",
            cut(
                box((x0, y1 - WALL, z + SLAB), (x1, y1, top)),
                [w for w in along_y if w[0][1] >= y0 + WALL],
            ),
            CREAM,
        ),  # noqa: E501
        p(
            f"{name}_wall_w",
            cut(
                box((x0, y0, z + SLAB), (x0 + WALL, y1, top)),
                [w for w in along_x if w[0][0] < x0 + WALL],
            ),
            CREAM,
        ),  # noqa: E501
        p(
            f"{name}_wall_e",
            cut(
                box((x1 - WALL, y0, z + SLAB), (x1, y1, top)),
                [w for w in along_x if w[0][0] >= x0 + WALL],
            ),
            CREAM,
        ),  # noqa: E501
    ]


def apartment_blocks(up="+z"):
    """Three touching blocks, storey by storey (slab + four walls), flat roofs with parapets;
    block b's parapet is exported twice (duplicated faces), as a careless IFC export does."""
    p = lambda name, shape, colour: piece(name, shape, colour, 50.0, up)  # noqa: E731
    pieces = []
    for name, lo, hi, storeys, facade in BLOCKS:
        for k in range(storeys):
            pieces += _storey(f"{name}{k}", lo, hi, k * STOREY, facade, p)
        z = storeys * STOREY
        (x0, y0), (x1, y1) = lo, hi
        pieces.append(p(f"{name}_roof", box((x0, y0, z), (x1, y1, z + SLAB)), (0.4, 0.4, 0.42)))
        parapet = [
            box((x0, y0, z + SLAB), (x1, y0 + 200, z + SLAB + 900)),
            box((x0, y1 - 200, z + SLAB), (x1, y1, z + SLAB + 900)),
            box((x0, y0 + 200, z + SLAB), (x0 + 200, y1 - 200, z + SLAB + 900)),
            box((x1 - 200, y0 + 200, z + SLAB), (x1, y1 - 200, z + SLAB + 900)),
        ]
        copies = 2 if name == "b" else 1
        for c in range(copies):
            pieces += [p(f"{name}_parapet_{i}_{c}", s, CONCRETE) for i, s in enumerate(parapet)]
    return {"pieces": pieces}


def terrain_height(x, y):
    return 6 * np.sin(x / 40.0) + 4 * np.cos(y / 55.0) + 0.02 * x


def _terrain_colour(z):
    t = min(max((z + 10) / 22.0, 0), 1)
    return (0.3 + 0.35 * t, 0.55 - 0.1 * t, 0.25 + 0.1 * t)


VILLAGE_HOUSES = ((-30.0, -20.0), (10.0, 25.0), (45.0, -35.0))


def terrain_village(up="+y"):
    """An open terrain surface 240 m square (48 x 48 cells, vertex colours) with three small
    houses (body and roof separate) and a tower sunk 1 m into it."""
    pieces = [
        heightfield("terrain", (-120, -120), (120, 120), 48, terrain_height, _terrain_colour, up)
    ]
    for k, (x, y) in enumerate(VILLAGE_HOUSES):
        z = float(terrain_height(x, y)) - 1.0
        pieces.append(
            piece(f"house_{k}", box((x - 4, y - 3, z), (x + 4, y + 3, z + 4)), CREAM, 0.05, up)
        )
        roof = extrude_yz([(y - 3.5, z + 4), (y + 3.5, z + 4), (y, z + 6.5)], x - 4.5, 9)
        pieces.append(piece(f"roof_{k}", roof, TILE, 0.05, up))
    z = float(terrain_height(-5.0, -5.0)) - 1.0
    pieces.append(piece("tower", box((-8, -8, z), (-2, -2, z + 18)), (0.75, 0.72, 0.65), 0.05, up))
    spire = extrude_xz([(-8, z + 18), (-2, z + 18), (-5, z + 24)], -8, 6)
    pieces.append(piece("tower_roof", spire, TILE, 0.05, up))
    return {"pieces": pieces}


def open_roof_game(up="+y"):
    """A game-style cottage, 8 x 6 m: walls as single-sided quads, no floor, the roof one sheet of
    triangles (16 x 16 cells over both slopes), gables as lone triangles, one wall quad wound the
    wrong way, vertex colours; no solid anywhere (open shells)."""
    walls = [
        [(0, 0, 0), (8, 0, 0), (8, 0, 3), (0, 0, 3)],
        [(8, 6, 0), (0, 6, 0), (0, 6, 3), (8, 6, 3)],
        [(0, 6, 0), (0, 0, 0), (0, 0, 3), (0, 6, 3)],
        [(8, 0, 0), (8, 6, 0), (8, 6, 3), (8, 0, 3)],
        [(0, 0, 3), (0, 3, 5), (0, 6, 3)],
        [(8, 6, 3), (8, 3, 5), (8, 0, 3)],
        [
            (1.5, -0.02, 1.0),
            (3.0, -0.02, 1.0),
            (3.0, -0.02, 2.2),
            (1.5, -0.02, 2.2),
        ],  # window decal
    ]
    roof = heightfield(
        "roof",
        (-0.4, -0.5),
        (8.4, 6.5),
        16,
        lambda x, y: 5.0 + 0.05 - np.abs(y - 3.0) * (2.0 / 3.0),
        lambda z: (0.55, 0.25 + 0.05 * (z - 4), 0.2),
        up,
    )
    w = sheet("walls", walls, (0.85, 0.8, 0.65), up, flip=(2,))
    w.colours = np.tile((0.85, 0.8, 0.65), (len(w.vertices), 1))
    w.colours[-4:] = (0.3, 0.5, 0.8)
    return {"pieces": [w, roof]}


def _stripes(size, bands):
    """An H x W x 3 image of horizontal bands ((rows, colour) from the top) with mortar lines."""
    rows = []
    for count, colour in bands:
        rows += [colour] * count
    image = np.array(rows, dtype=np.uint8)[:, None, :].repeat(size, axis=1)
    return image


def cottage_texture():
    """64 x 64: the top half roof tiles (dark red rows), the bottom half bricks."""
    image = _stripes(64, [(4, (140, 40, 30)), (4, (100, 30, 25))] * 4 + [(32, (170, 80, 60))])
    for row in range(32, 64, 4):
        image[row] = (220, 215, 200)  # mortar courses
        shift = 0 if (row // 4) % 2 else 8
        image[row : row + 4, shift::16] = (220, 215, 200)
    return image


COTTAGE = {"walls": ((0, 0, 0), (600, 400, 280)), "ridge": ((-30, 200, 460), (630, 200, 460))}


def cottage_tga(up="+y"):
    """Walls block and roof prism textured from one 64 x 64 TGA (bricks below, tiles above), the
    chimney untextured: three solids, centimetres."""
    roof = extrude_yz([(-30, 270), (430, 270), (200, 460)], -30, 660)
    return {
        "pieces": [
            textured_piece("walls", box(*COTTAGE["walls"]), 3.0, 200.0, (0.02, 0.48), up),
            textured_piece("roof", roof, 3.0, 200.0, (0.52, 0.98), up),
            piece("chimney", box((420, 250, 300), (480, 310, 520)), BRICK, 3.0, up),
        ],
        "texture": ("cottage.tga", cottage_texture()),
    }


BARN = {"body": ((0, 0, 0), (480, 360, 240)), "ridge": ((-12, 180, 384), (492, 180, 384))}
SILO = (600, 180, 72, 420)  # x, y of the axis, radius, height of the cylinder (the dome above)


def barn_texture():
    image = np.zeros((32, 64, 3), dtype=np.uint8)
    image[16:] = (150, 30, 25)
    image[16:, ::8] = (110, 20, 18)  # board gaps
    image[:16] = (90, 90, 95)  # roof steel
    image[:16, ::4] = (120, 120, 125)
    return image


def barn_bmp(up="+z"):
    """A barn 40 x 30 ft (inches) with a gable roof overhanging 1 ft, both textured from a BMP,
    and a silo (cylinder and dome) beside it, untextured."""
    sx, sy, r, h = SILO
    roof = extrude_yz([(-12, 234), (372, 234), (180, 384)], -12, 504)
    dome = piece("silo_dome", ellipsoid((sx, sy, h), (r, r, r)), (0.7, 0.7, 0.72), 2.0, up)
    return {
        "pieces": [
            textured_piece("barn", box(*BARN["body"]), 2.0, 120.0, (0.02, 0.48), up),
            textured_piece("roof", roof, 2.0, 120.0, (0.52, 0.98), up),
            piece("silo", rod((sx, sy, 0), (sx, sy, h), r), (0.75, 0.75, 0.78), 2.0, up),
            dome,
        ],
        "texture": ("barn.bmp", barn_texture()),
    }
