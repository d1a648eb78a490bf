"""Part shapes of a sheet set (docs/SHEET_FORMAT.md), in sheet coordinates at z = 0: the flat
pieces the CuttingSheet shows and the cut outlines its TechDraw pages draw. Needs FreeCAD."""

import FreeCAD
import Part


def _vector(point):
    return FreeCAD.Vector(point[0], point[1], 0.0)


def loop_wire(points):
    """A closed polygon wire through the [x, y] points of a loop (the last one not repeated)."""
    vectors = [_vector(p) for p in points]
    return Part.makePolygon(vectors + vectors[:1])


def region_face(outer, holes):
    """An exact planar face: the outer loop minus the hole loops."""
    return Part.Face([loop_wire(outer)] + [loop_wire(hole) for hole in holes])


def sheet_pieces(sheet_set, index):
    """The pieces on sheet `index`, in the sheet's order."""
    by_id = {piece["id"]: piece for piece in sheet_set["pieces"]}
    return [by_id[piece_id] for piece_id in sheet_set["sheets"][index]["pieces"]]


def flat_sheet(sheet_set, index):
    """Sheet `index` as a compound: every patch a face (pieces in order, patches in order), then
    every fold line and every tab outline a wire."""
    pieces = sheet_pieces(sheet_set, index)
    faces = [region_face(p["outer"], p["holes"]) for piece in pieces for p in piece["patches"]]
    folds = [
        Part.Wire(Part.makeLine(_vector(fold["from"]), _vector(fold["to"])))
        for piece in pieces
        for fold in piece["folds"]
    ]
    tabs = [loop_wire(tab["polygon"]) for piece in pieces for tab in piece["tabs"]]
    return Part.makeCompound(faces + folds + tabs)


def cut_outline(sheet_set, index):
    """What sheet `index` is cut along, without kerf: one face per region of `cut_nominal`. A page
    drawing these shows no edge inside a piece, so its folds show only as fold lines."""
    return Part.makeCompound(
        [
            region_face(region["outer"], region["holes"])
            for piece in sheet_pieces(sheet_set, index)
            for region in piece["cut_nominal"]
        ]
    )
