"""`popup verify DESIGN SHEETS`, run as a user would: exit 0 when the cutting file makes the
design, 1 when it does not (each finding printed), 2 for input it cannot use; the JSON report; a
folder or a file; the kerf header; printed sides from the flag or the card's CuttingSheet."""

import json
import os
import textwrap

import ezdxf
import pytest

import sheet_mutations
from cli_documents import build_cards
from cli_runner import assert_clean_error, data, popup, run_freecad_script
from test_cli import documented_codes

BOX = data("mechanisms/box.json")
TENT = data("mechanisms/tent.json")
REPORT_KEYS = {"design", "sheets", "ok", "max_error", "tolerance", "angles", "diagnostics"}
DIAGNOSTIC_KEYS = {"code", "severity", "message", "patches", "parameter", "angle_deg"}


def sheet(design, out, *extra, home=None):
    proc = popup("sheet", design, "--out", str(out), *extra, home=home)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return out


def verify(*args, home=None):
    proc = popup("verify", *map(str, args), home=home)
    assert "Traceback" not in proc.stdout + proc.stderr, proc.stderr
    return proc


@pytest.fixture(scope="module")
def box_sheets(tmp_path_factory):
    return sheet(BOX, tmp_path_factory.mktemp("box") / "sheets")


@pytest.fixture(scope="module")
def scaled_box(box_sheets, tmp_path_factory):
    """The box's sheets.dxf with its piece P2 scaled by 1.01: a file that does not match."""
    with open(box_sheets / "sheets.json") as f:
        sheet_set = json.load(f)
    path = tmp_path_factory.mktemp("scaled") / "scaled.dxf"
    sheet_mutations.mutated_copy(box_sheets / "sheets.dxf", path, sheet_set, "scale_piece")
    return path


def test_a_folder_and_its_sheets_dxf_verify(box_sheets):
    for sheets in (box_sheets, box_sheets / "sheets.dxf"):
        proc = verify(BOX, sheets)
        assert proc.returncode == 0, proc.stdout + proc.stderr
        (line,) = proc.stdout.strip().splitlines()
        assert line.startswith("sheets match the design: every patch within ")
        assert line.endswith(" over 13 fold angles") and "(tolerance " in line


def test_json_report(box_sheets):
    proc = verify(BOX, box_sheets, "--json", "--angles", "5")
    assert proc.returncode == 0, proc.stderr
    report = json.loads(proc.stdout)
    assert REPORT_KEYS <= set(report)
    assert report["design"] == os.path.abspath(BOX)
    assert report["sheets"] == os.path.abspath(box_sheets / "sheets.dxf")
    assert report["ok"] is True and report["angles"] == 5
    assert 0 <= report["max_error"] <= report["tolerance"]
    assert report["kerf"] == 0.1 and report["printed_sides"] == {}
    assert all(d["severity"] != "error" for d in report["diagnostics"])


def test_a_file_that_does_not_match_exits_1_naming_each_finding(scaled_box):
    proc = verify(BOX, scaled_box, "--json")
    assert proc.returncode == 1, proc.stderr
    report = json.loads(proc.stdout)
    assert report["ok"] is False and report["sheets"] == os.path.abspath(scaled_box)
    errors = [d for d in report["diagnostics"] if d["severity"] == "error"]
    assert errors
    # The same fields as popup check's and popup sheet's diagnostics, with documented codes.
    check = json.loads(popup("check", data("broken_tent.json"), "--json").stdout)
    assert {frozenset(d) for d in check["diagnostics"]} == {frozenset(DIAGNOSTIC_KEYS)}
    assert all(set(d) == DIAGNOSTIC_KEYS for d in report["diagnostics"])
    assert {d["code"] for d in report["diagnostics"]} <= documented_codes()

    text = verify(BOX, scaled_box)
    assert text.returncode == 1
    lines = text.stdout.strip().splitlines()
    assert lines[: len(errors)] == [f"error: {d['code']}: {d['message']}" for d in errors]
    assert lines[-1].startswith(f"sheets do NOT match the design: {len(errors)} error(s); ")


