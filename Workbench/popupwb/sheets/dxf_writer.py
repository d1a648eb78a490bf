"""DXF cutting file (R2010, millimetres) of a sheet set, for laser and blade cutters and CAD.

Layers (layer_style.SheetStyle): CUT holds only closed LWPOLYLINEs, one per cut loop; MOUNTAIN and
VALLEY one LINE per fold; GLUE the outline of each glue area; LABEL centred TEXT (and, for a
design the validity check rejects, the NOT VALID stamp of not_valid_stamp.py on every sheet).
Entities take colour and linetype BYLAYER, so a cutter can map layers (or colours) to operations.
The header's custom properties record the kerf the CUT lines were written with (PopUpKerf, mm)
and the paper thickness (PopUpPaperThickness, mm).
"""

import ezdxf
from ezdxf.enums import TextEntityAlignment

from .layer_style import SheetStyle
from .not_valid_stamp import sheet_stamp
from .sheet_set import loops, paper_size, pieces_by_sheet, points, sheet_file_paths

# All sheets share one file side by side: sheet k's origin is at x = k * (paper width + SHEET_GAP).
SHEET_GAP = 20.0  # mm
INSUNITS_MM = 4
MEASUREMENT_METRIC = 1
KERF_PROPERTY = "PopUpKerf"  # mm, in the header's custom properties
THICKNESS_PROPERTY = "PopUpPaperThickness"  # mm


def write_dxf(sheet_set, path, style=None, not_valid=None):
    """Writes every sheet of `sheet_set` (a popupcore.SheetSet) into one DXF at `path`, side by
    side; returns `path`. `not_valid` (a not_valid_stamp.NotValid) stamps every sheet."""
    style = style or SheetStyle()
    doc = _new_document(style, sheet_set)
    pitch = paper_size(sheet_set)[0] + SHEET_GAP
    stamp = sheet_stamp(sheet_set, not_valid)
    for index, pieces in enumerate(pieces_by_sheet(sheet_set)):
        _draw_sheet(doc.modelspace(), pieces, style, x_offset=index * pitch, stamp=stamp)
    doc.saveas(path)
    return path


def write_dxf_per_sheet(sheet_set, path, style=None, not_valid=None):
    """Writes one DXF per sheet, each at the origin: `path` for the first sheet, then
    <stem>-2.dxf, <stem>-3.dxf, ...; returns the paths written."""
    style = style or SheetStyle()
    paths = sheet_file_paths(path, sheet_set.sheet_count)
    stamp = sheet_stamp(sheet_set, not_valid)
    for pieces, sheet_path in zip(pieces_by_sheet(sheet_set), paths):
        doc = _new_document(style, sheet_set)
        _draw_sheet(doc.modelspace(), pieces, style, x_offset=0.0, stamp=stamp)
        doc.saveas(sheet_path)
    return paths


def _new_document(style, sheet_set):
    doc = ezdxf.new("R2010", setup=True, units=INSUNITS_MM)
    # What a re-reader needs besides the layers: the kerf the CUT lines were offset by (half on
    # each side), so the nominal outlines can be recovered; CAD programs keep custom properties.
    doc.header.custom_vars.append(KERF_PROPERTY, repr(sheet_set.options.kerf))
    doc.header.custom_vars.append(THICKNESS_PROPERTY, repr(sheet_set.paper_thickness))
    doc.header["$INSUNITS"] = INSUNITS_MM
    doc.header["$MEASUREMENT"] = MEASUREMENT_METRIC
    for layer in style.layers():
        _define_linetype(doc, layer)
        doc.layers.add(layer.name, color=layer.aci, linetype=layer.linetype)
    return doc


def _define_linetype(doc, layer):
    """Gives the layer's linetype the style's dash pattern in mm, so the DXF shows the same dashes
    as the SVG and PDF (ezdxf's standard DASHED/DASHDOT patterns are about 1 mm long). The
    standard names are kept: viewers such as LibreCAD pick their own pattern by name."""
    if not layer.dashes:
        if not doc.linetypes.has_entry(layer.linetype):
            raise ValueError(f"layer {layer.name}: DXF linetype {layer.linetype!r} is unknown")
        return
    pattern = [sum(layer.dashes)]
    for position, length in enumerate(layer.dashes):
        pattern.append(length if position % 2 == 0 else -length)
    if doc.linetypes.has_entry(layer.linetype):
        doc.linetypes.get(layer.linetype).setup_pattern(pattern)
    else:
        doc.linetypes.add(layer.linetype, pattern, description=layer.name.lower())


def _draw_sheet(modelspace, pieces, style, x_offset, stamp=None):
    def shifted(loop):
        return [(x + x_offset, y) for x, y in loop]

    for piece in pieces:
        for region in piece.cut:
            for loop in loops(region):
                modelspace.add_lwpolyline(
                    shifted(loop), format="xy", close=True, dxfattribs={"layer": style.cut.name}
                )
        for fold in piece.folds:
            start, end = shifted((fold.start, fold.end))
            modelspace.add_line(start, end, dxfattribs={"layer": style.fold(fold.direction).name})
        for area in piece.glue:
            modelspace.add_lwpolyline(
                shifted(points(area.polygon)),
                format="xy",
                close=True,
                dxfattribs={"layer": style.glue.name},
            )
        for label in piece.labels:
            _draw_label(modelspace, label, style, shifted)
    if stamp is not None:
        _draw_label(modelspace, stamp, style, shifted)


def _draw_label(modelspace, label, style, shifted):
    (position,) = shifted((label.position,))
    text = modelspace.add_text(
        label.text,
        height=label.height,
        rotation=label.angle,
        dxfattribs={"layer": style.label.name},
    )
    # MIDDLE_CENTER centres the cap height on the point, as the sheet format specifies.
    text.set_placement(position, align=TextEntityAlignment.MIDDLE_CENTER)
