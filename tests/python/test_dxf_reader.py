"""The DXF reader of `popup verify` (popupwb/sheets/dxf_reader.py): what the writer draws comes
back exactly; what a maker's CAD program may write instead (arcs, blocks, loose lines, other
alignments, lower-case layers, inches) is read as the same drawing; everything it cannot read is
one error naming the file, the layer and the entity."""

import json
import math
import os
import re
import shutil

import ezdxf
import pytest
from ezdxf.enums import MTextEntityAlignment, TextEntityAlignment

from popupwb.core import popupcore
from popupwb.sheets.dxf_reader import (
    FLATTEN_TOLERANCE,
    DxfReadError,
    read_dxf,
    read_sheet_drawing,
)
from popupwb.sheets.dxf_writer import SHEET_GAP, write_dxf
from popupwb.sheets.export import export_sheets, layout

SOURCE_DIR = os.environ["POPUP_SOURCE_DIR"]
DATA = os.path.join(SOURCE_DIR, "tests", "data")
# Two sheets on A3 (the second one is drawn 440 mm to the right), and a card with every kind of
# mechanism on one sheet.
ROUND_TRIP_DESIGNS = ["many_pieces.json", "mechanisms/demo_card.json", "mechanisms/box.json"]
EXACT = 1e-9  # mm


@pytest.fixture(scope="module", params=ROUND_TRIP_DESIGNS, ids=lambda name: name.split("/")[-1])
def written(request, tmp_path_factory):
    """(the layout as sheets.json spells it, the core's SheetSet, sheets.dxf path) of a design
    laid out on A3."""
    scaffold = popupcore.load_scaffold(os.path.join(DATA, request.param))
    core_set = layout(scaffold, paper="A3", kerf=0.15)
    out = tmp_path_factory.mktemp("dxf_reader")
    paths = export_sheets(core_set, str(out))
    with open(paths["sheet_set"]) as f:
        return json.load(f), core_set, paths["dxf"]


def close_points(a, b, tolerance=EXACT):
    return len(a) == len(b) and all(math.dist(p, q) <= tolerance for p, q in zip(a, b))


def written_entities(sheet_set):
    """What the writer draws, in its order, with sheet k moved k * (paper width + 20 mm)."""
    pitch = sheet_set["paper"]["width"] + SHEET_GAP
    cut, folds, glue, labels = [], [], [], []
    for sheet in sheet_set["sheets"]:
        dx = sheet["index"] * pitch
        for piece in (p for p in sheet_set["pieces"] if p["sheet"] == sheet["index"]):

            def moved(points):
                return [(x + dx, y) for x, y in points]

            for region in piece["cut"]:
                cut.extend(moved(loop) for loop in [region["outer"], *region["holes"]])
            folds.extend((*moved([f["from"], f["to"]]), f["direction"]) for f in piece["folds"])
            glue.extend(moved(g["polygon"]) for g in piece["glue"])
            labels.extend((t["text"], moved([t["position"]])[0]) for t in piece["labels"])
    return cut, folds, glue, labels


def test_the_written_entities_come_back_exactly(written):
    sheet_set, _, path = written
    drawing = read_dxf(path)
    cut, folds, glue, labels = written_entities(sheet_set)
    assert drawing.name == "sheets.dxf" and drawing.kerf == 0.15
    assert (len(drawing.cut), len(drawing.folds), len(drawing.glue), len(drawing.labels)) == (
        len(cut),
        len(folds),
        len(glue),
        len(labels),
    )
    for read, loop in zip(drawing.cut, cut):
        assert close_points(read, loop)
    for read, (start, end, direction) in zip(drawing.folds, folds):
        assert read.direction == direction and close_points([read.start, read.end], [start, end])
    for read, polygon in zip(drawing.glue, glue):
        assert close_points(read, polygon)  # same vertex order: the first edge is the crease
    for read, (text, position) in zip(drawing.labels, labels):
        assert read.text == text and math.dist(read.position, position) <= EXACT


