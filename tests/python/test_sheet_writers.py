"""Cutting-sheet writers (popupwb.sheets) on the hand-made sheet set tests/data/sheet_set_sample.json,
read through popupcore.sheet_set_from_json: numbers read back from the DXF, SVG, PDF and PNG files,
and the DXF through LibreCAD. No FreeCAD."""

import copy
import json
import math
import os
import re
import struct
import time
import xml.etree.ElementTree as ElementTree
import zlib

import ezdxf
import pytest

from conftest import TIME_SCALE
from popupwb.core import popupcore
from popupwb.sheets.dxf_checks import check_dxf, convert_with_librecad, librecad_available
from popupwb.sheets.dxf_writer import SHEET_GAP, write_dxf, write_dxf_per_sheet
from popupwb.sheets.instructions_pdf import write_instructions
from popupwb.sheets.layer_style import SheetStyle
from popupwb.sheets.pdf_writer import write_pdf
from popupwb.sheets.sheet_options import core_options
from popupwb.sheets.sheet_png import png_size, render_sheet_png
from popupwb.sheets.svg_writer import write_svg

LAYERS = {"CUT", "MOUNTAIN", "VALLEY", "GLUE", "LABEL"}
PT_PER_MM = 72.0 / 25.4
SVG = "{http://www.w3.org/2000/svg}"
INKSCAPE = "{http://www.inkscape.org/namespaces/inkscape}"


@pytest.fixture(scope="module")
def sheet_set(data_dir):
    """The fixture as its JSON spells it, for the expected numbers (bound() reads it into the
    writers' input)."""
    with open(os.path.join(data_dir, "sheet_set_sample.json")) as file:
        return json.load(file)


def bound(sheet_set):
    """The sheet set the writers take, read from the JSON object `sheet_set`."""
    return popupcore.sheet_set_from_json(json.dumps(sheet_set))


@pytest.fixture(scope="module")
def out_dir(tmp_path_factory):
    return tmp_path_factory.mktemp("sheets")


@pytest.fixture(scope="module")
def dxf_path(sheet_set, out_dir):
    return write_dxf(bound(sheet_set), str(out_dir / "sheets.dxf"))


def signed_area(loop):
    return 0.5 * sum(
        x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(loop, list(loop[1:]) + [loop[0]])
    )


def loops_of(pieces):
    return [
        loop
        for piece in pieces
        for region in piece["cut"]
        for loop in (region["outer"], *region["holes"])
    ]


def pieces_on(sheet_set, index):
    return [piece for piece in sheet_set["pieces"] if piece["sheet"] == index]


def folds_by_direction(pieces):
    folds = [fold for piece in pieces for fold in piece["folds"]]
    return {d: sum(1 for fold in folds if fold["direction"] == d) for d in ("mountain", "valley")}


# The fixture itself obeys docs/SHEET_FORMAT.md: the writers are tested on a valid sheet set.


def test_fixture_follows_the_sheet_format(sheet_set):
    width, height = sheet_set["paper"]["width"], sheet_set["paper"]["height"]
    margin = sheet_set["options"]["margin"]
    perimeter = 0.0
    for piece in sheet_set["pieces"]:
        for region in piece["cut"]:
            assert signed_area(region["outer"]) > 0, f"{piece['id']}: outer loop not CCW"
            assert all(signed_area(hole) < 0 for hole in region["holes"]), piece["id"]
            for x, y in region["outer"]:
                assert margin - 0.05 <= x <= width - margin + 0.05
                assert margin - 0.05 <= y <= height - margin + 0.05
        for loop in loops_of([piece]):
            perimeter += sum(math.dist(a, b) for a, b in zip(loop, loop[1:] + loop[:1]))
    assert perimeter == pytest.approx(sheet_set["cut_length"], rel=1e-12)
    pieces = {piece["id"]: piece for piece in sheet_set["pieces"]}
    for piece in sheet_set["pieces"]:
        for tab in piece["tabs"]:
            glue = [g for g in pieces[tab["target_piece"]]["glue"] if g["code"] == tab["code"]]
            assert len(glue) == 1 and glue[0]["tab_piece"] == piece["id"], tab["code"]
            assert glue[0]["hinge"] == tab["hinge"]
            assert any(f["hinge"] == tab["hinge"] and f["kind"] == "tab" for f in piece["folds"])
    glued = {"P1"}
    for step in sheet_set["assembly"]:
        assert all(join["target_piece"] in glued for join in step["glue"]), step["step"]
        glued.add(step["piece"])
    assert glued == set(pieces)


