"""SVG cutting files, one per sheet, as cutter software (Inkscape, Cricut, Silhouette, LightBurn)
imports them: the page is the paper in mm with a viewBox in mm, so one user unit is 1 mm, and each
layer of layer_style.SheetStyle is an Inkscape layer (a rejected design's NOT VALID stamp goes on
LABEL). Styles sit on every element rather than on
the layer groups because some cutter software ignores inherited styles.

With artwork (print_artwork.py) a sheet becomes a print-then-cut file: a PRINT layer under the
others holds each patch's image (a base64 PNG <image>, clipped by a clipPath that is the patch's
flat outline) and the registration marks (registration_marks.py), which are also drawn when
registration_marks=True.
"""

import svgwrite

from .layer_style import SheetStyle
from .not_valid_stamp import sheet_stamp
from .print_artwork import place_artwork, png_data_uri
from .sheet_set import baseline_centre, loops, paper_size, pieces_by_sheet, points, sheet_file_paths
from .registration_marks import MARK_SIZE, check_room_for_marks, mark_squares

INKSCAPE_NAMESPACE = "http://www.inkscape.org/namespaces/inkscape"
FONT_FAMILY = "Helvetica, Arial, sans-serif"
CAP_HEIGHT = 0.716  # of the font size, Helvetica/Arial
PRINT_LAYER = "PRINT"  # artwork and registration marks: printed, never cut


def write_svg(sheet_set, path, style=None, not_valid=None, artwork=None, registration_marks=False):
    """Writes one SVG per sheet of `sheet_set` (a popupcore.SheetSet): `path` for the first
    sheet, then <stem>-2.svg, <stem>-3.svg, ...; returns the paths written. `not_valid` (a
    not_valid_stamp.NotValid) stamps every sheet. `artwork`: {patch id: popupcore.PatchArtwork}
    (print_artwork.py) on the PRINT layer, with registration marks."""
    style = style or SheetStyle()
    placed = place_artwork(sheet_set, artwork)
    registration_marks = registration_marks or bool(artwork)
    if registration_marks:
        check_room_for_marks(sheet_set.options.margin)
    paths = sheet_file_paths(path, sheet_set.sheet_count)
    stamp = sheet_stamp(sheet_set, not_valid)
    for index, (pieces, sheet_path) in enumerate(zip(pieces_by_sheet(sheet_set), paths)):
        drawing = sheet_svg_drawing(
            sheet_set,
            pieces,
            style,
            sheet_path,
            stamp,
            placed.get(index, ()),
            registration_marks,
        )
        drawing.save(pretty=True)
    return paths


def _number(value):
    """Micrometre precision without trailing zeros."""
    text = f"{value:.6f}".rstrip("0").rstrip(".")
    return "0" if text == "-0" else text


def sheet_svg_drawing(
    sheet_set, pieces, style, path, stamp=None, artwork=(), registration_marks=False
):
    """One sheet, its `pieces` (of the popupcore.SheetSet `sheet_set`), as an svgwrite.Drawing in
    millimetres, a group per layer of `style` (glue, mountain, valley, label, cut) and the stamp
    when given; the file writer and the TechDraw page marks share it. `artwork`
    (print_artwork.PlacedArtwork of this sheet) and the registration marks go on a PRINT layer
    under the others."""
    width, height = paper_size(sheet_set)
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

    if artwork or registration_marks:
        _add_print_layer(drawing, artwork, registration_marks, sheet_set, flipped, loop_path)

    layers = {}
    # Drawing order, bottom to top: glue areas under the lines, cut lines over everything.
    for layer in (style.glue, style.mountain, style.valley, style.label, style.cut):
        group = drawing.g(id=layer.name)
        group.attribs["inkscape:groupmode"] = "layer"
        group.attribs["inkscape:label"] = layer.name
        layers[layer.name] = drawing.add(group)

    def text(label):
        anchor = flipped(baseline_centre(label))
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

    for piece in pieces:
        for area in piece.glue:
            glue = dict(stroke(style.glue), fill=svgwrite.rgb(*style.glue_fill))
            layers[style.glue.name].add(drawing.path(d=loop_path(points(area.polygon)), **glue))
        for fold in piece.folds:
            layer = style.fold(fold.direction)
            line = drawing.line(start=flipped(fold.start), end=flipped(fold.end), **stroke(layer))
            layers[layer.name].add(line)
        for label in piece.labels:
            layers[style.label.name].add(text(label))
        for region in piece.cut:
            # One path per loop: a cutter runs each as its own closed contour.
            for loop in loops(region):
                layers[style.cut.name].add(drawing.path(d=loop_path(loop), **stroke(style.cut)))
    if stamp is not None:
        layers[style.label.name].add(text(stamp))
    return drawing


def _add_print_layer(drawing, artwork, registration_marks, sheet_set, flipped, loop_path):
    """The PRINT layer: each image clipped to its patch's outline, and the registration marks."""
    group = drawing.g(id=PRINT_LAYER)
    group.attribs["inkscape:groupmode"] = "layer"
    group.attribs["inkscape:label"] = PRINT_LAYER
    drawing.add(group)
    width, height = paper_size(sheet_set)
    for item in artwork:
        clip_id = f"clip-patch-{item.patch.id}"
        clip = drawing.defs.add(drawing.clipPath(id=clip_id))
        outline = " ".join(loop_path(loop) for loop in loops(item.patch))
        clip.add(drawing.path(d=outline, clip_rule="evenodd"))
        # Image space: mm from its top-left corner, y down. Through its lower-left corner frame
        # (y up) onto the sheet (y up), then the SVG's y flip: F A F with F = diag(1, -1).
        (a, c, e), (b, d, f) = item.image_to_sheet
        width_mm, height_mm = item.size_mm
        matrix = (a, -b, -c, d, c * height_mm + e, height - (d * height_mm + f))
        image = drawing.image(
            href=png_data_uri(item.rgba),
            insert=(0, 0),
            size=(_number(width_mm), _number(height_mm)),
        )
        image["preserveAspectRatio"] = "none"
        image["transform"] = "matrix(" + " ".join(_number(value) for value in matrix) + ")"
        image["id"] = f"artwork-patch-{item.patch.id}"
        clipped = drawing.g(clip_path=f"url(#{clip_id})")
        clipped.add(image)
        group.add(clipped)
    if registration_marks:
        for x, y in mark_squares(width, height, sheet_set.options.margin):
            corner = flipped((x, y + MARK_SIZE))
            group.add(
                drawing.rect(
                    insert=corner, size=(_number(MARK_SIZE), _number(MARK_SIZE)), fill="#000000"
                )
            )
