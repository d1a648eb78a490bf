"""The `popup` command line (build/bin/popup, written by `make build`), run as a user would."""

import json
import math
import os
import shutil
import textwrap

import pytest

from cli_runner import (
    SOURCE_DIR,
    assert_clean_error,
    data,
    popup,
    read_report,
    run_freecad_script,
)

VERDICTS = ("foldable", "stable", "intersection_free", "enclosed")

# Invalid test designs and the property each one fails.
INVALID = {
    "broken_tent.json": "foldable",
    "unstable_five_bar.json": "stable",
    "colliding_walls.json": "intersection_free",
    "sticking_out_tent.json": "enclosed",
}


def documented_codes():
    """The diagnostic codes docs/DIAGNOSTICS.md lists (first column of its tables)."""
    with open(os.path.join(SOURCE_DIR, "docs", "DIAGNOSTICS.md")) as f:
        return {line.split("`")[1] for line in f if line.startswith("| `")}


def words(text):
    return text.lower().replace("-", " ").replace("_", " ")


def test_version():
    proc = popup("--version")
    assert proc.returncode == 0
    assert proc.stdout.strip() == "popup 0.1.0"


def test_valid_design():
    proc = popup("check", data("tent_fold.json"))
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.startswith("VALID")
    assert "Traceback" not in proc.stderr


def test_json_report():
    proc = popup("check", data("tent_fold.json"), "--json", "--samples", "37")
    assert proc.returncode == 0, proc.stderr
    report = json.loads(proc.stdout)  # exactly one JSON document on stdout
    assert isinstance(report, dict)
    for key in ("valid", *VERDICTS):
        assert report[key] is True, key
    for key in ("max_hinge_residual", "max_edge_strain", "flatness_at_zero", "model_size"):
        assert isinstance(report[key], float), key
    assert report["max_hinge_residual"] <= 1e-9 * report["model_size"]
    assert report["samples"] == 37
    assert report["file"] == data("tent_fold.json")
    assert isinstance(report["diagnostics"], list)
    for d in report["diagnostics"]:
        assert set(d) == {"code", "severity", "message", "patches", "parameter", "angle_deg"}
        assert d["code"] in documented_codes()


@pytest.mark.parametrize("name", sorted(INVALID))
def test_invalid_design_names_the_failing_property(name):
    failing = INVALID[name]
    proc = popup("check", data(name))
    assert proc.returncode == 1, (proc.stdout, proc.stderr)
    assert proc.stdout.startswith("INVALID")
    assert f"not {words(failing)}" in words(proc.stdout)
    assert "Traceback" not in proc.stderr

    proc = popup("check", data(name), "--json")
    assert proc.returncode == 1
    report = json.loads(proc.stdout)
    assert report["valid"] is False and report[failing] is False
    assert report["diagnostics"], "an invalid design comes with findings"


def test_missing_file(tmp_path):
    path = str(tmp_path / "no_such_design.json")
    assert_clean_error(popup("check", path), path, "no such file")


def test_garbage_json(tmp_path):
    path = tmp_path / "garbage.json"
    path.write_text("{ this is not JSON ]")
    assert_clean_error(popup("check", str(path)), str(path), "JSON")


def test_inconsistent_design(tmp_path):
    with open(data("tent_fold.json"), encoding="utf-8") as f:
        design = json.load(f)
    del design["patches"][0]["outline"]
    path = tmp_path / "no_outline.json"
    path.write_text(json.dumps(design))
    assert_clean_error(popup("check", str(path), "--json"), str(path), "patches[0].outline")


@pytest.mark.parametrize(
    "options, fragment",
    [
        (["--samples", "1"], "--samples 1: must be 2 to 100000"),
        (["--samples", "99999999999999999999"], "--samples 99999999999999999999: must be 2 to"),
        (["--clearance", "inf"], "--clearance inf"),
        (["--samples", "many"], "--samples"),
        (["--clearance", "-1"], "--clearance"),
        (["--colour", "red"], "--colour"),
    ],
)
def test_bad_option(options, fragment):
    assert_clean_error(popup("check", data("tent_fold.json"), *options), fragment)


