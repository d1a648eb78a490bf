"""The marks of a cutting-sheet page: the sheet's glue areas and labels (and a NOT VALID stamp),
as the SVG of one TechDraw symbol view (DrawViewSymbol) covering the whole paper.

They are the exported SVG's GLUE and LABEL layers, made by svg_writer itself, so the page shows
them exactly as the cutting file does: grey-filled glue areas, labels in the same font, size,
place and angle. The cut and fold lines are left to the page's DrawViewPart (real edges a maker
can dimension, and TechDraw's DXF export). One object per page however many labels there are.

TechDraw draws a symbol's SVG at its size in pixels divided by 3.78 px/mm
(QGIViewSymbol::drawSvg), so the SVG's width and height are given in those pixels and its viewBox
in mm: one user unit is then exactly 1 mm on the page. No FreeCAD needed.
"""

from .layer_style import SheetStyle
from .not_valid_stamp import sheet_stamp
from .sheet_set import paper_size, pieces_by_sheet
from .svg_writer import sheet_svg_drawing

TECHDRAW_PX_PER_MM = 3.78  # QGIViewSymbol's pxMm
MARK_LAYERS = ("glue", "label")  # SheetStyle fields the symbol keeps; the view draws the rest


def marks_svg(sheet_set, index, not_valid=None, style=None):
    """The SVG text of sheet `index`'s marks (of the popupcore.SheetSet `sheet_set`): glue areas,
    labels, and `not_valid`'s stamp."""
    style = style or SheetStyle()
    stamp = sheet_stamp(sheet_set, not_valid)
    pieces = pieces_by_sheet(sheet_set)[index]
    drawing = sheet_svg_drawing(sheet_set, pieces, style, "", stamp)
    kept = {getattr(style, name).name for name in MARK_LAYERS}
    drawing.elements = [e for e in drawing.elements if getattr(e, "attribs", {}).get("id") in kept]
    width, height = paper_size(sheet_set)
    drawing.attribs["width"] = f"{width * TECHDRAW_PX_PER_MM:.4f}"
    drawing.attribs["height"] = f"{height * TECHDRAW_PX_PER_MM:.4f}"
    return drawing.tostring()
