"""Assembly instructions PDF (A4): the paper, the pieces on each sheet, the glue steps in order,
the fold-line legend in the colours and dashes of the sheets, and the layout's diagnostics. For a
design the validity check rejects, the NOT VALID stamp heads every page and the check's findings
come first."""

from xml.sax.saxutils import escape

from reportlab.graphics.shapes import Drawing, Line
from reportlab.lib import colors
from reportlab.lib.pagesizes import A4
from reportlab.lib.styles import getSampleStyleSheet
from reportlab.lib.units import mm
from reportlab.platypus import Paragraph, SimpleDocTemplate, Spacer, Table, TableStyle

from .layer_style import SheetStyle
from .sheet_set import paper_size, pieces_by_sheet, side

LEGEND_LINE_LENGTH = 30.0  # mm
FOLD_MEANING = {
    "mountain": "Mountain fold: crease so that the line becomes a ridge, folding away from you "
    "(seen from the printed side).",
    "valley": "Valley fold: crease so that the line becomes a trough, folding towards you "
    "(seen from the printed side).",
}


PAGE_MARGIN = 20.0  # mm, every side
STAMP_SIZE = 12.0  # pt


def write_instructions(sheet_set, path, style=None, compress=True, not_valid=None):
    """Writes the assembly instructions for `sheet_set` (a popupcore.SheetSet) to the PDF `path`;
    returns `path`. compress=False leaves the page streams readable (tests grep the text).
    `not_valid` (a not_valid_stamp.NotValid) stamps every page and lists the validity findings
    first."""
    style = style or SheetStyle()
    styles = getSampleStyleSheet()
    document = SimpleDocTemplate(
        path,
        pagesize=A4,
        pageCompression=compress,
        title="Pop-up card: cutting and assembly",
        creator="PopUp",
        leftMargin=PAGE_MARGIN * mm,
        rightMargin=PAGE_MARGIN * mm,
        topMargin=PAGE_MARGIN * mm,
        bottomMargin=PAGE_MARGIN * mm,
    )
    story = [Paragraph("Pop-up card: cutting and assembly", styles["Title"])]
    if not_valid is not None:
        story += _not_valid_section(not_valid, styles)
    story += _paper_section(sheet_set)
    story += _pieces_section(sheet_set, styles)
    story += _assembly_section(sheet_set, styles)
    story += _legend_section(style, styles)
    story += _diagnostics_section(sheet_set, styles)
    if not_valid is None:
        document.build(story)
    else:

        def stamp(canvas, _document):  # in the top page margin, on every page
            canvas.saveState()
            canvas.setFont("Helvetica-Bold", STAMP_SIZE)
            canvas.setFillColorRGB(*style.cut.unit_colour())
            canvas.drawCentredString(A4[0] / 2.0, A4[1] - PAGE_MARGIN / 2.0 * mm, not_valid.text())
            canvas.restoreState()

        document.build(story, onFirstPage=stamp, onLaterPages=stamp)
    return path


def _not_valid_section(not_valid, styles):
    flowables = [
        Paragraph(escape(not_valid.text()), styles["Heading2"]),
        Paragraph(
            "The validity check rejects this design; these sheets were written on request "
            "(--force, or the CuttingSheet's Force property). Its findings:",
            styles["BodyText"],
        ),
    ]
    for finding in not_valid.findings or ("none reported",):
        flowables.append(Paragraph(escape(finding), styles["Bullet"], bulletText="-"))
    return flowables + [Spacer(1, 6 * mm)]


def _table(rows, column_widths, header=True):
    table = Table(rows, colWidths=[width * mm for width in column_widths], hAlign="LEFT")
    commands = [("VALIGN", (0, 0), (-1, -1), "TOP"), ("FONTSIZE", (0, 0), (-1, -1), 10)]
    if header:
        commands += [
            ("FONTNAME", (0, 0), (-1, 0), "Helvetica-Bold"),
            ("LINEBELOW", (0, 0), (-1, 0), 0.5, colors.black),
        ]
    table.setStyle(TableStyle(commands))
    return table