def test_the_drawing_is_the_cores_own_drawing_of_the_sheets(written):
    """popupcore.draw_sheets draws each sheet at its own origin: the reader's drawing of the file
    holding every sheet is their union, each moved to its place."""
    sheet_set, core_set, path = written
    drawing = read_sheet_drawing(path, popupcore)
    assert isinstance(drawing, popupcore.SheetDrawing)
    pitch = sheet_set["paper"]["width"] + SHEET_GAP
    cut, folds, glue, labels = [], [], [], []
    for k, sheet in enumerate(popupcore.draw_sheets(core_set)):
        assert sheet.kerf == drawing.kerf == 0.15
        cut += [[(x + k * pitch, y) for x, y in loop] for loop in sheet.cut]
        folds += [((f.start[0] + k * pitch, f.start[1]), f.direction) for f in sheet.folds]
        glue += [[(x + k * pitch, y) for x, y in loop] for loop in sheet.glue]
        labels += [(t.text, (t.position[0] + k * pitch, t.position[1])) for t in sheet.labels]
    assert len(drawing.cut) == len(cut) and len(drawing.glue) == len(glue)
    assert all(close_points(a, b) for a, b in zip(drawing.cut, cut))
    assert all(close_points(a, b) for a, b in zip(drawing.glue, glue))
    assert [(f.direction) for f in drawing.folds] == [d for _, d in folds]
    assert all(math.dist(f.start, s) <= EXACT for f, (s, _) in zip(drawing.folds, folds))
    assert [t.text for t in drawing.labels] == [t for t, _ in labels]
    assert all(math.dist(t.position, p) <= EXACT for t, (_, p) in zip(drawing.labels, labels))


def test_counts_per_layer_are_the_files(written):
    _, _, path = written
    space = ezdxf.readfile(path).modelspace()
    drawing = read_dxf(path)

    def count(query):
        return len(space.query(query))

    assert len(drawing.cut) == count("LWPOLYLINE[layer=='CUT']")
    assert len(drawing.glue) == count("LWPOLYLINE[layer=='GLUE']")
    assert sum(f.direction == "mountain" for f in drawing.folds) == count("LINE[layer=='MOUNTAIN']")
    assert sum(f.direction == "valley" for f in drawing.folds) == count("LINE[layer=='VALLEY']")
    assert len(drawing.labels) == count("TEXT[layer=='LABEL']")


# --- the kerf -------------------------------------------------------------------------------


def without_kerf_header(source, target):
    doc = ezdxf.readfile(source)
    doc.header.custom_vars.remove("PopUpKerf", all=True)
    doc.saveas(target)
    return str(target)


def test_kerf_comes_from_the_header_or_the_caller(written, tmp_path):
    _, _, path = written
    assert read_dxf(path).kerf == 0.15
    assert read_dxf(path, kerf=0.4).kerf == 0.4  # given: it overrides the header
    bare = without_kerf_header(path, tmp_path / "bare.dxf")
    with pytest.raises(DxfReadError, match=r"bare\.dxf: .*PopUpKerf.*--kerf"):
        read_dxf(bare)
    assert read_dxf(bare, kerf=0.1).kerf == 0.1


@pytest.mark.parametrize("value", ["wide", "-0.1", "nan", "inf"])
def test_a_bad_kerf_header_is_named(tmp_path, value):
    doc = drawing_with_square()
    doc.header.custom_vars.replace("PopUpKerf", value)
    path = save(doc, tmp_path)
    with pytest.raises(DxfReadError, match="PopUpKerf") as error:
        read_dxf(path)
    assert str(path) in str(error.value)


@pytest.mark.parametrize("kerf", [-1.0, math.inf, math.nan])
def test_a_bad_kerf_argument_is_named(tmp_path, kerf):
    with pytest.raises(DxfReadError, match="--kerf"):
        read_dxf(save(drawing_with_square(), tmp_path), kerf=kerf)


# --- what a maker's CAD program may write ---------------------------------------------------


def new_drawing(kerf="0.1"):
    doc = ezdxf.new("R2010", units=4)  # ezdxf defaults to metres
    if kerf is not None:
        doc.header.custom_vars.append("PopUpKerf", kerf)
    for name in ("CUT", "MOUNTAIN", "VALLEY", "GLUE", "LABEL"):
        doc.layers.add(name)
    return doc


SQUARE = [(0.0, 0.0), (40.0, 0.0), (40.0, 40.0), (0.0, 40.0)]


def drawing_with_square(kerf="0.1"):
    doc = new_drawing(kerf)
    doc.modelspace().add_lwpolyline(SQUARE, close=True, dxfattribs={"layer": "CUT"})
    return doc


def save(doc, folder, name="edited.dxf"):
    path = os.path.join(str(folder), name)
    doc.saveas(path)
    return path


