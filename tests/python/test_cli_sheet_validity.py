"""`popup sheet` and the validity check: a rejected design gets no sheets (exit 1, the findings on
stdout); --force writes them with "NOT VALID: <reason>" on every sheet of the DXF (LABEL layer),
the SVGs and the PDF, and on every page of the instructions. The files are read back with ezdxf,
ElementTree and pypdf; the reason is the hand-derived one: the tall tent's slope ends 5 mm beyond
the page when closed (not enclosed), nothing else fails."""

import json
import os
import xml.etree.ElementTree as ET

import ezdxf
import pypdf
import pytest

from cli_documents import BAD_OVERHANG, build_cards
from cli_runner import assert_clean_error, popup

STAMP = "NOT VALID: not enclosed"
SHEET_GAP = 20.0  # mm between sheets in sheets.dxf
SVG = "{http://www.w3.org/2000/svg}"


@pytest.fixture(scope="module")
def cards(tmp_path_factory, user_home):
    return build_cards(tmp_path_factory.mktemp("validity"), user_home)


def sheet(cards, home, out, *options, card="Bad", paper="A4"):
    return popup(
        "sheet",
        str(cards / "two_cards.FCStd"),
        "--card",
        card,
        "--out",
        str(out),
        "--paper",
        paper,
        *options,
        home=home,
    )


def test_an_invalid_design_gets_no_sheets(cards, user_home, tmp_path):
    out = tmp_path / "sheets"
    proc = sheet(cards, user_home, out)
    assert proc.returncode == 1, proc.stderr
    assert not out.exists()
    assert proc.stdout.startswith("INVALID: foldable, stable, intersection-free, NOT enclosed")
    assert f"sticks out of the closed card by {BAD_OVERHANG:g} mm" in proc.stdout
    (line,) = proc.stderr.strip().splitlines()
    assert STAMP in line and "no sheets written" in line and "--force" in line

    proc = sheet(cards, user_home, out, "--json")
    assert proc.returncode == 1
    result = json.loads(proc.stdout)
    assert result["written"] is False and result["valid"] is False
    assert result["object"] == "Bad" and result["validity"]["enclosed"] is False
    assert not out.exists()


def dxf_texts(path):
    """(text, x, y) of every TEXT and MTEXT entity on LABEL, re-read with ezdxf."""
    modelspace = ezdxf.readfile(path).modelspace()
    texts = []
    for entity in modelspace.query("TEXT MTEXT[layer=='LABEL']"):
        content = entity.dxf.text if entity.dxftype() == "TEXT" else entity.text
        point = entity.dxf.align_point if entity.dxftype() == "TEXT" else entity.dxf.insert
        texts.append((content, point.x, point.y))
    return texts


def pdf_pages_text(path):
    return [page.extract_text() for page in pypdf.PdfReader(str(path)).pages]


def test_force_writes_stamped_sheets(cards, user_home, tmp_path):
    # Printable 150 x 212 mm: the card's 148.1 x 210.1 mm pages fill one sheet, the tent needs a
    # second, so the stamp must be on both.
    proc = sheet(cards, user_home, tmp_path, "--force", "--json", paper="170x232")
    assert proc.returncode == 1, proc.stderr  # written, but the design is still not valid
    result = json.loads(proc.stdout)
    assert result["written"] is True and result["valid"] is False
    with open(tmp_path / "sheets.json") as f:
        sheet_set = json.load(f)
    with open(tmp_path / "report.json") as f:
        assert json.load(f)["not_valid"] == STAMP
    width, height = sheet_set["paper"]["width"], sheet_set["paper"]["height"]
    margin = sheet_set["options"]["margin"]
    count = len(sheet_set["sheets"])
    assert count == 2

    stamps = [(x, y) for text, x, y in dxf_texts(str(tmp_path / "sheets.dxf")) if text == STAMP]
    assert len(stamps) == count
    for index, (x, y) in enumerate(sorted(stamps)):
        # Centred across sheet `index` (sheets lie side by side), in its top margin band.
        assert x == pytest.approx(index * (width + SHEET_GAP) + width / 2.0)
        assert height - margin < y < height

    svgs = [tmp_path / "sheets.svg"] + [tmp_path / f"sheets-{n}.svg" for n in range(2, count + 1)]
    for svg in svgs:
        label_layer = next(
            g for g in ET.parse(svg).getroot().iter(f"{SVG}g") if g.get("id") == "LABEL"
        )
        assert STAMP in [t.text for t in label_layer.iter(f"{SVG}text")]

    pages = pdf_pages_text(tmp_path / "sheets.pdf")
    assert len(pages) == count and all(STAMP in page for page in pages)
    instructions = pdf_pages_text(tmp_path / "instructions.pdf")
    assert all(STAMP in page for page in instructions)
    # The findings name patches as a maker does (longer): a line may wrap inside the sentence.
    text = " ".join("".join(instructions).split())
    assert "Tent fold 'TallTent': slope, ground side [#" in text
    assert f"sticks out of the closed card by {BAD_OVERHANG:g} mm" in text


def test_a_valid_design_carries_no_stamp(cards, user_home, tmp_path):
    proc = sheet(cards, user_home, tmp_path, "--json", card="Good")
    assert proc.returncode == 0, proc.stderr
    result = json.loads(proc.stdout)
    assert result["written"] is True and result["valid"] is True
    texts = [text for text, _, _ in dxf_texts(str(tmp_path / "sheets.dxf"))]
    assert "P1" in texts and not any("NOT VALID" in text for text in texts)
    pdfs = pdf_pages_text(tmp_path / "sheets.pdf") + pdf_pages_text(tmp_path / "instructions.pdf")
    assert pdfs and not any("NOT VALID" in page for page in pdfs)
    with open(tmp_path / "report.json") as f:
        assert json.load(f)["not_valid"] is None


def test_several_cards_need_a_card_option(cards, user_home, tmp_path):
    path = str(cards / "two_cards.FCStd")
    proc = popup("sheet", path, "--out", str(tmp_path / "sheets"), home=user_home)
    assert_clean_error(proc, path, "2 cards (Good, Bad ('Tall tent card'))", "--card")
    assert not os.path.exists(tmp_path / "sheets")