def test_reader_names_the_missing_key(sheet_set):
    broken = copy.deepcopy(sheet_set)
    del broken["pieces"][2]["cut"]
    with pytest.raises(ValueError, match=r"^sheet set: pieces\[2\]\.cut missing$"):
        bound(broken)
    broken = copy.deepcopy(sheet_set)
    broken["pieces"][0]["folds"][0]["direction"] = "up"
    with pytest.raises(ValueError, match=r"pieces\[0\]\.folds\[0\]\.direction is 'up'"):
        write_dxf(bound(broken), os.devnull)
    broken = copy.deepcopy(sheet_set)
    broken["sheets"][1]["pieces"].append("P9")
    with pytest.raises(ValueError, match=r"sheets\[1\]\.pieces\[2\] names unknown piece 'P9'"):
        bound(broken)


# DXF


def test_dxf_numbers(sheet_set, dxf_path):
    report = check_dxf(dxf_path, expected_cut_length=sheet_set["cut_length"])
    assert report["audit_errors"] == 0
    assert report["insunits"] == 4
    assert set(report["layers_used"]) == LAYERS
    assert report["cut_loops"] == len(loops_of(sheet_set["pieces"])) == 5
    assert report["max_closure_gap"] == 0.0
    assert report["overlapping_cut_segments"] == 0
    assert report["cut_length_error"] < 1e-6
    counts = report["entity_counts"]
    assert counts["CUT"] == {"LWPOLYLINE": 5}
    folds = folds_by_direction(sheet_set["pieces"])
    assert counts["MOUNTAIN"] == {"LINE": folds["mountain"]}
    assert counts["VALLEY"] == {"LINE": folds["valley"]}
    assert counts["LABEL"] == {"TEXT": sum(len(piece["labels"]) for piece in sheet_set["pieces"])}
    assert counts["GLUE"] == {
        "LWPOLYLINE": sum(len(piece["glue"]) for piece in sheet_set["pieces"])
    }


def test_dxf_layers_header_and_sheet_placement(sheet_set, dxf_path):
    doc = ezdxf.readfile(dxf_path)
    assert doc.header["$MEASUREMENT"] == 1
    style = SheetStyle()
    layers = {layer.dxf.name: layer for layer in doc.layers}
    assert set(layers) - {"0", "Defpoints"} == LAYERS
    for expected in style.layers():
        assert layers[expected.name].dxf.color == expected.aci
        assert layers[expected.name].dxf.linetype.upper() == expected.linetype
    assert doc.linetypes.get("DASHED").simplified_line_pattern() == (3.0, 1.5)
    # Sheet 1 starts one paper width plus the gap to the right of sheet 0.
    offset = sheet_set["paper"]["width"] + SHEET_GAP
    first_cut = sheet_set["pieces"][1]["cut"][0]["outer"][0]  # P2, on sheet 1
    polylines = [
        tuple(p.get_points("xy")) for p in doc.modelspace().query("LWPOLYLINE[layer=='CUT']")
    ]
    assert any(
        math.dist(points[0], (first_cut[0] + offset, first_cut[1])) < 1e-9 for points in polylines
    )
    texts = doc.modelspace().query("TEXT")
    label = sheet_set["pieces"][0]["labels"][0]
    (text,) = [t for t in texts if t.dxf.text == label["text"]]
    assert (text.dxf.align_point.x, text.dxf.align_point.y) == pytest.approx(label["position"])
    assert text.dxf.height == label["height"]


def test_dxf_per_sheet(sheet_set, out_dir):
    paths = write_dxf_per_sheet(bound(sheet_set), str(out_dir / "per_sheet.dxf"))
    assert [os.path.basename(p) for p in paths] == ["per_sheet.dxf", "per_sheet-2.dxf"]
    for index, path in enumerate(paths):
        expected = loops_of(pieces_on(sheet_set, index))
        report = check_dxf(path)
        assert report["audit_errors"] == 0 and report["overlapping_cut_segments"] == 0
        assert report["cut_loops"] == len(expected)
        length = sum(
            math.dist(a, b) for loop in expected for a, b in zip(loop, loop[1:] + loop[:1])
        )
        assert report["cut_length"] == pytest.approx(length, rel=1e-9)


