"""SVG cutting files, one per sheet, as cutter software (Inkscape, Cricut, Silhouette, LightBurn)
imports them: the page is the paper in mm with a viewBox in mm, so one user unit is 1 mm, and each
layer of layer_style.SheetStyle is an Inkscape layer (a rejected design's NOT VALID stamp goes on
LABEL). Styles sit on every element rather than on
the layer groups because some cutter software ignores inherited styles.
"""

import svgwrite

from .sheet_set import read_sheet_set, sheet_file_paths
from .layer_style import SheetStyle
from .not_valid_stamp import stamp_label

INKSCAPE_NAMESPACE = "http://www.inkscape.org/namespaces/inkscape"
FONT_FAMILY = "Helvetica, Arial, sans-serif"
CAP_HEIGHT = 0.716  # of the font size, Helvetica/Arial


def write_svg(sheet_set, path, style=None, not_valid=None):
    """Writes one SVG per sheet: `path` for the first sheet, then <stem>-2.svg, <stem>-3.svg, ...;
    returns the paths written. `not_valid` (a not_valid_stamp.NotValid) stamps every sheet."""
    sheets = read_sheet_set(sheet_set)
    style = style or SheetStyle()
    paths = sheet_file_paths(path, len(sheets.sheets))
    stamp = None
    if not_valid is not None:
        stamp = stamp_label(sheets.width, sheets.height, sheets.margin, not_valid)
    for sheet, sheet_path in zip(sheets.sheets, paths):
        sheet_svg_drawing(sheets, sheet, style, sheet_path, stamp).save(pretty=True)
    return paths


def _number(value):
    """Micrometre precision without trailing zeros."""
    text = f"{value:.6f}".rstrip("0").rstrip(".")
    return "0" if text == "-0" else text


def sheet_svg_drawing(sheets, sheet, style, path, stamp=None):
    """One sheet as an svgwrite.Drawing in millimetres, a group per layer of `style` (glue,
    mountain, valley, label, cut) and the stamp when given; the file writer and the TechDraw page
    marks share it."""
    width, height = sheets.width, sheets.height
    drawing = svgwrite.Drawing(
        path,
        size=(f"{_number(width)}mm", f"{_number(height)}mm"),
        viewBox=f"0 0 {_number(width)} {_number(height)}",
        profile="full",
        debug=False,  # svgwrite's validator rejects the inkscape: attributes
    )
    drawing.attribs["xmlns:inkscape"] = INKSCAPE_NAMESPACE

    def flipped(point):  # sheet y goes up, SVG y goes down
        return (_number(point[0]), _number(height - point[1]))

    def loop_path(loop):
        return "M " + " L ".join(",".join(flipped(point)) for point in loop) + " Z"

    def stroke(layer):
        attributes = {
            "stroke": layer.hex_colour(),
            "stroke_width": _number(layer.line_width),
            "fill": "none",
        }
        if layer.dashes:
            attributes["stroke_dasharray"] = " ".join(_number(length) for length in layer.dashes)
        return attributes

    layers = {}
    # Drawing order, bottom to top: glue areas under the lines, cut lines over everything.
    for layer in (style.glue, style.mountain, style.valley, style.label, style.cut):
        group = drawing.g(id=layer.name)
        group.attribs["inkscape:groupmode"] = "layer"
        group.attribs["inkscape:label"] = layer.name
        layers[layer.name] = drawing.add(group)

    def text(label):
        anchor = flipped(label.baseline_centre())
        element = drawing.text(
            label.text,
            insert=anchor,
            fill=style.label.hex_colour(),
            font_family=FONT_FAMILY,
            font_size=_number(label.height / CAP_HEIGHT),
            text_anchor="middle",
        )
        if label.angle:
            # SVG turns clockwise in its y-down frame: a counter-clockwise angle is negative.
            element["transform"] = f"rotate({_number(-label.angle)} {anchor[0]} {anchor[1]})"
        return element

    for piece in sheet.pieces:
        for area in piece.glue:
            glue = dict(stroke(style.glue), fill=svgwrite.rgb(*style.glue_fill))
            layers[style.glue.name].add(drawing.path(d=loop_path(area.polygon), **glue))
        for fold in piece.folds:
            layer = style.fold(fold.direction)
            line = drawing.line(start=flipped(fold.start), end=flipped(fold.end), **stroke(layer))
            layers[layer.name].add(line)
        for label in piece.labels:
            layers[style.label.name].add(text(label))
        for region in piece.cut:
            # One path per loop: a cutter runs each as its own closed contour.
            for loop in region.loops():
                layers[style.cut.name].add(drawing.path(d=loop_path(loop), **stroke(style.cut)))
    if stamp is not None:
        layers[style.label.name].add(text(stamp))
    return drawing
