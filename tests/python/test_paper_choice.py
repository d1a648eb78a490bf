"""The automatic paper choice (popupwb.sheets.paper_choice) on hand-made piece sizes.

With 10 mm margins the printable areas are A4 190 x 277, Letter 195.9 x 259.4, A3 277 x 400 and
Tabloid 259.4 x 411.8 mm; by area Letter < A4 < Tabloid < A3. Every expected paper below follows
from those numbers.
"""

from types import SimpleNamespace

import pytest

from popupwb.sheets.paper_choice import (
    NoPaperFits,
    Paper,
    PieceSize,
    choose_paper,
    piece_sizes,
    presets,
    system_paper_family,
)


def pieces(*sizes):
    return [PieceSize(f"P{n}", w, h) for n, (w, h) in enumerate(sizes, start=1)]


def test_presets_come_from_the_core_family_first_smallest_first():
    assert [(p.name, p.width, p.height) for p in presets("iso")] == [
        ("A4", 210.0, 297.0),
        ("A3", 297.0, 420.0),
        ("Letter", 215.9, 279.4),
        ("Tabloid", 279.4, 431.8),
    ]
    assert [p.name for p in presets("us")] == ["Letter", "Tabloid", "A4", "A3"]


@pytest.mark.parametrize(
    "sizes, family, paper",
    [
        ([(190.0, 277.0)], "iso", "A4"),  # exactly the printable area
        ([(277.0, 190.0)], "iso", "A4"),  # the same, turned
        ([(190.1, 277.0)], "iso", "A3"),
        ([(100.0, 100.0), (210.1, 297.1)], "iso", "A3"),  # the largest piece decides
        ([(195.9, 259.4)], "us", "Letter"),
        ([(195.9, 259.5)], "us", "Tabloid"),
        ([(195.9, 259.4)], "iso", "A3"),  # too wide for A4 (190): ISO before Letter
        ([(250.0, 405.0)], "iso", "Tabloid"),  # A3 is 400 long: only Tabloid (411.8) holds it
    ],
)
def test_the_smallest_preset_holding_every_piece(sizes, family, paper):
    assert choose_paper(pieces(*sizes), 10.0, family).paper.name == paper


def test_the_margin_counts_on_every_side():
    assert choose_paper(pieces((200.0, 280.0)), 5.0, "iso").paper.name == "A4"  # 200 x 287
    assert choose_paper(pieces((200.0, 280.0)), 10.0, "iso").paper.name == "A3"


def test_no_preset_names_the_piece_its_size_and_the_largest_preset():
    with pytest.raises(NoPaperFits) as error:
        choose_paper(pieces((100.0, 100.0), (300.0, 500.0)), 10.0, "iso")
    message = str(error.value)
    assert "piece P2 (300.0 x 500.0 mm)" in message
    assert "largest preset: A3, 297 x 420 mm" in message


def test_pieces_no_single_preset_holds_together():
    # 10 x 405 fits only Tabloid (A3 is 400 long); 276 x 395 only A3 (Tabloid is 259.4 wide, and
    # both sides exceed that).
    with pytest.raises(NoPaperFits, match="no paper preset holds every piece"):
        choose_paper(pieces((10.0, 405.0), (276.0, 395.0)), 10.0, "iso")


def test_piece_sizes_are_the_bounding_boxes_of_the_largest_cut_region():
    square = [[10.0, 20.0], [40.0, 20.0], [40.0, 70.0], [10.0, 70.0]]
    speck = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]
    # The attributes piece_sizes reads of a popupcore.SheetSet, its pieces and their regions.
    cut = [SimpleNamespace(outer=speck), SimpleNamespace(outer=square)]
    sheet_set = SimpleNamespace(pieces=[SimpleNamespace(id="P1", cut=cut)])
    assert piece_sizes(sheet_set) == [PieceSize("P1", 30.0, 50.0)]


@pytest.mark.parametrize(
    "papersize, file_text, family",
    [
        ("letter", None, "us"),
        ("Tabloid", None, "us"),
        ("a4", "letter\n", "iso"),  # the variable wins over the file
        ("", "# comment\nletter\n", "us"),
        ("", "a3\n", "iso"),
        ("", None, "iso"),  # neither: ISO
    ],
)
def test_system_paper_family_follows_libpaper(tmp_path, papersize, file_text, family):
    path = tmp_path / "papersize"
    if file_text is not None:
        path.write_text(file_text)
    environ = {"PAPERSIZE": papersize} if papersize else {}
    assert system_paper_family(environ, str(path)) == family


def test_paper_holds_upright_or_turned():
    a4 = Paper("A4", 210.0, 297.0)
    assert a4.holds((190.0, 277.0), 10.0) and a4.holds((277.0, 190.0), 10.0)
    assert not a4.holds((190.0, 277.1), 10.0) and not a4.holds((191.0, 191.0), 10.0)
