"""Edits of a written sheets.dxf that a maker (or a slip in CAD) could make, for the tests of
`popup verify`. Each edit works on the DXF with ezdxf, as LibreCAD or Inkscape would, and uses the
layout (sheets.json) only to find which entities belong to which piece, fold or tab: what verify
itself reads is the DXF alone.

Every mutation returns a Mutation saying what it changed (piece, codes, by how much), or raises
Unavailable with the reason when the design has nothing to change that way (one tab, no fold).
"""

import math
from dataclasses import dataclass, field
from typing import List, Optional

import ezdxf

SHEET_GAP = 20.0  # mm between sheets in sheets.dxf (dxf_writer.SHEET_GAP)
MATCH = 1e-6  # mm: a DXF coordinate and the layout's agree this well


class Unavailable(Exception):
    """The design offers nothing this mutation can change; the message says why."""


@dataclass
class Mutation:
    name: str
    piece: str  # the piece changed
    codes: List[str] = field(default_factory=list)  # tab codes involved
    amount: Optional[float] = None  # mm or a factor
    note: str = ""


def sheet_offset(sheet_set, piece):
    return piece["sheet"] * (sheet_set["paper"]["width"] + SHEET_GAP)


def _moved(sheet_set, piece, points):
    dx = sheet_offset(sheet_set, piece)
    return [(p[0] + dx, p[1]) for p in points]


def _same(a, b):
    return math.dist((a[0], a[1]), (b[0], b[1])) <= MATCH


def _lines(doc, layers):
    return [e for e in doc.modelspace() if e.dxftype() == "LINE" and e.dxf.layer in layers]


def _fold_line(doc, sheet_set, piece, fold):
    """The DXF LINE drawing `fold` of `piece`."""
    start, end = _moved(sheet_set, piece, [fold["from"], fold["to"]])
    found = [
        e
        for e in _lines(doc, ("MOUNTAIN", "VALLEY"))
        if _same(e.dxf.start, start) and _same(e.dxf.end, end)
    ]
    assert len(found) == 1, f"fold {fold} of {piece['id']}: {len(found)} lines in the DXF"
    return found[0]


def _label_text(doc, sheet_set, piece, label):
    (position,) = _moved(sheet_set, piece, [label["position"]])
    found = [
        e
        for e in doc.modelspace().query("TEXT[layer=='LABEL']")
        if e.dxf.text == label["text"] and _same(e.dxf.align_point, position)
    ]
    assert len(found) == 1, f"label {label} of {piece['id']}: {len(found)} texts in the DXF"
    return found[0]


def _polylines(doc, layer, sheet_set, piece, loops):
    """The LWPOLYLINEs on `layer` drawing `loops` of `piece` (same vertices, same order)."""
    found = []
    candidates = list(doc.modelspace().query(f"LWPOLYLINE[layer=='{layer}']"))
    for loop in loops:
        loop = _moved(sheet_set, piece, loop)
        match = [
            e
            for e in candidates
            if len(e) == len(loop) and all(_same(p, q) for p, q in zip(e.get_points("xy"), loop))
        ]
        assert len(match) == 1, f"{layer} loop of {piece['id']}: {len(match)} polylines"
        found.append(match[0])
    return found


def piece_entities(doc, sheet_set, piece):
    """Every DXF entity drawing `piece`: CUT and GLUE polylines, fold lines and labels."""
    loops = [loop for r in piece["cut"] for loop in [r["outer"], *r["holes"]]]
    return (
        _polylines(doc, "CUT", sheet_set, piece, loops)
        + [_fold_line(doc, sheet_set, piece, f) for f in piece["folds"]]
        + _polylines(doc, "GLUE", sheet_set, piece, [g["polygon"] for g in piece["glue"]])
        + [_label_text(doc, sheet_set, piece, t) for t in piece["labels"]]
    )


def _pieces_mechanisms_first(sheet_set):
    """The pieces, the card (P1) last: a mechanism's piece is the more telling edit."""
    pieces = sheet_set["pieces"]
    return [p for p in pieces if p["id"] != "P1"] + [p for p in pieces if p["id"] == "P1"]


def _piece(sheet_set, piece_id):
    (piece,) = [p for p in sheet_set["pieces"] if p["id"] == piece_id]
    return piece


# --- a. a fold line moved -----------------------------------------------------------------------