def test_no_command():
    proc = popup()
    assert proc.returncode == 2
    assert "Traceback" not in proc.stderr


# --- FreeCAD documents ------------------------------------------------------------------------


MAKE_DOCUMENTS = textwrap.dedent(
    """
    import sys
    import FreeCAD
    from popupwb.make import make_scaffold

    valid, invalid, out = sys.argv[1:4]
    for name, design in (("valid", valid), ("invalid", invalid)):
        doc = FreeCAD.newDocument(name)
        doc.addObject("Part::Box", "Table")  # not a scaffold: the CLI must skip it
        make_scaffold(doc, design, fold_angle=90.0, name="Card")
        doc.recompute()
        doc.saveAs(f"{out}/{name}.FCStd")
        FreeCAD.closeDocument(doc.Name)
    doc = FreeCAD.newDocument("plain")
    doc.addObject("Part::Box", "Box")
    doc.recompute()
    doc.saveAs(f"{out}/plain.FCStd")
    """
)


@pytest.fixture(scope="module")
def documents(tmp_path_factory, user_home):
    """valid.FCStd, invalid.FCStd (one Scaffold each) and plain.FCStd (no Scaffold)."""
    out = tmp_path_factory.mktemp("fcstd")
    designs = []
    for name in ("tent_fold.json", "broken_tent.json"):
        shutil.copy(data(name), out / name)
        designs.append(str(out / name))
    run_freecad_script(MAKE_DOCUMENTS, *designs, out, home=user_home)
    return out


def test_check_fcstd(documents, user_home):
    proc = popup("check", str(documents / "valid.FCStd"), home=user_home)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.startswith("VALID")

    proc = popup("check", str(documents / "valid.FCStd"), "--json", home=user_home)
    assert proc.returncode == 0, proc.stderr
    report = json.loads(proc.stdout)
    assert report["valid"] is True
    assert report["object"] == "Card"


def test_check_fcstd_with_invalid_design(documents, user_home):
    proc = popup("check", str(documents / "invalid.FCStd"), "--json", home=user_home)
    assert proc.returncode == 1, proc.stderr
    report = json.loads(proc.stdout)
    assert report["valid"] is False and report["foldable"] is False


CARD_DOCUMENT = textwrap.dedent(
    """
    import sys
    import FreeCAD
    from popupwb import make

    doc = FreeCAD.newDocument("card")
    card = make.make_card(doc, preset="A5", fold_angle=70.0)
    box = make.make_box_fold(card, offset=40.0, width=60.0, name="Box")
    tent = make.make_tent_fold(box, name="Tent")
    doc.recompute()
    doc.saveAs(sys.argv[1] + "/card.FCStd")
    tent.Foot = -3.0
    doc.recompute()
    doc.saveAs(sys.argv[1] + "/bad_card.FCStd")
    """
)


@pytest.fixture(scope="module")
def card_documents(tmp_path_factory, user_home):
    """card.FCStd (an A5 card with a box carrying a tent) and bad_card.FCStd (its tent broken)."""
    folder = tmp_path_factory.mktemp("cards")
    run_freecad_script(CARD_DOCUMENT, folder, home=user_home)
    return folder


def test_check_fcstd_with_a_card_checks_its_whole_assembly(card_documents, user_home):
    tmp_path = card_documents
    proc = popup("check", str(tmp_path / "card.FCStd"), "--json", home=user_home)
    assert proc.returncode == 0, proc.stderr
    report = json.loads(proc.stdout)
    assert report["valid"] is True and report["object"] == "Card"
    path = str(tmp_path / "bad_card.FCStd")
    assert_clean_error(popup("check", path, home=user_home), path, "Tent: Foot = -3 mm")


def test_check_fcstd_without_scaffold(documents, user_home):
    path = str(documents / "plain.FCStd")
    assert_clean_error(popup("check", path, home=user_home), path, "no PopUp Scaffold")


def test_check_broken_fcstd(tmp_path, user_home):
    path = tmp_path / "broken.FCStd"
    path.write_bytes(b"this is not a zip archive")
    assert_clean_error(popup("check", str(path), home=user_home), str(path))


