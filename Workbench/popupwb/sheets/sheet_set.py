"""The sheet set (docs/SHEET_FORMAT.md) read into checked, frozen dataclasses.

A sheet set is the JSON object of docs/SHEET_FORMAT.md. `read_sheet_set` checks the parts the
writers draw and returns frozen dataclasses, so every writer works from the same checked data and a
malformed sheet set fails once, with a ValueError naming the key path. No FreeCAD needed.
"""

import math
import os
from dataclasses import dataclass
from typing import Optional, Tuple

Point = Tuple[float, float]
Loop = Tuple[Point, ...]

FORMAT = "popup-sheets"
VERSION = 1
FOLD_DIRECTIONS = ("mountain", "valley")
SIDES = ("front", "back")


@dataclass(frozen=True)
class Region:
    """One connected area to cut: an outer loop (counter-clockwise) and its holes (clockwise)."""

    outer: Loop
    holes: Tuple[Loop, ...]

    def loops(self):
        return (self.outer,) + self.holes


@dataclass(frozen=True)
class Fold:
    start: Point
    end: Point
    direction: str  # "mountain" or "valley", seen from the printed side
    kind: str  # "fold" or "tab"


@dataclass(frozen=True)
class Tab:
    code: str
    target_piece: str
    side: str


@dataclass(frozen=True)
class GlueArea:
    code: str
    polygon: Loop
    tab_piece: str
    side: str


@dataclass(frozen=True)
class Label:
    text: str
    kind: str
    position: Point
    height: float  # cap height, mm
    angle: float  # degrees counter-clockwise

    def baseline_centre(self):
        """Where the middle of the baseline goes so that the cap height is centred on `position`
        (writers whose text anchors on the baseline need this)."""
        turn = math.radians(self.angle)
        half = self.height / 2.0
        return (self.position[0] + half * math.sin(turn), self.position[1] - half * math.cos(turn))


@dataclass(frozen=True)
class FlatPatch:
    """A patch laid flat on its sheet, exact (no kerf)."""

    id: int
    name: str
    outer: Loop
    holes: Tuple[Loop, ...]
    # The patch's own frame (u, v) onto the sheet: ((a, b, tx), (c, d, ty)); None in sheet sets
    # written before it existed.
    to_sheet: Optional[Tuple[Tuple[float, float, float], Tuple[float, float, float]]]

    def normal_side_up(self):
        """The patch's normal side faces up (is printed); else its back side does."""
        (a, b, _), (c, d, _) = self.to_sheet
        return a * d - b * c > 0.0


@dataclass(frozen=True)
class Piece:
    id: str
    sheet: int
    cut: Tuple[Region, ...]
    folds: Tuple[Fold, ...]
    tabs: Tuple[Tab, ...]
    glue: Tuple[GlueArea, ...]
    labels: Tuple[Label, ...]
    patches: Tuple[FlatPatch, ...] = ()


@dataclass(frozen=True)
class Sheet:
    index: int
    pieces: Tuple[Piece, ...]


@dataclass(frozen=True)
class GlueJoin:
    code: str
    target_piece: str
    side: str


@dataclass(frozen=True)
class AssemblyStep:
    step: int
    piece: str
    glue: Tuple[GlueJoin, ...]
    text: str


@dataclass(frozen=True)
class Diagnostic:
    """A finding of the layout, with the fields of every PopUp diagnostic (docs/DIAGNOSTICS.md)."""

    severity: str
    code: str
    message: str
    patches: Tuple[int, ...]
    parameter: Optional[str]
    angle_deg: Optional[float]

    def to_dict(self):
        return {
            "code": self.code,
            "severity": self.severity,
            "message": self.message,
            "patches": list(self.patches),
            "parameter": self.parameter,
            "angle_deg": self.angle_deg,
        }


@dataclass(frozen=True)
class SheetSet:
    paper_name: str
    width: float  # mm
    height: float  # mm
    margin: float  # mm
    kerf: float  # mm, the cut lines' offset is half of it
    paper_thickness: float  # mm
    sheets: Tuple[Sheet, ...]
    cut_length: float  # mm, all cut loops
    stack_height: float  # mm
    assembly: Tuple[AssemblyStep, ...]
    diagnostics: Tuple[Diagnostic, ...]

    def pieces(self):
        return tuple(piece for sheet in self.sheets for piece in sheet.pieces)