def test_bulges_are_flattened_within_a_micrometre(tmp_path):
    """A 40 x 20 mm stadium: two straight sides and two half circles of radius 10 (bulge 1)."""
    doc = new_drawing()
    points = [(0, 0, 0), (40, 0, 1), (40, 20, 0), (0, 20, 1)]
    doc.modelspace().add_lwpolyline(points, format="xyb", close=True, dxfattribs={"layer": "CUT"})
    (loop,) = read_dxf(save(doc, tmp_path)).cut
    assert len(loop) > 20
    centres = [(40.0, 10.0), (0.0, 10.0)]

    def on_outline(p):
        if 0 <= p[0] <= 40:
            return min(abs(p[1]), abs(p[1] - 20))
        return min(abs(math.dist(p, c) - 10.0) for c in centres)

    assert max(on_outline(p) for p in loop) <= 1e-9  # every vertex on the stadium
    for a, b in zip(loop, loop[1:] + loop[:1]):  # every chord within the tolerance of the arc
        middle = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
        assert on_outline(middle) <= FLATTEN_TOLERANCE + 1e-12
    assert max(p[0] for p in loop) == pytest.approx(50.0, abs=1e-9)
    assert min(p[0] for p in loop) == pytest.approx(-10.0, abs=1e-9)


def test_circles_arcs_and_loose_lines_close_into_loops(tmp_path):
    doc = new_drawing()
    space = doc.modelspace()
    space.add_circle((100, 100), 5, dxfattribs={"layer": "CUT"})
    # A square from four LINEs, one drawn backwards, in shuffled order.
    for start, end in [((0, 0), (40, 0)), ((40, 40), (0, 40)), ((40, 40), (40, 0))]:
        space.add_line(start, end, dxfattribs={"layer": "CUT"})
    space.add_line((0, 0), (0, 40), dxfattribs={"layer": "CUT"})
    # A D shape: a LINE closed by an ARC.
    space.add_line((200, 0), (200, 20), dxfattribs={"layer": "CUT"})
    space.add_arc((200, 10), 10, -90, 90, dxfattribs={"layer": "CUT"})
    circle, square, d_shape = read_dxf(save(doc, tmp_path)).cut
    assert all(abs(math.dist(p, (100, 100)) - 5) <= 1e-9 for p in circle) and len(circle) > 40
    assert sorted(square) == sorted(SQUARE)
    assert max(p[0] for p in d_shape) == pytest.approx(210.0, abs=1e-9)


def test_a_polyline_returning_to_its_start_is_closed(tmp_path):
    doc = new_drawing()
    doc.modelspace().add_lwpolyline(SQUARE + SQUARE[:1], dxfattribs={"layer": "CUT"})
    assert read_dxf(save(doc, tmp_path)).cut == [SQUARE]


def test_old_style_polylines_are_read(tmp_path):
    doc = new_drawing()
    space = doc.modelspace()
    space.add_polyline2d(SQUARE, close=True, dxfattribs={"layer": "CUT"})
    space.add_polyline2d([(0, 20), (40, 20)], dxfattribs={"layer": "VALLEY"})
    drawing = read_dxf(save(doc, tmp_path))
    assert drawing.cut == [SQUARE]
    assert [(f.start, f.end, f.direction) for f in drawing.folds] == [
        ((0.0, 20.0), (40.0, 20.0), "valley")
    ]


def test_a_fold_polyline_gives_one_fold_per_straight_run(tmp_path):
    doc = drawing_with_square()
    doc.modelspace().add_lwpolyline(
        [(0, 10), (20, 10), (40, 10), (40, 30)], dxfattribs={"layer": "MOUNTAIN"}
    )
    folds = read_dxf(save(doc, tmp_path)).folds
    assert [(f.start, f.end, f.direction) for f in folds] == [
        ((0.0, 10.0), (40.0, 10.0), "mountain"),
        ((40.0, 10.0), (40.0, 30.0), "mountain"),
    ]