def test_dxf_checks_find_doubled_and_open_cuts(tmp_path):
    doc = ezdxf.new("R2010", units=4)
    doc.layers.add("CUT")
    modelspace = doc.modelspace()
    # Two squares sharing the edge x = 10 (a cutter would cut it twice), the shared stretch run
    # in opposite directions.
    modelspace.add_lwpolyline(
        [(0, 0), (10, 0), (10, 10), (0, 10)], close=True, dxfattribs={"layer": "CUT"}
    )
    modelspace.add_lwpolyline(
        [(10, 2), (20, 2), (20, 8), (10, 8)], close=True, dxfattribs={"layer": "CUT"}
    )
    # A triangle of lines whose last corner misses by 0.5 mm, and an open polyline that returns.
    modelspace.add_line((30, 0), (40, 0), dxfattribs={"layer": "CUT"})
    modelspace.add_line((40, 0), (35, 8), dxfattribs={"layer": "CUT"})
    modelspace.add_line((35, 8), (30.5, 0), dxfattribs={"layer": "CUT"})
    modelspace.add_lwpolyline([(50, 0), (60, 0), (55, 5), (50, 0)], dxfattribs={"layer": "CUT"})
    path = str(tmp_path / "faulty.dxf")
    doc.saveas(path)
    report = check_dxf(path)
    assert report["overlapping_cut_segments"] == 1
    assert report["cut_loops"] == 2
    assert report["max_closure_gap"] == pytest.approx(0.5)
    triangle = 10 + math.hypot(5, 8) + math.hypot(4.5, 8)
    assert report["cut_length"] == pytest.approx(40 + 32 + triangle + 10 + 2 * math.hypot(5, 5))


# LibreCAD reads the DXF: an independent client, not ezdxf reading its own output.


@pytest.mark.skipif(not librecad_available(), reason="librecad binary not installed")
def test_librecad_converts_the_dxf(dxf_path, tmp_path):
    started = time.monotonic()
    pdf_path = convert_with_librecad(dxf_path, str(tmp_path))
    assert time.monotonic() - started < 20 * TIME_SCALE
    assert pdf_path == str(tmp_path / "sheets.pdf")
    with open(pdf_path, "rb") as file:
        data = file.read()
    assert data.startswith(b"%PDF")
    strokes = b"".join(_pdf_streams(data))
    assert b"1 0 0 SCN" in strokes  # LibreCAD drew the red CUT layer


def _pdf_streams(data):
    for match in re.finditer(rb"stream\r?\n(.*?)endstream", data, re.S):
        try:
            yield zlib.decompress(match.group(1))
        except zlib.error:
            yield match.group(1)


# SVG


def test_svg_files(sheet_set, out_dir):
    paths = write_svg(bound(sheet_set), str(out_dir / "sheets.svg"))
    assert [os.path.basename(p) for p in paths] == ["sheets.svg", "sheets-2.svg"]
    width, height = sheet_set["paper"]["width"], sheet_set["paper"]["height"]
    for index, path in enumerate(paths):
        root = ElementTree.parse(path).getroot()
        assert root.get("width") == f"{width:g}mm" and root.get("height") == f"{height:g}mm"
        assert root.get("viewBox") == f"0 0 {width:g} {height:g}"
        layers = {
            group.get(f"{INKSCAPE}label"): group
            for group in root.iter(f"{SVG}g")
            if group.get(f"{INKSCAPE}groupmode") == "layer"
        }
        assert set(layers) == LAYERS
        pieces = pieces_on(sheet_set, index)
        cut_paths = layers["CUT"].findall(f"{SVG}path")
        assert len(cut_paths) == len(loops_of(pieces))
        assert all(path.get("d").endswith("Z") for path in cut_paths)
        folds = folds_by_direction(pieces)
        assert len(layers["MOUNTAIN"].findall(f"{SVG}line")) == folds["mountain"]
        assert len(layers["VALLEY"].findall(f"{SVG}line")) == folds["valley"]
        assert len(layers["LABEL"].findall(f"{SVG}text")) == sum(len(p["labels"]) for p in pieces)
        # y flipped: the first cut point of the first piece, in SVG coordinates.
        x, y = pieces[0]["cut"][0]["outer"][0]
        first = re.match(r"M ([-0-9.]+),([-0-9.]+)", cut_paths[0].get("d"))
        assert (float(first[1]), float(first[2])) == pytest.approx((x, height - y), abs=1e-6)