class _Node:
    """A value of the sheet set and its key path, for error messages such as
    "sheet set: pieces[2].cut missing"."""

    def __init__(self, value, path=""):
        self.value = value
        self.path = path

    def error(self, problem):
        return ValueError(f"sheet set: {self.path or 'top level'} {problem}")

    def __getitem__(self, key):
        if not isinstance(self.value, dict):
            raise self.error("is not an object")
        path = f"{self.path}.{key}" if self.path else key
        if key not in self.value:
            raise ValueError(f"sheet set: {path} missing")
        return _Node(self.value[key], path)

    def items(self):
        if not isinstance(self.value, list):
            raise self.error("is not a list")
        return [_Node(item, f"{self.path}[{i}]") for i, item in enumerate(self.value)]

    def number(self, positive=False):
        value = self.value
        if (
            isinstance(value, bool)
            or not isinstance(value, (int, float))
            or not math.isfinite(value)
        ):
            raise self.error(f"is not a number: {value!r}")
        if positive and value <= 0:
            raise self.error(f"must be positive, not {value!r}")
        return float(value)

    def integer(self):
        if isinstance(self.value, bool) or not isinstance(self.value, int):
            raise self.error(f"is not an integer: {self.value!r}")
        return self.value

    def optional(self, read):
        """None for a JSON null, else the value read by `read` (a method of _Node)."""
        return None if self.value is None else read(self)

    def text(self, choices=None):
        if not isinstance(self.value, str):
            raise self.error(f"is not a string: {self.value!r}")
        if choices is not None and self.value not in choices:
            raise self.error(f"is {self.value!r}, expected one of {', '.join(choices)}")
        return self.value

    def point(self):
        if not isinstance(self.value, list) or len(self.value) != 2:
            raise self.error(f"is not a point [x, y]: {self.value!r}")
        x, y = (coordinate.number() for coordinate in self.items())
        return (x, y)

    def loop(self):
        points = tuple(point.point() for point in self.items())
        if len(points) < 3:
            raise self.error(f"has {len(points)} points, a loop needs at least 3")
        return points


def _to_sheet(node):
    rows = node.items()
    if len(rows) != 2:
        raise node.error(f"is not a 2 x 3 matrix: {node.value!r}")
    matrix = []
    for row in rows:
        values = tuple(value.number() for value in row.items())
        if len(values) != 3:
            raise row.error(f"has {len(values)} numbers, expected 3")
        matrix.append(values)
    (a, b, _), (c, d, _) = matrix
    if abs(abs(a * d - b * c) - 1.0) > 1e-6:
        raise node.error(f"is not a rotation or reflection: determinant {a * d - b * c:g}")
    return tuple(matrix)


def _flat_patch(node):
    return FlatPatch(
        id=node["id"].integer(),
        name=node["name"].text(),
        outer=node["outer"].loop(),
        holes=tuple(hole.loop() for hole in node["holes"].items()),
        to_sheet=_to_sheet(node["to_sheet"]) if "to_sheet" in node.value else None,
    )


def _region(node):
    return Region(node["outer"].loop(), tuple(hole.loop() for hole in node["holes"].items()))


def _piece(node):
    return Piece(
        id=node["id"].text(),
        sheet=node["sheet"].integer(),
        cut=tuple(_region(region) for region in node["cut"].items()),
        folds=tuple(
            Fold(
                fold["from"].point(),
                fold["to"].point(),
                fold["direction"].text(FOLD_DIRECTIONS),
                fold["kind"].text(("fold", "tab")),
            )
            for fold in node["folds"].items()
        ),
        tabs=tuple(
            Tab(tab["code"].text(), tab["target_piece"].text(), tab["side"].text(SIDES))
            for tab in node["tabs"].items()
        ),
        glue=tuple(
            GlueArea(
                area["code"].text(),
                area["polygon"].loop(),
                area["tab_piece"].text(),
                area["side"].text(SIDES),
            )
            for area in node["glue"].items()
        ),
        labels=tuple(
            Label(
                label["text"].text(),
                label["kind"].text(("piece", "tab", "glue", "fold")),
                label["position"].point(),
                label["height"].number(positive=True),
                label["angle"].number(),
            )
            for label in node["labels"].items()
        ),
        patches=tuple(_flat_patch(patch) for patch in node["patches"].items())
        if "patches" in node.value
        else (),
    )