def test_the_sheets_of_another_design_do_not_verify(box_sheets):
    proc = verify(TENT, box_sheets, "--json")
    assert proc.returncode == 1, proc.stderr
    report = json.loads(proc.stdout)
    assert report["ok"] is False
    assert [d for d in report["diagnostics"] if d["severity"] == "error"]


def without_kerf_header(source, target):
    doc = ezdxf.readfile(str(source))
    doc.header.custom_vars.remove("PopUpKerf", all=True)
    doc.saveas(str(target))
    return target


def test_the_kerf_comes_from_the_header_or_kerf(box_sheets, tmp_path):
    bare = without_kerf_header(box_sheets / "sheets.dxf", tmp_path / "bare.dxf")
    assert_clean_error(verify(BOX, bare), str(bare), "PopUpKerf", "--kerf")
    proc = verify(BOX, bare, "--kerf", "0.1")
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_kerf_overrides_the_header(tmp_path):
    wide = sheet(BOX, tmp_path / "wide", "--kerf", "0.3")
    proc = verify(BOX, wide, "--json")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert json.loads(proc.stdout)["kerf"] == 0.3
    # Read with the wrong kerf the outlines are 0.1 mm too large all round.
    proc = verify(BOX, wide, "--kerf", "0.1", "--json")
    assert proc.returncode == 1, proc.stdout + proc.stderr
    assert json.loads(proc.stdout)["kerf"] == 0.1


def test_the_printed_side_must_be_the_one_the_sheets_were_written_with(tmp_path):
    turned = sheet(BOX, tmp_path / "turned", "--printed-side", "P1=back")
    assert verify(BOX, turned).returncode == 1
    proc = verify(BOX, turned, "--printed-side", "P1=back", "--json")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert json.loads(proc.stdout)["printed_sides"] == {"P1": "back"}


@pytest.mark.parametrize(
    "args, fragments",
    [
        ([BOX, "missing_folder"], ["missing_folder: no such file"]),
        ([BOX, data("tent_fold.json")], ["tent_fold.json", "not a readable DXF file"]),
        (["missing.json", "SHEETS"], ["missing.json: no such file"]),
        ([data("broken_tent.json"), "SHEETS"], ["broken_tent.json"]),
        ([BOX, "SHEETS", "--kerf", "-1"], ["--kerf -1", ">= 0"]),
        ([BOX, "SHEETS", "--kerf", "nan"], ["--kerf nan"]),
        ([BOX, "SHEETS", "--angles", "1"], ["--angles 1", "2 to"]),
        ([BOX, "SHEETS", "--printed-side", "P1=up"], ["--printed-side P1=up", "front or back"]),
        ([BOX, "SHEETS", "--printed-side", "P1"], ["--printed-side", "PIECE=SIDE"]),
        ([BOX, "SHEETS", "--card", "Card"], ["--card Card", "only for FreeCAD documents"]),
        ([BOX], ["the following arguments are required: sheets"]),
    ],
)
def test_unusable_input_exits_2_with_one_line(box_sheets, args, fragments):
    args = [str(box_sheets) if a == "SHEETS" else a for a in args]
    assert_clean_error(verify(*args), *fragments)


def test_a_folder_without_sheets_dxf_is_named(tmp_path):
    assert_clean_error(verify(BOX, tmp_path), str(tmp_path), "sheets.dxf")


def test_an_open_cut_line_is_named(box_sheets, tmp_path):
    doc = ezdxf.readfile(str(box_sheets / "sheets.dxf"))
    line = doc.modelspace().query("LWPOLYLINE[layer=='CUT']")[0]
    line.closed = False
    doc.saveas(str(tmp_path / "open.dxf"))
    proc = verify(BOX, tmp_path / "open.dxf")
    assert_clean_error(proc, "open.dxf", "layer CUT", f"#{line.dxf.handle}", "open")