def test_svg_single_sheet_keeps_the_path(data_dir, tmp_path):
    # The fixture's first sheet alone would leave tabs glued onto pieces it no longer has: a
    # real one-sheet layout instead.
    scaffold = popupcore.load_scaffold(os.path.join(data_dir, "mechanisms", "tent.json"))
    one_sheet = popupcore.layout_sheets(scaffold, core_options(paper="A3"))
    assert one_sheet.sheet_count == 1
    assert write_svg(one_sheet, str(tmp_path / "card.svg")) == [str(tmp_path / "card.svg")]
    assert os.listdir(tmp_path) == ["card.svg"]


# PDF


def _media_boxes(data):
    return [
        tuple(float(v) for v in box.split())
        for box in re.findall(rb"/MediaBox\s*\[\s*([-0-9.\s]+?)\s*\]", data)
    ]


def test_pdf_pages_are_the_paper(sheet_set, out_dir):
    path = write_pdf(bound(sheet_set), str(out_dir / "sheets.pdf"))
    with open(path, "rb") as file:
        data = file.read()
    width, height = sheet_set["paper"]["width"], sheet_set["paper"]["height"]
    boxes = _media_boxes(data)
    assert len(boxes) == len(re.findall(rb"/Type\s*/Page\b(?!s)", data)) == 2
    for box in boxes:
        assert box == pytest.approx((0, 0, width * PT_PER_MM, height * PT_PER_MM), abs=1e-3)


def test_pdf_registration_marks(sheet_set, tmp_path):
    path = write_pdf(
        bound(sheet_set), str(tmp_path / "marks.pdf"), registration_marks=True, compress=False
    )
    with open(path, "rb") as file:
        data = file.read()
    # Three filled 5 mm squares a page, centred in the 10 mm margin band.
    marks = re.findall(rb"([-0-9.]+) ([-0-9.]+) 5 5 re f", data)
    assert len(marks) == 3 * 2
    assert {(float(x), float(y)) for x, y in marks} == {(2.5, 289.5), (202.5, 289.5), (2.5, 2.5)}
    narrow = copy.deepcopy(sheet_set)
    narrow["options"]["margin"] = 4.0
    with pytest.raises(ValueError, match="margin of at least 6 mm"):
        write_pdf(bound(narrow), str(tmp_path / "narrow.pdf"), registration_marks=True)


def _pdf_text(data):
    """The strings shown by Tj in an uncompressed PDF, joined with single spaces."""
    strings = re.findall(rb"\(((?:\\.|[^\\)])*)\) Tj", data)
    text = " ".join(re.sub(rb"\\(.)", rb"\1", s).decode("latin-1") for s in strings)
    return " ".join(text.split())


def test_instructions(sheet_set, out_dir):
    path = write_instructions(bound(sheet_set), str(out_dir / "instructions.pdf"), compress=False)
    with open(path, "rb") as file:
        data = file.read()
    assert len(re.findall(rb"/Type\s*/Page\b(?!s)", data)) >= 1
    text = _pdf_text(data)
    for step in sheet_set["assembly"]:
        assert " ".join(step["text"].split()) in text
    for piece in sheet_set["pieces"]:
        assert piece["id"] in text
    assert sheet_set["diagnostics"][0]["message"] in text
    assert "Mountain fold" in text and "Valley fold" in text
    assert "0.2 mm" in text and "1.20 mm" in text


# PNG


def test_png_size_and_content(sheet_set, out_dir):
    import matplotlib.image

    path = render_sheet_png(bound(sheet_set), 1, str(out_dir / "sheet-2.png"), dpi=100)
    with open(path, "rb") as file:
        header = file.read(24)
    assert header[:8] == b"\x89PNG\r\n\x1a\n"
    size = struct.unpack(">II", header[16:24])
    assert size == png_size(210.0, 297.0, 100) == (827, 1169)
    pixels = matplotlib.image.imread(path)
    red = (pixels[..., 0] > 0.8) & (pixels[..., 1] < 0.3) & (pixels[..., 2] < 0.3)
    assert red.sum() > 1000  # the cut lines are drawn
    with pytest.raises(ValueError, match="sheet index 2 outside 0..1"):
        render_sheet_png(bound(sheet_set), 2, str(out_dir / "none.png"))