def _sheets(root, pieces_by_id):
    """The sheets in index order, each with its pieces in the order the sheet lists them."""
    sheets = []
    placed = set()
    for position, node in enumerate(root["sheets"].items()):
        index = node["index"].integer()
        if index != position:
            raise node["index"].error(f"is {index}, expected {position} (sheets in index order)")
        pieces = []
        for id_node in node["pieces"].items():
            piece_id = id_node.text()
            if piece_id not in pieces_by_id:
                raise id_node.error(f"names unknown piece {piece_id!r}")
            if piece_id in placed:
                raise id_node.error(f"places piece {piece_id!r} a second time")
            piece, piece_path = pieces_by_id[piece_id]
            if piece.sheet != index:
                raise ValueError(
                    f"sheet set: {piece_path}.sheet is {piece.sheet} but sheets[{position}] "
                    f"lists {piece_id!r}"
                )
            placed.add(piece_id)
            pieces.append(piece)
        sheets.append(Sheet(index, tuple(pieces)))
    if not sheets:
        raise root["sheets"].error("is empty")
    for piece_id, (_, piece_path) in pieces_by_id.items():
        if piece_id not in placed:
            raise ValueError(f"sheet set: {piece_path} ({piece_id!r}) is on no sheet")
    return tuple(sheets)


def read_sheet_set(data):
    """Checks the sheet set `data` (a dict) and returns it as a SheetSet; ValueError if malformed."""
    root = _Node(data)
    if root["format"].text() != FORMAT:
        raise root["format"].error(f"is {data['format']!r}, expected {FORMAT!r}")
    if root["version"].integer() != VERSION:
        raise root["version"].error(f"is {data['version']!r}, this reader knows {VERSION}")
    pieces_by_id = {}
    for node in root["pieces"].items():
        piece = _piece(node)
        if piece.id in pieces_by_id:
            raise node["id"].error(f"repeats piece id {piece.id!r}")
        pieces_by_id[piece.id] = (piece, node.path)
    paper = root["paper"]
    options = root["options"]
    return SheetSet(
        paper_name=paper["name"].text(),
        width=paper["width"].number(positive=True),
        height=paper["height"].number(positive=True),
        margin=options["margin"].number(),
        kerf=options["kerf"].number(),
        paper_thickness=options["paper_thickness"].number(positive=True),
        sheets=_sheets(root, pieces_by_id),
        cut_length=root["cut_length"].number(),
        stack_height=root["stack_height"].number(),
        assembly=tuple(
            AssemblyStep(
                step=node["step"].integer(),
                piece=node["piece"].text(),
                glue=tuple(
                    GlueJoin(
                        join["code"].text(), join["target_piece"].text(), join["side"].text(SIDES)
                    )
                    for join in node["glue"].items()
                ),
                text=node["text"].text(),
            )
            for node in root["assembly"].items()
        ),
        diagnostics=tuple(
            Diagnostic(
                node["severity"].text(("error", "warning", "info")),
                node["code"].text(),
                node["message"].text(),
                tuple(item.integer() for item in node["patches"].items()),
                node["parameter"].optional(_Node.text),
                node["angle_deg"].optional(_Node.number),
            )
            for node in root["diagnostics"].items()
        ),
    )


def sheet_file_paths(path, count):
    """File names for `count` one-sheet files: `path` itself for the first sheet, then
    <stem>-2<ext>, <stem>-3<ext>, ... (numbered from 1 like the sheets printed in the instructions).
    """
    path = os.fspath(path)
    stem, extension = os.path.splitext(path)
    return [path] + [f"{stem}-{number}{extension}" for number in range(2, count + 1)]
