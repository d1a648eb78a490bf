"""Printable PDF of the cutting sheets: one page per sheet, the page exactly the paper, drawn at 1:1
in the colours and dashes of layer_style.SheetStyle. Print it to cut by hand, or print and then
cut on a cutter with registration marks (print-then-cut). Sheets of a design the validity check
rejects carry the NOT VALID stamp (not_valid_stamp.py) on every page.

Registration marks (registration_marks=True): filled black squares of REGISTRATION_MARK_SIZE mm in
the top-left, top-right and bottom-left corners, each centred in the margin band (so it stays
clear of the pieces); the bottom-right corner is left empty so the cutter's camera can tell the
sheet's orientation. They are printed only: the DXF and SVG cut files carry none.
"""

from reportlab.lib.units import mm
from reportlab.pdfgen.canvas import Canvas

from .sheet_set import read_sheet_set
from .layer_style import SheetStyle
from .not_valid_stamp import stamp_label

FONT = "Helvetica"
CAP_HEIGHT = 0.718  # of the font size, Helvetica
REGISTRATION_MARK_SIZE = 5.0  # mm
REGISTRATION_CLEARANCE = 0.5  # mm, least distance between a mark and the printable pieces


def write_pdf(sheet_set, path, style=None, registration_marks=False, compress=True, not_valid=None):
    """Writes the sheets of `sheet_set` to the PDF `path`, one page each; returns `path`.
    compress=False leaves the page streams readable (tests grep them). `not_valid` (a
    not_valid_stamp.NotValid) stamps every page."""
    sheets = read_sheet_set(sheet_set)
    style = style or SheetStyle()
    if registration_marks:
        _check_room_for_marks(sheets.margin)
    canvas = Canvas(
        path, pagesize=(sheets.width * mm, sheets.height * mm), pageCompression=compress
    )
    canvas.setTitle(f"PopUp cutting sheets, {sheets.paper_name}")
    canvas.setCreator("PopUp")
    stamp = None
    if not_valid is not None:
        stamp = stamp_label(sheets.width, sheets.height, sheets.margin, not_valid)
    for sheet in sheets.sheets:
        canvas.scale(mm, mm)  # from here on, user units are mm with the origin lower left
        for piece in sheet.pieces:
            _draw_piece(canvas, piece, style)
        if stamp is not None:
            canvas.setFillColorRGB(*style.label.unit_colour())
            _draw_label(canvas, stamp)
        if registration_marks:
            _draw_registration_marks(canvas, sheets.width, sheets.height, sheets.margin)
        canvas.showPage()
    canvas.save()
    return path


def _check_room_for_marks(margin):
    needed = REGISTRATION_MARK_SIZE + 2 * REGISTRATION_CLEARANCE
    if margin < needed:
        raise ValueError(
            f"registration marks need a margin of at least {needed:g} mm; the sheet set has "
            f"{margin:g} mm"
        )


def _stroke_style(canvas, layer):
    canvas.setStrokeColorRGB(*layer.unit_colour())
    canvas.setLineWidth(layer.line_width)
    canvas.setDash(list(layer.dashes) or [], 0)


def _loop_path(canvas, loop):
    path = canvas.beginPath()
    path.moveTo(*loop[0])
    for point in loop[1:]:
        path.lineTo(*point)
    path.close()
    return path


def _draw_piece(canvas, piece, style):
    _stroke_style(canvas, style.glue)
    canvas.setFillColorRGB(*style.glue_fill_unit())
    for area in piece.glue:
        canvas.drawPath(_loop_path(canvas, area.polygon), stroke=1, fill=1)
    for fold in piece.folds:
        _stroke_style(canvas, style.fold(fold.direction))
        canvas.line(*fold.start, *fold.end)
    canvas.setFillColorRGB(*style.label.unit_colour())
    for label in piece.labels:
        _draw_label(canvas, label)
    _stroke_style(canvas, style.cut)
    for region in piece.cut:
        for loop in region.loops():
            canvas.drawPath(_loop_path(canvas, loop), stroke=1, fill=0)


def _draw_label(canvas, label):
    canvas.saveState()
    canvas.translate(*label.baseline_centre())
    canvas.rotate(label.angle)
    canvas.setFont(FONT, label.height / CAP_HEIGHT)
    canvas.drawCentredString(0, 0, label.text)
    canvas.restoreState()


def _draw_registration_marks(canvas, width, height, margin):
    inset = (margin - REGISTRATION_MARK_SIZE) / 2.0
    far_x = width - inset - REGISTRATION_MARK_SIZE
    far_y = height - inset - REGISTRATION_MARK_SIZE
    canvas.setFillColorRGB(0, 0, 0)
    for x, y in ((inset, far_y), (far_x, far_y), (inset, inset)):
        canvas.rect(x, y, REGISTRATION_MARK_SIZE, REGISTRATION_MARK_SIZE, stroke=0, fill=1)