def test_blocks_are_exploded_with_their_transformation(tmp_path):
    """A block holding a piece (on layer 0, so it takes the INSERT's layer, and on named layers),
    inserted turned by 90 degrees and moved, inside another block."""
    doc = new_drawing()
    piece = doc.blocks.new("PIECE")
    piece.add_lwpolyline(SQUARE, close=True)  # layer 0: the INSERT's layer, CUT
    piece.add_line((0, 20), (40, 20), dxfattribs={"layer": "valley"})
    piece.add_lwpolyline(
        [(0, 0), (10, 0), (8, 2), (2, 2)], close=True, dxfattribs={"layer": "GLUE"}
    )
    text = piece.add_text("P7", height=5, dxfattribs={"layer": "LABEL"})
    text.set_placement((20, 30), align=TextEntityAlignment.MIDDLE_CENTER)
    outer = doc.blocks.new("SHEET")
    outer.add_blockref("PIECE", (100, 0), dxfattribs={"rotation": 90, "layer": "CUT"})
    doc.modelspace().add_blockref("SHEET", (0, 50), dxfattribs={"layer": "CUT"})
    drawing = read_dxf(save(doc, tmp_path))

    def placed(x, y):  # turned 90 degrees about the origin, then moved by (100, 50)
        return (100.0 - y, 50.0 + x)

    assert len(drawing.cut) == 1 and close_points(drawing.cut[0], [placed(*p) for p in SQUARE])
    (fold,) = drawing.folds
    assert fold.direction == "valley"
    assert close_points([fold.start, fold.end], [placed(0, 20), placed(40, 20)])
    assert close_points(drawing.glue[0], [placed(*p) for p in [(0, 0), (10, 0), (8, 2), (2, 2)]])
    (label,) = drawing.labels
    assert label.text == "P7" and math.dist(label.position, placed(20, 30)) <= EXACT


def test_layers_match_whatever_their_case(tmp_path):
    doc = ezdxf.new("R2010", units=4)  # ezdxf defaults to metres
    doc.header.custom_vars.append("PopUpKerf", "0.1")
    doc.modelspace().add_lwpolyline(SQUARE, close=True, dxfattribs={"layer": "cut"})
    doc.modelspace().add_line((0, 20), (40, 20), dxfattribs={"layer": "Mountain"})
    doc.modelspace().add_line((0, 99), (40, 99), dxfattribs={"layer": "Notes"})  # ignored
    drawing = read_dxf(save(doc, tmp_path))
    assert drawing.cut == [SQUARE] and [f.direction for f in drawing.folds] == ["mountain"]


def test_inches_are_converted_to_millimetres(tmp_path):
    doc = drawing_with_square()
    doc.header["$INSUNITS"] = 1
    (loop,) = read_dxf(save(doc, tmp_path)).cut
    assert close_points(loop, [(x * 25.4, y * 25.4) for x, y in SQUARE])


@pytest.mark.parametrize(
    "align",
    [
        TextEntityAlignment.LEFT,
        TextEntityAlignment.BOTTOM_RIGHT,
        TextEntityAlignment.TOP_CENTER,
        TextEntityAlignment.MIDDLE,
    ],
)
def test_a_label_is_read_at_its_centre_whatever_its_alignment(tmp_path, align):
    """The same text placed with another alignment, at the point that alignment puts it when its
    cap height is centred on (50, 60): read back at (50, 60) (to a tenth of a millimetre: the
    text's width is measured with a font)."""
    try:  # ezdxf 1.1 moved the fonts (Debian 13); Debian 12's 0.18 has them in tools
        from ezdxf.fonts import fonts
    except ImportError:
        from ezdxf.tools import fonts

    height, angle = 5.0, 30.0
    font = fonts.make_font("DejaVuSans.ttf", height)
    width = font.text_width("B (back)")
    descender = font.measurements.descender_height
    along, across = {
        TextEntityAlignment.LEFT: (-width / 2, -height / 2),
        TextEntityAlignment.BOTTOM_RIGHT: (width / 2, -height / 2 - descender),
        TextEntityAlignment.TOP_CENTER: (0.0, height / 2),
        TextEntityAlignment.MIDDLE: (0.0, 0.0),
    }[align]
    turn = math.radians(angle)
    point = (
        50 + along * math.cos(turn) - across * math.sin(turn),
        60 + along * math.sin(turn) + across * math.cos(turn),
    )
    doc = drawing_with_square()
    doc.styles.get("Standard").dxf.font = "DejaVuSans.ttf"
    text = doc.modelspace().add_text(
        "B (back)", height=height, rotation=angle, dxfattribs={"layer": "LABEL"}
    )
    text.set_placement(point, align=align)
    (label,) = read_dxf(save(doc, tmp_path)).labels
    assert label.text == "B (back)"
    assert math.dist(label.position, (50, 60)) <= 0.1 * height


