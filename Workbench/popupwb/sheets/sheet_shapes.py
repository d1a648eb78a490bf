"""Part shapes of a sheet set (a popupcore.SheetSet, docs/SHEET_FORMAT.md), in sheet coordinates
at z = 0: the flat pieces the CuttingSheet shows and the cut outlines its TechDraw pages draw.
Needs FreeCAD."""

import FreeCAD
import Part

from popupwb import freecad_version

from .sheet_set import loops, pieces_by_sheet, points


def _vector(point):
    return FreeCAD.Vector(point[0], point[1], 0.0)


def loop_wire(loop):
    """A closed polygon wire through the (x, y) points of a loop (the last one not repeated)."""
    vectors = [_vector(p) for p in loop]
    return Part.makePolygon(vectors + vectors[:1])


def region_face(region):
    """An exact planar face: the outer loop of `region` (or of a flat patch) minus its holes."""
    return Part.Face([loop_wire(loop) for loop in loops(region)])


def flat_sheet(sheet_set, index):
    """Sheet `index` as a compound: every patch a face (pieces in order, patches in order), then
    every fold line and every tab outline a wire."""
    pieces = pieces_by_sheet(sheet_set)[index]
    faces = [region_face(patch) for piece in pieces for patch in piece.patches]
    folds = [
        Part.Wire(Part.makeLine(_vector(fold.start), _vector(fold.end)))
        for piece in pieces
        for fold in piece.folds
    ]
    tabs = [loop_wire(points(tab.polygon)) for piece in pieces for tab in piece.tabs]
    return freecad_version.compound(faces + folds + tabs)


def cut_outline(sheet_set, index):
    """What sheet `index` is cut along, without kerf: one face per region of `cut_nominal`. A page
    drawing these shows no edge inside a piece, so its folds show only as fold lines."""
    return freecad_version.compound(
        [
            region_face(region)
            for piece in pieces_by_sheet(sheet_set)[index]
            for region in piece.cut_nominal
        ]
    )