# --- FreeCAD documents: the card to verify against, and the printed sides of its CuttingSheet ---

PRINTED = textwrap.dedent(
    """
    import sys
    import FreeCAD
    from popupwb import make

    folder = sys.argv[1]
    doc = FreeCAD.newDocument("printed")
    card = make.make_card(doc, preset="A5", name="Card")
    make.make_tent_fold(card, name="Tent", offset=40.0, width=60.0, foot=20.0,
                        foot_backdrop=20.0, slope=30.0)
    make.make_cutting_sheet(card, paper="A4", printed_sides={"P1": "back"}, make_pages=False)
    doc.recompute()
    doc.saveAs(folder + "/printed.FCStd")
    make.make_cutting_sheet(card, paper="A4", make_pages=False, name="Plain")
    doc.recompute()
    doc.saveAs(folder + "/two_sheets.FCStd")
    """
)


@pytest.fixture(scope="module")
def documents(tmp_path_factory, user_home):
    """printed.FCStd: an A5 card with a tent, its CuttingSheet printing P1 on the back;
    two_sheets.FCStd: the same with a second CuttingSheet printing everything on the front;
    two_cards.FCStd (cli_documents.py); the card's sheets written both ways."""
    folder = tmp_path_factory.mktemp("documents")
    run_freecad_script(PRINTED, folder, home=user_home)
    build_cards(str(folder), user_home)
    printed = str(folder / "printed.FCStd")
    sheet(printed, folder / "back", "--printed-side", "P1=back", home=user_home)
    sheet(printed, folder / "front", "--printed-side", "P1=front", home=user_home)
    sheet(printed, folder / "from_card", home=user_home)  # the CuttingSheet's P1=back
    sheet(str(folder / "two_cards.FCStd"), folder / "good", "--card", "Good", home=user_home)
    return folder


def test_a_card_is_verified_with_its_cutting_sheets_printed_sides(documents, user_home):
    printed = documents / "printed.FCStd"
    proc = verify(printed, documents / "back", "--json", home=user_home)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    report = json.loads(proc.stdout)
    assert report["printed_sides"] == {"P1": "back"} and report["object"] == "Card"
    assert verify(printed, documents / "front", home=user_home).returncode == 1
    # --printed-side overrides the CuttingSheet's, piece by piece.
    proc = verify(printed, documents / "front", "--printed-side", "P1=front", home=user_home)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    # `popup sheet` of the card without the flag prints the sides its CuttingSheet says, as the
    # feature does: the same sheets as with --printed-side P1=back.
    layout = json.loads((documents / "from_card" / "sheets.json").read_text())
    sides = {piece["id"]: piece["printed_side"] for piece in layout["pieces"]}
    assert sides["P1"] == "back" and set(sides.values()) <= {"front", "back"}
    assert verify(printed, documents / "from_card", home=user_home).returncode == 0


def test_cutting_sheets_that_disagree_need_printed_side(documents, user_home):
    two = documents / "two_sheets.FCStd"
    assert_clean_error(
        verify(two, documents / "back", home=user_home), "two_sheets.FCStd", "--printed-side"
    )
    proc = verify(two, documents / "back", "--printed-side", "P1=back", home=user_home)
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_a_document_with_several_cards_needs_card(documents, user_home):
    cards = documents / "two_cards.FCStd"
    assert_clean_error(verify(cards, documents / "good", home=user_home), "--card")
    proc = verify(cards, documents / "good", "--card", "Good", home=user_home)
    assert proc.returncode == 0, proc.stdout + proc.stderr


# --- edits that change the file but not what is cut, creased and glued -------------------------