def test_sheet_writes_every_file(card_documents, user_home, tmp_path):
    out = tmp_path / "sheets"
    proc = popup(
        "sheet", str(card_documents / "card.FCStd"), "--out", str(out), "--json", home=user_home
    )
    assert proc.returncode == 0, proc.stderr
    report = json.loads(proc.stdout)
    # The card, the box's strip, backbone and two end-panel pieces, and the tent.
    assert len(report["pieces"]) == 6
    assert 1 <= report["sheets"] <= report["shelf_packer_sheets"]
    assert report["round_trip"]["ok"] and report["errors"] == []
    assert report["dxf_check"]["audit_errors"] == 0 and report["object"] == "Card"
    for name in ("sheets.dxf", "sheets.svg", "sheets.pdf", "instructions.pdf", "report.json"):
        assert (out / name).stat().st_size > 0, name
    text = popup("sheet", str(card_documents / "card.FCStd"), "--out", str(out), home=user_home)
    assert text.returncode == 0 and "round trip:" in text.stdout and "ok" in text.stdout


def test_sheet_of_a_card_with_a_broken_mechanism_names_it(card_documents, user_home, tmp_path):
    path = str(card_documents / "bad_card.FCStd")
    proc = popup("sheet", path, "--out", str(tmp_path), home=user_home)
    assert_clean_error(proc, path, "Tent: Foot = -3 mm")


@pytest.mark.parametrize(
    "options, fragments",
    [
        (["--paper", "A9"], ["A9", "A4, A3, Letter, Tabloid"]),
        (["--paper", "A3", "--kerf", "-1"], ["--kerf: kerf = -1", "0 to 2 mm"]),
        (["--paper", "A3", "--tab-angle", "120"], ["--tab-angle: tab_angle = 120"]),
        (
            ["--paper", "A3", "--min-corner-angle", "95"],
            ["--min-corner-angle: min_corner_angle = 95", "0 to 90°"],
        ),
        (["--paper", "A3", "--min-feature", "-2"], ["--min-feature: min_feature = -2"]),
        (["--paper", "A4"], ["piece P1", "does not fit the printable area 190.0 x 277.0 mm of A4"]),
    ],
)
def test_sheet_bad_input_is_named(options, fragments, tmp_path):
    design = data("mechanisms/demo_card.json")
    proc = popup("sheet", design, "--out", str(tmp_path), *options)
    assert_clean_error(proc, *fragments)


def test_sheet_needs_an_output_folder():
    assert_clean_error(popup("sheet", data("mechanisms/tent.json")), "--out")


def spiked_card(path):
    """A 200 x 140 card whose ground has a 20° spike on its outer edge (base 20 mm); every other
    corner of the card is 90°."""
    tip = 140.0 + 10.0 / math.tan(math.radians(10.0))
    design = {
        "format": "popup-design",
        "version": 1,
        "name": "spiked card",
        "design_angle_deg": 180.0,
        "paper_thickness": 0.2,
        "ground": 0,
        "backdrop": 1,
        "patches": [
            {
                "id": 0,
                "name": "ground",
                "role": "ground",
                "outline": [
                    [0, 0, 0], [140, 0, 0], [140, 150, 0], [tip, 160, 0], [140, 170, 0],
                    [140, 200, 0], [0, 200, 0],
                ],
            },
            {
                "id": 1,
                "name": "backdrop",
                "role": "backdrop",
                "outline": [[0, 0, 0], [0, 200, 0], [-140, 200, 0], [-140, 0, 0]],
            },
        ],
        "hinges": [
            {"id": 0, "patches": [0, 1], "from": [0, 0, 0], "to": [0, 200, 0], "fold": "valley"}
        ],
        "glue": [],
    }  # fmt: skip
    with open(path, "w") as f:
        json.dump(design, f)
    return str(path)


def test_sheet_corner_limit_decides_the_sharp_corner_warning(tmp_path):
    design = spiked_card(tmp_path / "spiked.json")

    def sharp_corners(limit):
        out = tmp_path / f"limit{limit}"
        args = ["--out", str(out), "--paper", "500x400", "--min-corner-angle", str(limit)]
        proc = popup("sheet", design, *args)
        assert proc.returncode == 0, proc.stderr
        report = read_report(out)
        return [d for d in report["warnings"] if d["code"] == "sharp_corner"]

    (spike,) = sharp_corners(30)
    assert "has a 20° corner" in spike["message"] and sorted(spike["patches"]) == [0, 1]
    assert sharp_corners(25) != [] and sharp_corners(19) == []


