"""Cutting sheets of real designs, end to end: the core's layout of every mechanism type and the
demo card written as DXF/SVG/PDF and read back (issue 4, section 4)."""

import glob
import json
import os
import re
import xml.etree.ElementTree as ElementTree

import ezdxf
import pytest

from popupwb.core import popupcore
from popupwb.sheets.dxf_checks import check_dxf, convert_with_librecad
from popupwb.sheets.export import export_sheets, layout

SOURCE_DIR = os.environ["POPUP_SOURCE_DIR"]
DESIGNS = sorted(glob.glob(os.path.join(SOURCE_DIR, "tests", "data", "mechanisms", "*.json")))
LAYERS = {"CUT", "MOUNTAIN", "VALLEY", "GLUE", "LABEL"}
MM = 72.0 / 25.4  # PDF points per millimetre


def name_of(path):
    return os.path.splitext(os.path.basename(path))[0]


@pytest.fixture(scope="module", params=DESIGNS, ids=name_of)
def written(request, tmp_path_factory):
    sheet_set = layout(popupcore.load_scaffold(request.param), paper="A3")
    out = str(tmp_path_factory.mktemp(name_of(request.param)))
    paths = export_sheets(sheet_set, out)
    with open(paths["sheet_set"]) as f:  # the layout as sheets.json spells it, for the checks
        return json.load(f), paths


def test_there_is_a_design_per_mechanism_type():
    assert len(DESIGNS) == 11


def test_layout_is_usable(written):
    sheet_set, _ = written
    assert [d for d in sheet_set["diagnostics"] if d["severity"] == "error"] == []
    trip = sheet_set["round_trip"]
    assert trip["ok"] and trip["max_error"] <= 1e-6 * sheet_set["card_size"]
    assert len(sheet_set["sheets"]) <= sheet_set["shelf_sheet_count"]


def test_dxf_reads_back_exactly(written):
    sheet_set, paths = written
    check = check_dxf(paths["dxf"], expected_cut_length=sheet_set["cut_length"])
    assert check["audit_errors"] == 0
    assert check["insunits"] == 4
    assert set(check["layers_used"]) <= LAYERS and {"CUT", "LABEL"} <= set(check["layers_used"])
    loops = sum(1 + len(r["holes"]) for p in sheet_set["pieces"] for r in p["cut"])
    assert check["cut_loops"] == loops
    assert check["max_closure_gap"] <= 1e-6
    assert check["overlapping_cut_segments"] == 0
    assert check["cut_length_error"] <= 1e-6
    doc = ezdxf.readfile(paths["dxf"])
    assert {layer.dxf.name for layer in doc.layers} - {"0", "Defpoints"} == LAYERS
    folds = [f for p in sheet_set["pieces"] for f in p["folds"]]
    space = doc.modelspace()
    for direction in ("mountain", "valley"):
        wanted = sum(f["direction"] == direction for f in folds)
        assert len(space.query(f"LINE[layer=='{direction.upper()}']")) == wanted


def test_dxf_records_its_kerf_and_paper_thickness(tmp_path):
    design = DESIGNS[0]
    scaffold = popupcore.load_scaffold(design)
    for kerf in (0.0, 0.25):
        paths = export_sheets(layout(scaffold, paper="A3", kerf=kerf), str(tmp_path / str(kerf)))
        header = dict(ezdxf.readfile(paths["dxf"]).header.custom_vars)
        assert float(header["PopUpKerf"]) == kerf
        assert float(header["PopUpPaperThickness"]) == scaffold.paper_thickness


def test_report_json(written):
    sheet_set, paths = written
    with open(paths["report"]) as f:
        report = json.load(f)
    assert report["sheets"] == len(sheet_set["sheets"])
    assert report["round_trip"]["ok"] is True
    assert report["dxf_check"]["audit_errors"] == 0
    assert len(report["pieces"]) == len(sheet_set["pieces"])
    assert report["tabs"] == sum(len(p["tabs"]) for p in sheet_set["pieces"])


def test_svg_is_millimetres(written):
    sheet_set, paths = written
    assert len(paths["svg"]) == len(sheet_set["sheets"])
    root = ElementTree.parse(paths["svg"][0]).getroot()
    width, height = sheet_set["paper"]["width"], sheet_set["paper"]["height"]
    assert root.get("width") == f"{width:g}mm" and root.get("height") == f"{height:g}mm"
    assert [float(v) for v in root.get("viewBox").split()] == [0, 0, width, height]


def test_pdf_page_is_the_paper(written):
    sheet_set, paths = written
    with open(paths["pdf"], "rb") as f:
        boxes = re.findall(rb"/MediaBox\s*\[\s*([-0-9.\s]+?)\s*\]", f.read())
    assert len(boxes) == len(sheet_set["sheets"])
    for box in boxes:
        x0, y0, x1, y1 = (float(v) for v in box.split())
        assert abs(x1 - x0 - sheet_set["paper"]["width"] * MM) < 1e-3
        assert abs(y1 - y0 - sheet_set["paper"]["height"] * MM) < 1e-3


def test_librecad_converts_the_demo_sheets(tmp_path):
    demo = os.path.join(SOURCE_DIR, "tests", "data", "mechanisms", "demo_card.json")
    paths = export_sheets(layout(popupcore.load_scaffold(demo), paper="A3"), str(tmp_path))
    pdf = convert_with_librecad(paths["dxf"], str(tmp_path / "librecad"))
    with open(pdf, "rb") as f:
        assert f.read(5) == b"%PDF-"


def test_bad_options_are_named():
    demo = popupcore.load_scaffold(DESIGNS[0])
    with pytest.raises(ValueError, match="tab_angle = 95, must be more than 0, at most 90"):
        layout(demo, paper="A3", tab_angle=95)
    with pytest.raises(ValueError, match="A9"):
        layout(demo, paper="A9")
    with pytest.raises(ValueError, match="unknown sheet option"):
        layout(demo, colour="red")


def test_an_export_leaves_no_sheet_of_an_earlier_one(tmp_path):
    """Sheets of a two-sheet layout, then a one-sheet layout into the same folder: only the new
    files remain (a stale sheets-2.svg would be cut as part of the new design)."""
    import glob

    scaffold = popupcore.load_scaffold(DESIGNS[0])
    two = export_sheets(layout(scaffold, paper="230x310"), str(tmp_path))
    assert len(two["svg"]) >= 2
    (tmp_path / "notes.txt").write_text("mine")  # not ours: stays
    one = export_sheets(layout(scaffold, paper="A3"), str(tmp_path))
    assert one["svg"] == [str(tmp_path / "sheets.svg")]
    assert sorted(glob.glob(str(tmp_path / "sheets*.svg"))) == [str(tmp_path / "sheets.svg")]
    assert (tmp_path / "notes.txt").read_text() == "mine"