def test_mtext_is_read_at_its_centre(tmp_path):
    doc = drawing_with_square()
    space = doc.modelspace()
    mtext = space.add_mtext("A1", dxfattribs={"layer": "LABEL", "char_height": 4})
    mtext.set_location((30, 30), attachment_point=MTextEntityAlignment.MIDDLE_CENTER)
    two_lines = space.add_mtext("A1\\P(back)", dxfattribs={"layer": "LABEL", "char_height": 4})
    two_lines.set_location((70, 30), attachment_point=MTextEntityAlignment.MIDDLE_CENTER)
    first, second = read_dxf(save(doc, tmp_path)).labels
    assert (first.text, first.position) == ("A1", (30.0, 30.0))
    assert (second.text, second.position) == ("A1 (back)", (70.0, 30.0))


def test_texts_outside_label_and_empty_texts_are_not_labels(tmp_path):
    doc = drawing_with_square()
    space = doc.modelspace()
    space.add_text("P9", dxfattribs={"layer": "Notes"})
    space.add_text("   ", dxfattribs={"layer": "LABEL"})
    space.add_text("P1", dxfattribs={"layer": "MOUNTAIN"})
    assert read_dxf(save(doc, tmp_path)).labels == []


def test_a_folder_is_read_through_its_sheets_dxf(written, tmp_path):
    _, _, path = written
    shutil.copy(path, tmp_path / "sheets.dxf")
    assert read_dxf(str(tmp_path)).cut == read_dxf(path).cut
    empty = tmp_path / "empty"
    empty.mkdir()
    with pytest.raises(DxfReadError, match=r"empty: folder without sheets\.dxf"):
        read_dxf(str(empty))


# --- what cannot be read ----------------------------------------------------------------------


def handle_of(entity):
    return "#" + entity.dxf.handle


def assert_named(path, *fragments, kerf=None):
    with pytest.raises(DxfReadError) as error:
        read_dxf(path, kerf=kerf)
    message = str(error.value)
    assert "\n" not in message
    assert message.startswith(str(path)), message
    for fragment in fragments:
        assert fragment in message, (fragment, message)
    return message


def test_an_open_cut_polyline_is_named(tmp_path):
    doc = drawing_with_square()
    line = doc.modelspace().add_lwpolyline(
        [(100, 0), (140, 0), (140, 40)], dxfattribs={"layer": "CUT"}
    )
    assert_named(save(doc, tmp_path), "layer CUT", "LWPOLYLINE " + handle_of(line), "open")


def test_loose_cut_lines_that_do_not_close_are_named(tmp_path):
    doc = drawing_with_square()
    space = doc.modelspace()
    space.add_line((100, 0), (140, 0), dxfattribs={"layer": "CUT"})
    gap = space.add_line((140, 0), (140, 40), dxfattribs={"layer": "CUT"})
    space.add_line((140.01, 40), (100, 0), dxfattribs={"layer": "CUT"})  # 10 um short
    message = assert_named(save(doc, tmp_path), "layer CUT", "open", "(140, 40)")
    assert handle_of(gap) in message or "LINE #" in message


def test_three_cut_lines_meeting_at_one_end_are_named(tmp_path):
    """A square of four LINEs and its diagonal: every end meets another, two meet two."""
    doc = new_drawing()
    space = doc.modelspace()
    for start, end in zip(SQUARE, SQUARE[1:] + SQUARE[:1]):
        space.add_line(start, end, dxfattribs={"layer": "CUT"})
    space.add_line(SQUARE[0], SQUARE[2], dxfattribs={"layer": "CUT"})
    assert_named(save(doc, tmp_path), "layer CUT", "LINE #", "branches")


def test_a_missing_file_is_named(tmp_path):
    assert_named(str(tmp_path / "gone.dxf"), "no such file")


@pytest.mark.parametrize(
    "content", [b"PopUp sheets\n", b"\x00\x01\x02\xff\xfe binary", b"0\nSECTION\n2\nHEADER\n"]
)
def test_a_file_that_is_not_dxf_is_named(tmp_path, content):
    path = tmp_path / "sheets.dxf"
    path.write_bytes(content)
    assert_named(str(path), "not a readable DXF file")


