"""Structured diagnostics across the boundary: the same fields in C++, Python and --json output."""

import json
import os
import subprocess

import pytest

from conftest import SOURCE_DIR, BUILD_DIR

popupcore = pytest.importorskip("popupcore")

FIELDS = {"code", "severity", "message", "patches", "parameter", "angle_deg"}
POPUP = os.path.join(BUILD_DIR, "bin", "popup")


def documented_codes():
    with open(os.path.join(SOURCE_DIR, "docs", "DIAGNOSTICS.md")) as f:
        return [line.split("`")[1] for line in f if line.startswith("| `")]


def test_every_code_is_documented_once_and_nothing_else():
    documented = documented_codes()
    assert len(documented) == len(set(documented))
    assert sorted(documented) == sorted(popupcore.diagnostic_codes())


def test_design_error_carries_its_diagnostics():
    with pytest.raises(popupcore.DesignError) as caught:
        params = popupcore.CardParams()
        params.width = -5.0
        popupcore.make_card(params)
    diagnostics = caught.value.diagnostics
    assert len(diagnostics) == 1
    d = diagnostics[0]
    assert set(d) == FIELDS
    assert (d["code"], d["severity"], d["parameter"]) == ("bad_parameter", "error", "Width")
    assert d["patches"] == [] and d["angle_deg"] is None
    assert d["message"] in str(caught.value)


def test_a_broken_design_file_names_the_field():
    with pytest.raises(popupcore.DesignError) as caught:
        popupcore.scaffold_from_json('{"format": "popup-design", "version": 7}')
    (d,) = caught.value.diagnostics
    assert d["code"] == "bad_field" and d["parameter"] == "version"


def read_design(name):
    with open(os.path.join(SOURCE_DIR, "tests", "data", name)) as f:
        return json.load(f)


@pytest.mark.parametrize(
    "name, code, angle",
    [
        ("colliding_walls.json", "intersection", True),
        ("unstable_five_bar.json", "unstable", True),
        ("sticking_out_tent.json", "not_enclosed", True),
    ],
)
def test_check_json_names_the_patches_of_the_design(name, code, angle):
    out = subprocess.run(
        [POPUP, "check", os.path.join(SOURCE_DIR, "tests", "data", name), "--json"],
        capture_output=True,
        text=True,
    )
    assert out.returncode == 1, out.stderr
    report = json.loads(out.stdout)
    ids = {p["id"] for p in read_design(name)["patches"]}
    found = [d for d in report["diagnostics"] if d["code"] == code]
    assert found, report["diagnostics"]
    for d in report["diagnostics"]:
        assert set(d) == FIELDS
        assert set(d["patches"]) <= ids
    assert all(d["patches"] for d in found)
    if angle:
        assert all(0.0 <= d["angle_deg"] <= 180.0 for d in found)
    # The message names each patch it is about, as a person reads it.
    for d in found:
        for i in d["patches"]:
            assert f"patch {i}" in d["message"]


def test_the_layout_crosses_the_binding_as_bound_types():
    import math

    scaffold = popupcore.load_scaffold(
        os.path.join(SOURCE_DIR, "tests", "data", "mechanisms", "box.json")
    )
    options = popupcore.SheetOptions()
    options.paper = "A3"
    options.kerf = 0.2
    sheets = popupcore.layout_sheets(scaffold, options)
    assert isinstance(sheets, popupcore.SheetSet)
    assert sheets.options.paper == "A3" and sheets.options.kerf == 0.2
    data = json.loads(sheets.to_json())  # the file format, written from the same layout
    assert [p.id for p in sheets.pieces] == [p["id"] for p in data["pieces"]]
    assert sheets.pieces[0].id == "P1" and sheets.sheet_count == len(data["sheets"])
    assert math.isclose(sheets.cut_length, data["cut_length"], rel_tol=1e-12)
    assert sheets.round_trip.ok and sheets.round_trip.max_error <= sheets.round_trip.tolerance
    for piece, written in zip(sheets.pieces, data["pieces"]):
        assert piece.printed_side == "front"
        assert [f.direction for f in piece.folds] == [f["direction"] for f in written["folds"]]
        assert [t.code for t in piece.tabs] == [t["code"] for t in written["tabs"]]
        for patch in piece.patches:
            assert patch.outer.shape[1] == 2 and patch.outer.shape[0] >= 3
        # Kerf moves every cut line out by half of it: the compensated outline is larger.
        for cut, nominal in zip(piece.cut, piece.cut_nominal):
            assert abs(shoelace(cut.outer)) > abs(shoelace(nominal.outer))
    for d in sheets.diagnostics:
        assert d.to_dict() in data["diagnostics"]


def test_a_sheet_set_reads_back_from_its_json():
    """What a CuttingSheet stores (SheetSet.to_json()) comes back as the same bound SheetSet;
    a damaged text is a DesignError naming the key path."""
    scaffold = popupcore.load_scaffold(
        os.path.join(SOURCE_DIR, "tests", "data", "mechanisms", "box.json")
    )
    options = popupcore.SheetOptions()
    options.paper = "A3"
    sheets = popupcore.layout_sheets(scaffold, options)
    text = sheets.to_json()
    again = popupcore.sheet_set_from_json(text)
    assert again.to_json() == text
    assert [p.id for p in again.pieces] == [p.id for p in sheets.pieces]
    assert (again.cut_length, again.sheet_count) == (sheets.cut_length, sheets.sheet_count)
    ids = [p.id for p in again.pieces]
    data = json.loads(text)
    for step, written in zip(again.assembly, data["assembly"]):  # pieces by index, not id
        assert ids[step.piece] == written["piece"] and step.text == written["text"]
        assert [(j.code, ids[j.tab_piece], ids[j.target_piece]) for j in step.joins] == [
            (j["code"], j["tab_piece"], j["target_piece"]) for j in written["glue"]
        ]
    # A layout stored before flat patches had frames reads with none.
    for piece in data["pieces"]:
        for patch in piece["patches"]:
            del patch["to_sheet"]
    older = popupcore.sheet_set_from_json(json.dumps(data))
    assert all(p.to_sheet is None for piece in older.pieces for p in piece.patches)
    del data["pieces"][1]["labels"][0]["position"]
    with pytest.raises(
        popupcore.DesignError, match=r"^sheet set: pieces\[1\]\.labels\[0\]\.position missing$"
    ) as error:
        popupcore.sheet_set_from_json(json.dumps(data))
    assert error.value.diagnostics[0]["code"] == "bad_field"
    assert error.value.diagnostics[0]["parameter"] == "pieces[1].labels[0].position"
    with pytest.raises(popupcore.DesignError, match="sheet set: not valid JSON"):
        popupcore.sheet_set_from_json("{")


def shoelace(loop):
    return 0.5 * sum(
        loop[i][0] * loop[(i + 1) % len(loop)][1] - loop[(i + 1) % len(loop)][0] * loop[i][1]
        for i in range(len(loop))
    )