def shift_fold(doc, sheet_set, distance=0.5):
    """Moves the first fold (a crease inside a piece, not a tab's) of a mechanism's piece, or the
    card's central fold, `distance` mm perpendicular to itself."""
    for piece in _pieces_mechanisms_first(sheet_set):
        for fold in piece["folds"]:
            if fold["kind"] != "fold":
                continue
            line = _fold_line(doc, sheet_set, piece, fold)
            (sx, sy), (ex, ey) = fold["from"], fold["to"]
            length = math.hypot(ex - sx, ey - sy)
            nx, ny = -(ey - sy) / length * distance, (ex - sx) / length * distance
            line.dxf.start = (line.dxf.start[0] + nx, line.dxf.start[1] + ny)
            line.dxf.end = (line.dxf.end[0] + nx, line.dxf.end[1] + ny)
            return Mutation("shift_fold", piece["id"], amount=distance, note=str(fold))
    raise Unavailable("no piece has a fold line")


# --- b. a fold on the wrong layer -----------------------------------------------------------------


def flip_fold(doc, sheet_set):
    """Puts a MOUNTAIN fold line (a crease inside a piece) on VALLEY; when no piece has one, a
    VALLEY line on MOUNTAIN."""
    for wanted, other in (("mountain", "VALLEY"), ("valley", "MOUNTAIN")):
        for piece in _pieces_mechanisms_first(sheet_set):
            for fold in piece["folds"]:
                if fold["kind"] == "fold" and fold["direction"] == wanted:
                    _fold_line(doc, sheet_set, piece, fold).dxf.layer = other
                    return Mutation("flip_fold", piece["id"], note=f"{wanted} -> {other}")
    raise Unavailable("no piece has a fold line")


# --- c. two tab codes swapped ---------------------------------------------------------------------


def tab_codes(sheet_set):
    """The tab codes as drawn: LABEL texts that are also a glue area's code ("A" or "A (back)")."""
    glue = set()
    for piece in sheet_set["pieces"]:
        for label in piece["labels"]:
            if label["kind"] == "glue":
                glue.add(label["text"].split(" (")[0])
    return [
        (piece, label)
        for piece in sheet_set["pieces"]
        for label in piece["labels"]
        if label["kind"] == "tab" and label["text"] in glue
    ]


def swap_tab_codes(doc, sheet_set):
    """Swaps the texts of two tab codes: of two tabs on different pieces going to different
    pieces when there are such, else on one piece going to different patches. Swapping the two
    codes of a piece that its turning half round maps onto itself (a symmetric tent) makes the
    same card, so such a pair is never taken."""
    tabs = tab_codes(sheet_set)
    if len(tabs) < 2:
        raise Unavailable(f"{len(tabs)} glue tab(s): nothing to swap")
    target = {}
    for piece in sheet_set["pieces"]:
        for tab in piece["tabs"]:
            target[tab["code"]] = (tab["target_piece"], tab["target_patch"], piece, tab)

    def sameness(pair):
        (piece_a, label_a), (piece_b, label_b) = pair
        (to_a, patch_a, *_), (to_b, patch_b, *_) = target[label_a["text"]], target[label_b["text"]]
        return (piece_a["id"] == piece_b["id"], to_a == to_b, patch_a == patch_b)

    pairs = [(a, b) for i, a in enumerate(tabs) for b in tabs[i + 1 :]]
    pairs = [pair for pair in pairs if not all(sameness(pair)[1:])]
    pairs = [pair for pair in pairs if not _swap_is_a_symmetry(sheet_set, target, pair)]
    if not pairs:
        raise Unavailable(
            f"the {len(tabs)} tabs either go to one patch or sit on a piece that turning half "
            "round maps onto itself, swapping their codes: swapped, they make the same card"
        )
    (piece_a, label_a), (piece_b, label_b) = min(pairs, key=sameness)
    text_a = _label_text(doc, sheet_set, piece_a, label_a)
    text_b = _label_text(doc, sheet_set, piece_b, label_b)
    text_a.dxf.text, text_b.dxf.text = label_b["text"], label_a["text"]
    return Mutation(
        "swap_tab_codes",
        piece_a["id"],
        codes=[label_a["text"], label_b["text"]],
        note=f"{piece_a['id']} and {piece_b['id']}",
    )