def test_a_dxf_without_cut_lines_is_named(tmp_path):
    doc = new_drawing()
    doc.modelspace().add_line((0, 0), (10, 0), dxfattribs={"layer": "VALLEY"})
    assert_named(save(doc, tmp_path), "layer CUT", "nothing to cut")


@pytest.mark.parametrize("value", ["nan", "inf", "-inf"])
def test_non_finite_coordinates_are_named(tmp_path, value):
    doc = drawing_with_square()
    marker = doc.modelspace().add_line((123.25, 7), (130, 7), dxfattribs={"layer": "VALLEY"})
    path = save(doc, tmp_path)
    with open(path) as f:
        text = f.read()
    assert text.count("123.25") == 1
    with open(path, "w") as f:
        f.write(text.replace("123.25", value))
    assert_named(path, "layer VALLEY", "LINE " + handle_of(marker), "not a finite number")


def test_non_finite_bulges_are_named(tmp_path):
    doc = new_drawing()
    line = doc.modelspace().add_lwpolyline(
        [(0, 0, 0), (40, 0, 0.123456), (40, 40, 0)], format="xyb", close=True
    )
    line.dxf.layer = "CUT"
    path = save(doc, tmp_path)
    with open(path) as f:
        text = f.read()
    with open(path, "w") as f:
        f.write(text.replace("0.123456", "nan"))
    assert_named(path, "layer CUT", handle_of(line), "not a finite number")


@pytest.mark.parametrize(
    "layer, add, fragment",
    [
        ("CUT", lambda s: s.add_text("P1", dxfattribs={"layer": "CUT"}), "not a cut line"),
        (
            "MOUNTAIN",
            lambda s: s.add_arc((0, 0), 5, 0, 90, dxfattribs={"layer": "MOUNTAIN"}),
            "straight",
        ),
        (
            "GLUE",
            lambda s: s.add_lwpolyline([(0, 0), (5, 0), (5, 5)], dxfattribs={"layer": "GLUE"}),
            "open",
        ),
        ("GLUE", lambda s: s.add_line((0, 0), (5, 0), dxfattribs={"layer": "GLUE"}), "polyline"),
        (
            "VALLEY",
            lambda s: s.add_lwpolyline(SQUARE, close=True, dxfattribs={"layer": "VALLEY"}),
            "closed",
        ),
    ],
)
def test_what_a_layer_cannot_hold_is_named(tmp_path, layer, add, fragment):
    doc = drawing_with_square()
    entity = add(doc.modelspace())
    assert_named(save(doc, tmp_path), f"layer {layer}", handle_of(entity), fragment)


def test_an_entity_inside_a_block_is_named_by_its_insert(tmp_path):
    doc = drawing_with_square()
    block = doc.blocks.new("TAB")
    block.add_lwpolyline([(0, 0), (5, 0), (5, 5)], dxfattribs={"layer": "CUT"})
    insert = doc.modelspace().add_blockref("TAB", (100, 100))
    message = assert_named(save(doc, tmp_path), "layer CUT", "open")
    assert re.search(rf"block 'TAB' \(INSERT {handle_of(insert)}\)", message), message


def test_the_sheet_drawing_carries_everything_to_the_core(written):
    _, _, path = written
    plain = read_dxf(path)
    drawing = plain.to_sheet_drawing(popupcore)
    assert (drawing.name, drawing.kerf) == (plain.name, plain.kerf)
    assert all(close_points(a, b) for a, b in zip(drawing.cut, plain.cut))
    assert len(drawing.cut) == len(plain.cut) and len(drawing.glue) == len(plain.glue)
    assert [(f.direction, tuple(f.start), tuple(f.end)) for f in drawing.folds] == [
        (f.direction, tuple(f.start), tuple(f.end)) for f in plain.folds
    ]
    assert [(t.text, tuple(t.position)) for t in drawing.labels] == [
        (t.text, tuple(t.position)) for t in plain.labels
    ]


def test_a_drawing_written_per_sheet_reads_at_the_origin(tmp_path):
    """write_dxf draws every sheet side by side; one sheet alone has the same entities."""
    scaffold = popupcore.load_scaffold(os.path.join(DATA, "mechanisms", "tent.json"))
    sheet_set = layout(scaffold, paper="A3")
    path = write_dxf(sheet_set, str(tmp_path / "one.dxf"))
    cut, *_ = written_entities(json.loads(sheet_set.to_json()))
    assert all(close_points(a, b) for a, b in zip(read_dxf(path).cut, cut))