def explode_cut_lines(doc):
    """LibreCAD's Explode: each CUT polyline becomes its LINEs (written in reverse order)."""
    space = doc.modelspace()
    for line in list(space.query("LWPOLYLINE[layer=='CUT']")):
        points = [tuple(p) for p in line.get_points("xy")]
        for start, end in reversed(list(zip(points, points[1:] + points[:1]))):
            space.add_line(start, end, dxfattribs={"layer": "CUT"})
        space.delete_entity(line)


def into_a_turned_block(doc):
    """Everything grouped into a block, inserted turned a quarter and moved: a rigid motion."""
    block = doc.blocks.new("SHEETS")
    space = doc.modelspace()
    for entity in list(space):
        space.unlink_entity(entity)
        block.add_entity(entity)
    space.add_blockref("SHEETS", (1000.0, -50.0), dxfattribs={"rotation": 90.0})


def lower_case_layers(doc):
    for entity in doc.modelspace():
        entity.dxf.layer = entity.dxf.layer.lower()


def labels_as_mtext(doc):
    from ezdxf.enums import MTextEntityAlignment

    space = doc.modelspace()
    for text in list(space.query("TEXT")):
        mtext = space.add_mtext(
            text.dxf.text, dxfattribs={"layer": text.dxf.layer, "char_height": text.dxf.height}
        )
        mtext.set_location(
            text.dxf.align_point, attachment_point=MTextEntityAlignment.MIDDLE_CENTER
        )
        space.delete_entity(text)


@pytest.mark.parametrize(
    "edit", [explode_cut_lines, into_a_turned_block, lower_case_layers, labels_as_mtext]
)
def test_edits_that_keep_the_geometry_still_verify(box_sheets, tmp_path, edit):
    doc = ezdxf.readfile(str(box_sheets / "sheets.dxf"))
    edit(doc)
    doc.saveas(str(tmp_path / "edited.dxf"))
    from popupwb.sheets.dxf_reader import read_dxf

    def counts(drawing):
        return [len(drawing.cut), len(drawing.folds), len(drawing.glue), len(drawing.labels)]

    assert counts(read_dxf(str(tmp_path / "edited.dxf"))) == counts(read_dxf(str(box_sheets)))
    proc = verify(BOX, tmp_path / "edited.dxf", "--json")
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_a_piece_moved_and_turned_elsewhere_still_verifies(box_sheets, tmp_path):
    """A maker re-nesting: the box's strip P3 turned 37 degrees and moved 600 mm to the right,
    clear of the other pieces (a rigid motion on the sheet, not a turn-over)."""
    import math

    with open(box_sheets / "sheets.json") as f:
        sheet_set = json.load(f)
    doc = ezdxf.readfile(str(box_sheets / "sheets.dxf"))
    (piece,) = [p for p in sheet_set["pieces"] if p["id"] == "P3"]
    cx, cy = sheet_mutations.centroid(piece["cut"][0]["outer"])
    turn = math.radians(37.0)

    def moved(p):
        x, y = p[0] - cx, p[1] - cy
        return (
            cx + 600 + x * math.cos(turn) - y * math.sin(turn),
            cy + x * math.sin(turn) + y * math.cos(turn),
        )

    for entity in sheet_mutations.piece_entities(doc, sheet_set, piece):
        if entity.dxftype() == "LWPOLYLINE":
            entity.set_points([moved(p) for p in entity.get_points("xy")], format="xy")
        elif entity.dxftype() == "LINE":
            entity.dxf.start, entity.dxf.end = moved(entity.dxf.start), moved(entity.dxf.end)
        else:
            entity.dxf.align_point = moved(entity.dxf.align_point)
            entity.dxf.insert = moved(entity.dxf.insert)
            entity.dxf.rotation += 37.0
    doc.saveas(str(tmp_path / "renested.dxf"))
    proc = verify(BOX, tmp_path / "renested.dxf")
    assert proc.returncode == 0, proc.stdout + proc.stderr
