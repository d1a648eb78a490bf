"""The bound sheet set (popupcore.SheetSet, docs/SHEET_FORMAT.md) in the shapes the writers draw.

Every writer takes the SheetSet that popupcore.layout_sheets gives (export.layout), or that
popupcore.sheet_set_from_json reads back from a CuttingSheet's stored layout or a sheets.json
(checked there: a malformed one fails once, naming the key path). These helpers give its parts as
the writers draw them: the pieces sheet by sheet, loops as tuples of (x, y) floats, where a
label's baseline goes. No FreeCAD needed.
"""

import math
import os

import numpy


def pieces_by_sheet(sheet_set):
    """The pieces on each sheet, sheet 0 first, each sheet's in the sheet set's order (the
    "sheets" of sheets.json)."""
    pieces = sheet_set.pieces  # a new list at each access: read once
    return [[p for p in pieces if p.sheet == index] for index in range(sheet_set.sheet_count)]


def paper_size(sheet_set):
    """(width, height) of the paper, mm."""
    return sheet_set.options.paper_width, sheet_set.options.paper_height


def points(loop):
    """A loop (an (n, 2) array, or any [x, y] sequence) as a tuple of (x, y) floats."""
    return tuple(tuple(point) for point in numpy.asarray(loop, dtype=float).tolist())


def loops(region):
    """A region's (or a flat patch's) outer loop, then its holes, each as `points`."""
    return (points(region.outer),) + tuple(points(hole) for hole in region.holes)


def side(front):
    """A glue side as the files name it."""
    return "front" if front else "back"


def baseline_centre(label):
    """Where the middle of the baseline goes so that the cap height is centred on the label's
    position (writers whose text anchors on the baseline need this). `label`: a
    popupcore.SheetLabel, or anything with its position, height (cap height, mm) and angle
    (degrees counter-clockwise)."""
    turn = math.radians(label.angle)
    half = label.height / 2.0
    x, y = label.position
    return (x + half * math.sin(turn), y - half * math.cos(turn))


def sheet_file_paths(path, count):
    """File names for `count` one-sheet files: `path` itself for the first sheet, then
    <stem>-2<ext>, <stem>-3<ext>, ... (numbered from 1 like the sheets printed in the instructions).
    """
    path = os.fspath(path)
    stem, extension = os.path.splitext(path)
    return [path] + [f"{stem}-{number}{extension}" for number in range(2, count + 1)]
