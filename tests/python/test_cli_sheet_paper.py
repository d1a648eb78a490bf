"""`popup sheet` without --paper: the smallest paper preset holding every piece within the margins,
said on stdout and in the JSON report, and written into sheets.json, the DXF and the SVG.

Expected papers by hand, with 10 mm margins (printable = paper - 20 mm each way):
  A4 190 x 277, Letter 195.9 x 259.4, A3 277 x 400, Tabloid 259.4 x 411.8 mm.
  The demo's A4 card opens to 210 x 297 mm (+ 0.1 mm kerf): too large for A4 and Letter either
  way round, inside A3 and Tabloid. An A5 card opens to 148 x 210 mm: inside A4 and Letter.
  By area Letter (60322 mm^2) < A4 (62370) and Tabloid (120645) < A3 (124740); ISO sizes come
  first unless the system paper (PAPERSIZE) is a US one.
"""

import json
import xml.etree.ElementTree as ET

import ezdxf
import pytest

from cli_documents import build_cards, build_demo_card
from cli_runner import assert_clean_error, popup

MARGIN = 10.0
SHEET_GAP = 20.0  # mm between sheets in sheets.dxf
PAPERS = {"A4": (210.0, 297.0), "A3": (297.0, 420.0), "Letter": (215.9, 279.4)}
PAPERS["Tabloid"] = (279.4, 431.8)


@pytest.fixture(scope="module")
def documents(tmp_path_factory, user_home):
    folder = tmp_path_factory.mktemp("paper")
    build_cards(folder, user_home)
    build_demo_card(folder, user_home)
    return folder


def cut_boxes(dxf_path, paper_width):
    """(sheet index, x0, y0, x1, y1) of every CUT polyline, re-read with ezdxf, in sheet
    coordinates."""
    pitch = paper_width + SHEET_GAP
    boxes = []
    for polyline in ezdxf.readfile(dxf_path).modelspace().query("LWPOLYLINE[layer=='CUT']"):
        xs, ys = zip(*polyline.get_points("xy"))
        sheet = int(min(xs) // pitch)
        boxes.append((sheet, min(xs) - sheet * pitch, min(ys), max(xs) - sheet * pitch, max(ys)))
    return boxes


def fits(size, paper):
    room = (paper[0] - 2 * MARGIN, paper[1] - 2 * MARGIN)
    w, h = size
    return (w <= room[0] and h <= room[1]) or (h <= room[0] and w <= room[1])


def assert_sheets_on(out, name):
    """The written files say `name` and every cut lies inside its margins."""
    width, height = PAPERS[name]
    with open(out / "sheets.json") as f:
        sheet_set = json.load(f)
    assert sheet_set["paper"] == {"name": name, "width": width, "height": height}
    boxes = cut_boxes(str(out / "sheets.dxf"), width)
    assert boxes
    for _, x0, y0, x1, y1 in boxes:
        assert MARGIN - 1e-6 <= x0 and x1 <= width - MARGIN + 1e-6
        assert MARGIN - 1e-6 <= y0 and y1 <= height - MARGIN + 1e-6
    svg = ET.parse(out / "sheets.svg").getroot()
    assert (svg.get("width"), svg.get("height")) == (f"{width:g}mm", f"{height:g}mm")
    return max(((x1 - x0, y1 - y0) for _, x0, y0, x1, y1 in boxes), key=lambda s: s[0] * s[1])


def test_the_demo_card_lands_on_a3(documents, user_home, tmp_path):
    out = tmp_path / "sheets"
    card = str(documents / "card.FCStd")
    proc = popup("sheet", card, "--out", str(out), home=user_home, env_vars={"PAPERSIZE": "a4"})
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.startswith("paper A3 (297 x 420 mm) chosen automatically")
    assert "largest: piece P1 (210.1 x 297.1 mm)" in proc.stdout.splitlines()[0]
    largest = assert_sheets_on(out, "A3")
    assert not fits(largest, PAPERS["A4"]) and not fits(largest, PAPERS["Letter"])

    proc = popup(
        "sheet", card, "--out", str(out), "--json", home=user_home, env_vars={"PAPERSIZE": "a4"}
    )
    assert proc.returncode == 0, proc.stderr
    report = json.loads(proc.stdout)
    assert report["paper"] == {"name": "A3", "width": 297.0, "height": 420.0}
    assert report["paper_chosen_automatically"] is True


def test_a_small_card_lands_on_a4(documents, user_home, tmp_path):
    proc = popup(
        "sheet",
        str(documents / "two_cards.FCStd"),
        "--card",
        "Good",
        "--out",
        str(tmp_path),
        home=user_home,
        env_vars={"PAPERSIZE": "a4"},
    )
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.startswith("paper A4 (210 x 297 mm) chosen automatically")
    largest = assert_sheets_on(tmp_path, "A4")
    assert largest == pytest.approx((148.1, 210.1), abs=1e-6) or largest == pytest.approx(
        (210.1, 148.1), abs=1e-6
    )


def test_the_demo_card_on_a_us_system_lands_on_tabloid(documents, user_home, tmp_path):
    card = str(documents / "card.FCStd")
    proc = popup(
        "sheet", card, "--out", str(tmp_path), home=user_home, env_vars={"PAPERSIZE": "letter"}
    )
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.startswith("paper Tabloid (279.4 x 431.8 mm) chosen automatically")
    largest = assert_sheets_on(tmp_path, "Tabloid")
    assert not fits(largest, PAPERS["Letter"])


def test_a_small_card_on_a_us_system_lands_on_letter(documents, user_home, tmp_path):
    proc = popup(
        "sheet",
        str(documents / "two_cards.FCStd"),
        "--card",
        "Good",
        "--out",
        str(tmp_path),
        "--json",
        home=user_home,
        env_vars={"PAPERSIZE": "letter"},
    )
    assert proc.returncode == 0, proc.stderr
    assert json.loads(proc.stdout)["paper"]["name"] == "Letter"
    assert_sheets_on(tmp_path, "Letter")


def test_an_explicit_paper_is_kept(documents, user_home, tmp_path):
    card = str(documents / "card.FCStd")
    proc = popup(
        "sheet", card, "--out", str(tmp_path), "--paper", "Tabloid", "--json", home=user_home
    )
    assert proc.returncode == 0, proc.stderr
    report = json.loads(proc.stdout)
    assert report["paper"]["name"] == "Tabloid" and report["paper_chosen_automatically"] is False
    assert_sheets_on(tmp_path, "Tabloid")
    proc = popup("sheet", card, "--out", str(tmp_path), "--paper", "A4", home=user_home)
    assert_clean_error(proc, card, "piece P1 (210.1 x 297.1 mm) does not fit", "of A4")


def test_a_card_larger_than_every_preset_is_named(documents, user_home, tmp_path):
    path = str(documents / "huge.FCStd")
    proc = popup("sheet", path, "--out", str(tmp_path / "sheets"), home=user_home)
    # 300 x 300 mm pages open to 300 x 600 mm (+ 0.1 mm kerf), turned on the measuring sheet.
    assert_clean_error(
        proc, path, "piece P1 (600.1 x 300.1 mm)", "no paper preset", "A3, 297 x 420 mm"
    )
    assert not (tmp_path / "sheets").exists()
