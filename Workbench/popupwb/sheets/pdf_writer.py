"""Printable PDF of the cutting sheets: one page per sheet, the page exactly the paper, drawn at 1:1
in the colours and dashes of layer_style.SheetStyle. Print it to cut by hand, or print and then
cut on a cutter with registration marks (print-then-cut). Sheets of a design the validity check
rejects carry the NOT VALID stamp (not_valid_stamp.py) on every page.

Registration marks (registration_marks=True, and always with artwork): registration_marks.py. The
DXF carries none; the SVG has them on its print layer when it carries artwork.

Artwork (print_artwork.py): each patch's image, clipped to the patch's flat outline, drawn under
the lines, for print-then-cut.
"""

from reportlab.lib.units import mm
from reportlab.pdfgen.canvas import FILL_EVEN_ODD, Canvas

from reportlab.lib.utils import ImageReader

from .layer_style import SheetStyle
from .not_valid_stamp import sheet_stamp
from .print_artwork import pil_image, place_artwork
from .registration_marks import MARK_SIZE, check_room_for_marks, mark_squares
from .sheet_set import baseline_centre, loops, paper_size, pieces_by_sheet, points

FONT = "Helvetica"
CAP_HEIGHT = 0.718  # of the font size, Helvetica
REGISTRATION_MARK_SIZE = MARK_SIZE  # mm


def write_pdf(
    sheet_set,
    path,
    style=None,
    registration_marks=False,
    compress=True,
    not_valid=None,
    artwork=None,
):
    """Writes the sheets of `sheet_set` (a popupcore.SheetSet) to the PDF `path`, one page each;
    returns `path`. compress=False leaves the page streams readable (tests grep them). `not_valid`
    (a not_valid_stamp.NotValid) stamps every page. `artwork`: {patch id: popupcore.PatchArtwork}
    (print_artwork.py), printed on the patches; registration marks come with it."""
    style = style or SheetStyle()
    placed = place_artwork(sheet_set, artwork)
    registration_marks = registration_marks or bool(artwork)
    margin = sheet_set.options.margin
    if registration_marks:
        check_room_for_marks(margin)
    width, height = paper_size(sheet_set)
    canvas = Canvas(path, pagesize=(width * mm, height * mm), pageCompression=compress)
    canvas.setTitle(f"PopUp cutting sheets, {sheet_set.options.paper}")
    canvas.setCreator("PopUp")
    stamp = sheet_stamp(sheet_set, not_valid)
    for index, pieces in enumerate(pieces_by_sheet(sheet_set)):
        canvas.scale(mm, mm)  # from here on, user units are mm with the origin lower left
        for item in placed.get(index, ()):
            _draw_artwork(canvas, item)
        for piece in pieces:
            _draw_piece(canvas, piece, style)
        if stamp is not None:
            canvas.setFillColorRGB(*style.label.unit_colour())
            _draw_label(canvas, stamp)
        if registration_marks:
            _draw_registration_marks(canvas, width, height, margin)
        canvas.showPage()
    canvas.save()
    return path


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
        canvas.drawPath(_loop_path(canvas, points(area.polygon)), stroke=1, fill=1)
    for fold in piece.folds:
        _stroke_style(canvas, style.fold(fold.direction))
        canvas.line(*fold.start, *fold.end)
    canvas.setFillColorRGB(*style.label.unit_colour())
    for label in piece.labels:
        _draw_label(canvas, label)
    _stroke_style(canvas, style.cut)
    for region in piece.cut:
        for loop in loops(region):
            canvas.drawPath(_loop_path(canvas, loop), stroke=1, fill=0)


def _draw_label(canvas, label):
    canvas.saveState()
    canvas.translate(*baseline_centre(label))
    canvas.rotate(label.angle)
    canvas.setFont(FONT, label.height / CAP_HEIGHT)
    canvas.drawCentredString(0, 0, label.text)
    canvas.restoreState()


def _draw_artwork(canvas, item):
    """One patch's image, clipped to its flat outline (holes cut out, even-odd)."""
    canvas.saveState()
    outline = canvas.beginPath()
    for loop in loops(item.patch):
        outline.moveTo(*loop[0])
        for point in loop[1:]:
            outline.lineTo(*point)
        outline.close()
    canvas.clipPath(outline, stroke=0, fill=0, fillMode=FILL_EVEN_ODD)  # holes cut out
    (a, c, e), (b, d, f) = item.image_to_sheet
    canvas.transform(a, b, c, d, e, f)  # image mm (x right, y up) -> sheet mm
    width, height = item.size_mm
    canvas.drawImage(
        ImageReader(pil_image(item.rgba)), 0, 0, width, height, mask="auto", anchor="sw"
    )
    canvas.restoreState()


def _draw_registration_marks(canvas, width, height, margin):
    canvas.setFillColorRGB(0, 0, 0)
    for x, y in mark_squares(width, height, margin):
        canvas.rect(x, y, MARK_SIZE, MARK_SIZE, stroke=0, fill=1)