def _swap_is_a_symmetry(sheet_set, target, pair):
    """True when both tabs are on one piece and a rigid motion of the sheet (no turning over)
    takes the piece's outline and folds (with their directions) onto themselves and one tab's
    crease onto the other's: the swapped codes then make the same card."""
    (piece_a, label_a), (piece_b, label_b) = pair
    if piece_a["id"] != piece_b["id"]:
        return False
    piece = piece_a
    crease_a = target[label_a["text"]][3]["polygon"][:2]
    crease_b = target[label_b["text"]][3]["polygon"][:2]
    outline = [tuple(p) for r in piece["cut_nominal"] for p in r["outer"]]
    folds = [(tuple(f["from"]), tuple(f["to"]), f["direction"]) for f in piece["folds"]]
    for onto in (crease_b, crease_b[::-1]):
        motion = _motion(crease_a, onto)
        if motion is None:
            continue
        moved = [motion(p) for p in outline]
        if not all(any(_same(m, p) for p in outline) for m in moved):
            continue
        if all(
            any(
                d == direction and {_key(motion(s)), _key(motion(e))} == {_key(s2), _key(e2)}
                for s2, e2, d in folds
            )
            for s, e, direction in folds
        ):
            return True
    return False


def _motion(source, target):
    """The rotation and translation taking segment `source` onto `target`; None if their lengths
    differ."""
    (a, b), (c, d) = source, target
    if abs(math.dist(a, b) - math.dist(c, d)) > MATCH:
        return None
    turn = math.atan2(d[1] - c[1], d[0] - c[0]) - math.atan2(b[1] - a[1], b[0] - a[0])
    cos, sin = math.cos(turn), math.sin(turn)

    def moved(p):
        x, y = p[0] - a[0], p[1] - a[1]
        return (c[0] + cos * x - sin * y, c[1] + sin * x + cos * y)

    return moved


# --- d. a tab cut off -----------------------------------------------------------------------------


def _intersection(p, q, a, b):
    """Where the line p-q meets the line a-b; None when they are parallel."""
    d1 = (q[0] - p[0], q[1] - p[1])
    d2 = (b[0] - a[0], b[1] - a[1])
    cross = d1[0] * d2[1] - d1[1] * d2[0]
    scale = math.hypot(*d1) * math.hypot(*d2)
    if scale == 0 or abs(cross) <= 1e-12 * scale:
        return None
    t = ((a[0] - p[0]) * d2[1] - (a[1] - p[1]) * d2[0]) / cross
    return (p[0] + t * d1[0], p[1] + t * d1[1])


def _area(loop):
    return 0.5 * sum(
        a[0] * b[1] - b[0] * a[1] for a, b in zip(loop, list(loop[1:]) + list(loop[:1]))
    )


def cut_off_tab(doc, sheet_set):
    """What a maker does who cuts a tab off: the CUT loop goes straight along the tab's crease
    (half the kerf outside it, as the rest of the outline), and the tab's crease line and its
    code, printed on the tab, go with it. The glue area on the other piece stays."""
    kerf = sheet_set["options"]["kerf"]
    for piece in _pieces_mechanisms_first(sheet_set):
        for tab in piece["tabs"]:
            return _cut_off(doc, sheet_set, piece, tab, kerf)
    raise Unavailable("no glue tab")


