"""`popup sheet` on a card designed from a model prints its artwork as the GUI export does: the
print layer of the SVG and PDF carries the model's images and the three registration marks,
unless every CuttingSheet of the card has PrintArtwork off. Checked by re-reading the files."""

import os
import re
import shutil
from xml.etree import ElementTree

import pytest
from pypdf import PdfReader

from cli_runner import load_tool, popup
from test_cli_fit import UPRIGHT

SVG = "{http://www.w3.org/2000/svg}"
MARK = rb"([-0-9.]+) ([-0-9.]+) 5 5 re f"  # a 5 mm filled square (registration_marks.py)


@pytest.fixture(scope="module")
def fitted(tmp_path_factory):
    """design.FCStd of a cuboid fitted by `popup fit` (a card with a SourceModel)."""
    folder = tmp_path_factory.mktemp("fitted")
    model = load_tool("make_models").write_model("cuboid", str(folder / "cuboid.stl"))
    proc = popup("fit", model, "--out", str(folder / "fit"), *UPRIGHT)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return str(folder / "fit" / "design.FCStd")


def print_layer(svg_path):
    """(images, registration mark squares) of an SVG's PRINT layer; ([], []) without one."""
    root = ElementTree.parse(svg_path).getroot()
    layers = [g for g in root.iter(SVG + "g") if g.get("id") == "PRINT"]
    if not layers:
        return [], []
    (layer,) = layers
    return list(layer.iter(SVG + "image")), layer.findall(SVG + "rect")


def pdf_images_and_marks(pdf_path):
    reader = PdfReader(pdf_path)
    images = marks = 0
    for page in reader.pages:
        xobjects = page["/Resources"].get("/XObject", {})
        images += sum(x.get_object()["/Subtype"] == "/Image" for x in xobjects.values())
        marks += len(re.findall(MARK, page.get_contents().get_data()))
    return images, marks, len(reader.pages)


def test_popup_sheet_prints_the_source_model_with_registration_marks(fitted, tmp_path):
    out = tmp_path / "sheets"
    proc = popup("sheet", fitted, "--out", str(out))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    svgs = sorted(f for f in os.listdir(out) if f.endswith(".svg"))
    patches = 0
    for name in svgs:
        images, marks = print_layer(out / name)
        assert len(marks) == 3, name  # three corners of every sheet
        assert all(
            i.get("href", i.get("{http://www.w3.org/1999/xlink}href")).startswith(
                "data:image/png;base64,"
            )
            for i in images
        )
        patches += len(images)
    # A box fold's parts and the card's two pages are printed (its end panels too).
    assert patches >= 6
    images, marks, pages = pdf_images_and_marks(out / "sheets.pdf")
    assert images == patches
    assert marks == 3 * pages


def test_print_artwork_off_on_the_cards_cutting_sheet_prints_nothing(fitted, tmp_path, freecad):
    from popupwb.make.make_cutting_sheet import make_cutting_sheet

    path = str(tmp_path / "no_artwork.FCStd")
    shutil.copy(fitted, path)
    doc = freecad.openDocument(path)
    try:
        sheet = make_cutting_sheet(doc.getObject("Card"), paper="A4", make_pages=False)
        sheet.PrintArtwork = False
        doc.recompute()
        doc.save()
    finally:
        freecad.closeDocument(doc.Name)
    out = tmp_path / "sheets"
    proc = popup("sheet", path, "--out", str(out))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    for name in (f for f in os.listdir(out) if f.endswith(".svg")):
        assert print_layer(out / name) == ([], [])
    images, marks, _ = pdf_images_and_marks(out / "sheets.pdf")
    assert (images, marks) == (0, 0)
