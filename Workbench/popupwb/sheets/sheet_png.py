"""PNG preview of one sheet (make demo, reports): the paper at 1:1 scale for the given dpi, in the
colours and dashes of layer_style.SheetStyle. Matplotlib's Agg canvas, no display and no pyplot
state, so it is safe inside FreeCAD and in tests."""

import matplotlib
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.patches import Polygon, Rectangle

from .layer_style import SheetStyle
from .sheet_set import baseline_centre, loops, paper_size, pieces_by_sheet, points

MM_PER_INCH = 25.4
PT_PER_MM = 72.0 / MM_PER_INCH
FONT = "DejaVu Sans"
CAP_HEIGHT = 0.729  # of the font size, DejaVu Sans
PAPER_EDGE = (0.6, 0.6, 0.6)


def png_size(width_mm, height_mm, dpi):
    """Pixel size of a preview: the paper size at `dpi`, rounded to whole pixels."""
    return round(width_mm / MM_PER_INCH * dpi), round(height_mm / MM_PER_INCH * dpi)


def render_sheet_png(sheet_set, sheet_index, path, dpi=100, style=None):
    """Writes sheet `sheet_index` (0-based) of `sheet_set` (a popupcore.SheetSet) as a PNG at
    `path`; returns `path`."""
    if not 0 <= sheet_index < sheet_set.sheet_count:
        raise ValueError(f"sheet index {sheet_index} outside 0..{sheet_set.sheet_count - 1}")
    style = style or SheetStyle()
    paper_width, paper_height = paper_size(sheet_set)
    pixels = png_size(paper_width, paper_height, dpi)
    figure = Figure(figsize=(pixels[0] / dpi, pixels[1] / dpi), dpi=dpi, facecolor="white")
    FigureCanvasAgg(figure)
    axes = figure.add_axes((0, 0, 1, 1))
    axes.set_xlim(0, paper_width)
    axes.set_ylim(0, paper_height)
    axes.set_axis_off()
    # Lines at least one pixel wide, or a 0.2 mm line fades out at low dpi.
    min_width = 72.0 / dpi

    def width(layer):
        return max(layer.line_width * PT_PER_MM, min_width)

    axes.add_patch(
        Rectangle((0, 0), paper_width, paper_height, fill=False, edgecolor=PAPER_EDGE, lw=1)
    )
    # Dashes in mm on paper, not in multiples of the line width (matplotlib's default).
    with matplotlib.rc_context({"lines.scale_dashes": False}):
        for piece in pieces_by_sheet(sheet_set)[sheet_index]:
            for area in piece.glue:
                axes.add_patch(
                    Polygon(
                        points(area.polygon),
                        closed=True,
                        facecolor=style.glue_fill_unit(),
                        edgecolor=style.glue.unit_colour(),
                        lw=width(style.glue),
                    )
                )
            for fold in piece.folds:
                layer = style.fold(fold.direction)
                axes.plot(
                    (fold.start[0], fold.end[0]),
                    (fold.start[1], fold.end[1]),
                    color=layer.unit_colour(),
                    lw=width(layer),
                    linestyle=(0, [length * PT_PER_MM for length in layer.dashes])
                    if layer.dashes
                    else "solid",
                )
            for label in piece.labels:
                axes.text(
                    *baseline_centre(label),
                    label.text,
                    color=style.label.unit_colour(),
                    fontfamily=FONT,
                    fontsize=label.height / CAP_HEIGHT * PT_PER_MM,
                    rotation=label.angle,
                    rotation_mode="anchor",
                    ha="center",
                    va="baseline",
                )
            for region in piece.cut:
                for loop in loops(region):
                    closed = loop + loop[:1]
                    axes.plot(
                        [x for x, _ in closed],
                        [y for _, y in closed],
                        color=style.cut.unit_colour(),
                        lw=width(style.cut),
                    )
    figure.savefig(path, dpi=dpi, facecolor="white")
    return path