def _cut_off(doc, sheet_set, piece, tab, kerf):
    p0, p1, p2, p3 = _moved(sheet_set, piece, tab["polygon"][:4])
    (cut_line,) = _polylines(doc, "CUT", sheet_set, piece, [piece["cut"][0]["outer"]])
    loop = [tuple(p) for p in cut_line.get_points("xy")]
    n = len(loop)

    def nearest(point):
        index = min(range(n), key=lambda i: math.dist(loop[i], point))
        assert math.dist(loop[index], point) <= kerf, (point, loop[index])
        return index

    i2, i3 = nearest(p2), nearest(p3)  # the tab's far corners, moved out by half the kerf
    step = 1 if (i2 + 1) % n == i3 else -1
    assert (i2 + step) % n == i3, "the tab's far corners are not neighbours on the CUT loop"
    i1, i0 = (i2 - step) % n, (i3 + step) % n  # where the tab's sides leave the outline
    # The crease moved half the kerf towards the tab: the new edge of the outline.
    length = math.dist(p0, p1)
    nx, ny = -(p1[1] - p0[1]) / length, (p1[0] - p0[0]) / length
    if (p2[0] - p0[0]) * nx + (p2[1] - p0[1]) * ny < 0:
        nx, ny = -nx, -ny
    a = (p0[0] + nx * kerf / 2, p0[1] + ny * kerf / 2)
    b = (p1[0] + nx * kerf / 2, p1[1] + ny * kerf / 2)
    # Each side's outline edge, running away from the tab, meets the new edge (or lies on it).
    corner1 = _intersection(loop[(i1 - step) % n], loop[i1], a, b) or loop[i1]
    corner0 = _intersection(loop[(i0 + step) % n], loop[i0], a, b) or loop[i0]
    replaced = {i1: corner1, i0: corner0}
    new_loop = [replaced.get(i, loop[i]) for i in range(n) if i not in (i2, i3)]
    before, after = abs(_area(loop)), abs(_area(new_loop))
    tab_area = abs(_area([p0, p1, p2, p3]))
    assert abs(before - after - tab_area) <= kerf * 2 * math.dist(p1, p2) + 1e-6, (
        before,
        after,
        tab_area,
    )
    cut_line.set_points(new_loop, format="xy")
    # The crease at the tab's foot and the code printed on the tab.
    for fold in piece["folds"]:
        ends = _moved(sheet_set, piece, [fold["from"], fold["to"]])
        if fold["kind"] == "tab" and {_key(e) for e in ends} == {_key(p0), _key(p1)}:
            doc.modelspace().delete_entity(_fold_line(doc, sheet_set, piece, fold))
            break
    else:
        raise AssertionError(f"tab {tab['code']} of {piece['id']}: no crease line")
    for label in piece["labels"]:
        if label["kind"] == "tab" and label["text"] == tab["code"]:
            doc.modelspace().delete_entity(_label_text(doc, sheet_set, piece, label))
            break
    else:
        raise AssertionError(f"tab {tab['code']} of {piece['id']}: no code on the sheet")
    return Mutation(
        "cut_off_tab", piece["id"], codes=[tab["code"]], note=f"onto {tab['target_piece']}"
    )


def _key(point):
    return (round(point[0], 5), round(point[1], 5))


# --- e. a piece scaled ----------------------------------------------------------------------------


def centroid(loop):
    area = _area(loop)
    cx = cy = 0.0
    for a, b in zip(loop, list(loop[1:]) + list(loop[:1])):
        w = a[0] * b[1] - b[0] * a[1]
        cx += (a[0] + b[0]) * w
        cy += (a[1] + b[1]) * w
    return (cx / (6 * area), cy / (6 * area))


def scale_piece(doc, sheet_set, factor=1.01, piece_id=None):
    """Scales one piece (P2, else P1) by `factor` about the centroid of its outline: its CUT
    loops, fold lines, glue areas and labels, as a maker's "scale selection" would."""
    ids = [p["id"] for p in sheet_set["pieces"]]
    piece = _piece(sheet_set, piece_id or ("P2" if "P2" in ids else "P1"))
    cx, cy = centroid(_moved(sheet_set, piece, piece["cut"][0]["outer"]))

    def scaled(point):
        return (cx + (point[0] - cx) * factor, cy + (point[1] - cy) * factor)

    for entity in piece_entities(doc, sheet_set, piece):
        kind = entity.dxftype()
        if kind == "LWPOLYLINE":
            entity.set_points([scaled(p) for p in entity.get_points("xy")], format="xy")
        elif kind == "LINE":
            entity.dxf.start, entity.dxf.end = scaled(entity.dxf.start), scaled(entity.dxf.end)
        else:
            entity.dxf.insert = scaled(entity.dxf.insert)
            entity.dxf.align_point = scaled(entity.dxf.align_point)
    return Mutation("scale_piece", piece["id"], amount=factor)


MUTATIONS = {
    "shift_fold": shift_fold,
    "flip_fold": flip_fold,
    "swap_tab_codes": swap_tab_codes,
    "cut_off_tab": cut_off_tab,
    "scale_piece": scale_piece,
}


def mutated_copy(source, target, sheet_set, name):
    """Writes `source` (a sheets.dxf) with mutation `name` applied to `target`; its Mutation."""
    doc = ezdxf.readfile(str(source))
    mutation = MUTATIONS[name](doc, sheet_set)
    doc.saveas(str(target))
    return mutation