def test_printed_side_turns_the_card_over(tmp_path):
    """The card's central fold is the longest fold line: a valley seen from the printed inside,
    a mountain when the card is printed on its outside. Read back from the DXF."""
    import ezdxf

    design = data("mechanisms/demo_card.json")

    def longest_fold_layer(*extra):
        out = tmp_path / ("_".join(extra) or "front")
        proc = popup("sheet", design, "--out", str(out), "--paper", "A3", *extra)
        assert proc.returncode == 0, proc.stderr
        lines = [
            e
            for e in ezdxf.readfile(str(out / "sheets.dxf")).modelspace()
            if e.dxftype() == "LINE" and e.dxf.layer in ("MOUNTAIN", "VALLEY")
        ]
        longest = max(lines, key=lambda e: (e.dxf.end - e.dxf.start).magnitude)
        with open(out / "sheets.json") as f:
            sides = {p["id"]: p["printed_side"] for p in json.load(f)["pieces"]}
        return longest.dxf.layer, (longest.dxf.end - longest.dxf.start).magnitude, sides

    layer, length, sides = longest_fold_layer()
    assert layer == "VALLEY" and set(sides.values()) == {"front"}
    turned_layer, turned_length, turned_sides = longest_fold_layer("--printed-side", "P1=back")
    assert turned_layer == "MOUNTAIN" and turned_length == pytest.approx(length, abs=1e-6)
    assert turned_sides["P1"] == "back" and sides.keys() == turned_sides.keys()
    assert all(side == "front" for piece, side in turned_sides.items() if piece != "P1")
    proc = popup("sheet", design, "--out", str(tmp_path / "x"), "--printed-side", "P1=up")
    assert_clean_error(proc, "--printed-side", "front or back")


def rewritten(source, target, change):
    """A copy of the .FCStd `source` whose Document.xml is change(text)."""
    import zipfile

    with zipfile.ZipFile(source) as old, zipfile.ZipFile(target, "w") as new:
        for item in old.infolist():
            data = old.read(item)
            if item.filename == "Document.xml":
                data = change(data)
            new.writestr(item, data)
    return str(target)