def _paper_section(sheet_set):
    width, height = paper_size(sheet_set)
    rows = [
        ["Paper", f"{sheet_set.options.paper}, {width:g} x {height:g} mm"],
        ["Paper thickness", f"{sheet_set.paper_thickness:g} mm"],
        ["Folded stack height", f"{sheet_set.stack_height:.2f} mm"],
        ["Sheets", str(sheet_set.sheet_count)],
        ["Pieces", str(len(sheet_set.pieces))],
        ["Total cut length", f"{sheet_set.cut_length:.0f} mm"],
    ]
    return [_table(rows, (45, 115), header=False), Spacer(1, 6 * mm)]


def _codes(items):
    return ", ".join(item.code for item in items) or "-"


def _pieces_section(sheet_set, styles):
    rows = [["Sheet", "Piece", "Tabs", "Glue areas"]]
    for index, pieces in enumerate(pieces_by_sheet(sheet_set)):
        for piece in pieces:
            rows.append([str(index + 1), piece.id, _codes(piece.tabs), _codes(piece.glue)])
    return [
        Paragraph("Pieces", styles["Heading2"]),
        Paragraph(
            "Cut out every piece along the red lines and crease every fold line before gluing. "
            "Tab codes match the glue areas they go on.",
            styles["BodyText"],
        ),
        Spacer(1, 2 * mm),
        _table(rows, (15, 25, 45, 45)),
        Spacer(1, 6 * mm),
    ]


def _assembly_section(sheet_set, styles):
    ids = [piece.id for piece in sheet_set.pieces]
    steps = sheet_set.assembly
    stepped = {ids[step.piece] for step in steps}
    on_sheets = [piece.id for pieces in pieces_by_sheet(sheet_set) for piece in pieces]
    bases = [piece_id for piece_id in on_sheets if piece_id not in stepped]
    body = styles["BodyText"]
    rows = [["Step", "Piece", "Glue", "Instruction"]]
    for number, step in enumerate(steps, start=1):
        joins = "<br/>".join(
            escape(f"tab {join.code} onto {ids[join.target_piece]}, {side(join.front)}")
            for join in step.joins
        )
        rows.append(
            [
                str(number),
                ids[step.piece],
                Paragraph(joins, body),
                Paragraph(escape(step.text), body),
            ]
        )
    return [
        Paragraph("Assembly", styles["Heading2"]),
        Paragraph(
            escape(f"Start from {', '.join(bases)}; glue the pieces on in this order."), body
        ),
        Spacer(1, 2 * mm),
        _table(rows, (12, 15, 45, 98)),
        Spacer(1, 6 * mm),
    ]


def _legend_line(layer):
    drawing = Drawing(LEGEND_LINE_LENGTH * mm, 4 * mm)
    line = Line(0, 2 * mm, LEGEND_LINE_LENGTH * mm, 2 * mm)
    line.strokeColor = colors.Color(*layer.unit_colour())
    line.strokeWidth = 2 * layer.line_width * mm  # twice the sheet width, to read on screen
    line.strokeDashArray = [length * mm for length in layer.dashes] or None
    drawing.add(line)
    return drawing


def _legend_section(style, styles):
    rows = [
        [
            _legend_line(style.fold(direction)),
            Paragraph(FOLD_MEANING[direction], styles["BodyText"]),
        ]
        for direction in ("mountain", "valley")
    ]
    rows.append([_legend_line(style.cut), Paragraph("Cut line.", styles["BodyText"])])
    return [
        Paragraph("Line legend", styles["Heading2"]),
        _table(rows, (35, 135), header=False),
        Spacer(1, 6 * mm),
    ]


def _diagnostics_section(sheet_set, styles):
    flowables = [Paragraph("Warnings", styles["Heading2"])]
    diagnostics = sheet_set.diagnostics
    if not diagnostics:
        return flowables + [Paragraph("None.", styles["BodyText"])]
    for diagnostic in diagnostics:
        text = f"{diagnostic.severity.capitalize()} ({diagnostic.code}): {diagnostic.message}"
        flowables.append(Paragraph(escape(text), styles["Bullet"], bulletText="-"))
    return flowables