def test_documents_freecad_would_misread_are_refused_unread(card_documents, user_home, tmp_path):
    good = str(card_documents / "card.FCStd")
    laughs = (
        b'<?xml version="1.0"?><!DOCTYPE lolz [<!ENTITY lol "lol">'
        + b"".join(b'<!ENTITY lol%d "%s">' % (k, b"&lol%d;" % (k - 1) * 10) for k in range(1, 10))
        + b"]>"
    )
    bomb = rewritten(good, tmp_path / "bomb.FCStd", lambda t: laughs + t[t.index(b"<Document") :])
    proc = popup("check", bomb, home=user_home)
    assert_clean_error(proc, "bomb.FCStd", "DOCTYPE")
    cut = rewritten(good, tmp_path / "cut.FCStd", lambda t: t[: len(t) // 2])
    assert_clean_error(popup("check", cut, home=user_home), "cut.FCStd", "Document.xml is damaged")

    def twice(xml):
        start = xml.index(b'<Object type="Part::FeaturePython" name="Tent"')
        end = xml.index(b"/>", start) + 2
        return xml[:end] + xml[start:end] + xml[end:]

    doubled = rewritten(good, tmp_path / "twice.FCStd", twice)
    assert_clean_error(popup("check", doubled, home=user_home), "names object 'Tent' twice")
    not_zip = tmp_path / "plain.FCStd"
    not_zip.write_text("hello")
    assert_clean_error(popup("check", str(not_zip), home=user_home), "zip archive")
    assert popup("check", good, home=user_home).returncode == 0


def test_names_cannot_write_to_the_terminal(tmp_path):
    """A patch name with an escape and a newline is printed escaped: no fake VALID line."""
    with open(data("tent_fold.json")) as f:
        design = json.load(f)
    design["hinges"].pop(1)  # the slope hangs from nothing: its name is in a finding
    design["patches"][2]["name"] = "x\x1b[31m\nVALID: fake"
    path = tmp_path / "named.json"
    path.write_text(json.dumps(design))
    proc = popup("check", str(path))
    assert proc.returncode == 1
    assert "\x1b" not in proc.stdout and "\\x1b[31m\\x0aVALID: fake" in proc.stdout
    assert [line for line in proc.stdout.splitlines() if line.startswith("VALID")] == []


def test_a_clearance_beyond_the_model_is_named():
    """The largest clearance is 5% of the model size popup check reports (345.4 mm here)."""
    proc = popup("check", data("mechanisms/box.json"), "--clearance", "1000")
    assert_clean_error(proc, "--clearance 1000: clearance = 1000 mm, must be 0 to 17.2")
    assert popup("check", data("mechanisms/box.json"), "--clearance", "0").returncode == 0


def test_a_damaged_document_does_not_check_valid(card_documents, user_home, tmp_path):
    """card.FCStd with its Box hosted on its own Tent (a Host loop), or with the tent's feature
    module renamed: mechanisms would be left out silently, so the check refuses the document."""
    import re

    good = str(card_documents / "card.FCStd")

    def host_loop(xml):
        text = xml.decode()
        start = text.index('<Object name="Box">')
        end = text.index("</Object>", start)
        looped = re.sub(
            r'(<Property name="Host".*?<Link value=")Card', r"\1Tent", text[start:end], 1, re.S
        )
        assert looped != text[start:end]
        return (text[:start] + looped + text[end:]).encode()

    def no_proxy(xml):
        return xml.replace(
            b'module="popupwb.features.tent_fold"', b'module="popupwb.features.gone"'
        )

    looped = rewritten(good, tmp_path / "loop.FCStd", host_loop)
    assert_clean_error(
        popup("check", looped, home=user_home),
        "Box: Host = Tent, must not lead back to itself (Box -> Tent -> Box)",
    )
    missing = rewritten(good, tmp_path / "noproxy.FCStd", no_proxy)
    assert_clean_error(popup("check", missing, home=user_home), "Tent", "proxy module missing")


def test_a_utf16_design_is_named_as_such(tmp_path):
    with open(data("tent_fold.json"), encoding="utf-8") as f:
        text = f.read()
    path = tmp_path / "utf16.json"
    path.write_bytes(b"\xff\xfe" + text.encode("utf-16-le"))
    assert_clean_error(popup("check", str(path)), "utf16.json", "UTF-8 text", "\\xff")


def float_options():
    """(command, flag) of every float option of every popup command, read off the parser."""
    import argparse

    from popupwb import cli

    parser = cli.build_parser()
    (commands,) = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
    return [
        (name, action.option_strings[-1])
        for name, sub in commands.choices.items()
        for action in sub._actions
        if action.type is float
    ]


def test_every_float_option_takes_negative_values():
    """`--kerf -inf` got argparse's 'expected one argument': -inf, -nan and -1e-3 are values of
    every float option, so the option's own range check names it."""
    from popupwb import cli

    options = float_options()
    assert ("sheet", "--kerf") in options and ("check", "--clearance") in options
    assert ("verify", "--kerf") in options and len(options) >= 11
    positional = {
        "check": ["d"],
        "sheet": ["d", "--out", "o"],
        "verify": ["d", "s"],
        "fit": ["m", "--out", "o"],
        "animate": ["a", "--out", "o"],
    }
    for command, flag in options:
        for text in ("-inf", "-Infinity", "-nan", "-1e-3", "-2.5E+1", "-.5", "-7"):
            args = cli.build_parser().parse_args([command, *positional[command], flag, text])
            value = getattr(args, flag[2:].replace("-", "_"))
            expected = float(text)
            assert value == expected or (math.isnan(value) and math.isnan(expected)), (flag, text)
    with pytest.raises(cli.InputError, match="expected one argument"):
        cli.build_parser().parse_args(["sheet", "d", "--out", "o", "--kerf", "-x"])
