"""The PopUp preferences (popupwb/preferences.py): `popup sheet` takes its defaults from the user's
FreeCAD user.cfg (here a sandboxed FREECAD_USER_HOME), and each option given overrides its own.
The DXF is read back with ezdxf, independently of the writer."""

import json
import textwrap

import ezdxf
import pytest

from cli_documents import build_cards
from cli_runner import assert_clean_error, popup, run_freecad_script

MAGENTA_ACI = 6  # AutoCAD's palette: index 6 is (255, 0, 255)

WRITE_PREFERENCES = textwrap.dedent(
    """
    import json, sys
    import FreeCAD
    from popupwb import preferences

    values = json.loads(sys.argv[1])
    values = {k: tuple(v) if isinstance(v, list) else v for k, v in values.items()}
    preferences.write(FreeCAD.ParamGet(preferences.PARAMETER_GROUP), values)
    FreeCAD.saveParameter()
    """
)


def set_preferences(home, **values):
    run_freecad_script(WRITE_PREFERENCES, json.dumps(values), home=home)


@pytest.fixture(scope="module")
def cards(tmp_path_factory, user_home):
    return build_cards(tmp_path_factory.mktemp("cards"), user_home)


@pytest.fixture
def home(tmp_path):
    """A FreeCAD user home of this test's own, with its preferences."""
    folder = tmp_path / "home"
    folder.mkdir()
    return str(folder)


def dxf_facts(folder):
    doc = ezdxf.readfile(str(folder / "sheets.dxf"))
    layers = {layer.dxf.name: layer.dxf.color for layer in doc.layers}
    used = {entity.dxf.layer for entity in doc.modelspace()}
    return layers, used, float(doc.header.custom_vars.get("PopUpKerf"))


def test_popup_sheet_takes_its_defaults_from_the_preferences(cards, home, tmp_path):
    out = tmp_path / "preferred"
    set_preferences(
        home,
        Kerf=0.3,
        TabWidth=6.0,
        TabAngle=40.0,
        SheetPaper="A3",
        CutLayerName="Schnitt",
        CutLayerColour=[255, 0, 255],
        ValleyLayerName="Tal",
        ExportFolder=str(out),
    )
    proc = popup("sheet", str(cards / "two_cards.FCStd"), "--card", "Good", home=home)
    assert proc.returncode == 0, proc.stderr
    layers, used, kerf = dxf_facts(out)  # no --out: the preferred folder
    assert layers["Schnitt"] == MAGENTA_ACI and "CUT" not in layers
    assert {"Schnitt", "Tal"} <= used  # the cuts and valley folds are drawn on the renamed layers
    assert layers["MOUNTAIN"] == 5  # a layer left alone keeps name and colour
    assert kerf == 0.3
    report = json.loads((out / "report.json").read_text())
    assert report["paper"]["name"] == "A3"
    assert (report["options"]["tab_width"], report["options"]["tab_angle"]) == (6.0, 40.0)
    # popup verify reads the sheets by the same layer names.
    verified = popup(
        "verify", str(cards / "two_cards.FCStd"), str(out), "--card", "Good", home=home
    )
    assert verified.returncode == 0, verified.stdout + verified.stderr


def test_options_override_the_preferences(cards, home, tmp_path):
    set_preferences(home, Kerf=0.3, SheetPaper="A3", ExportFolder=str(tmp_path / "preferred"))
    out = tmp_path / "given"
    args = ["--card", "Good", "--kerf", "0.05", "--paper", "A4", "--tab-width", "7", "--out"]
    proc = popup("sheet", str(cards / "two_cards.FCStd"), *args, str(out), home=home)
    assert proc.returncode == 0, proc.stderr
    assert not (tmp_path / "preferred").exists()
    _, _, kerf = dxf_facts(out)
    assert kerf == 0.05
    report = json.loads((out / "report.json").read_text())
    assert report["paper"]["name"] == "A4" and report["options"]["tab_width"] == 7.0


def test_an_unset_preference_is_the_built_in_default(cards, home, tmp_path):
    out = tmp_path / "out"
    proc = popup(
        "sheet", str(cards / "two_cards.FCStd"), "--card", "Good", "--out", str(out), home=home
    )
    assert proc.returncode == 0, proc.stderr
    layers, _, kerf = dxf_facts(out)
    assert layers["CUT"] == 1 and kerf == 0.1  # layer_style.SheetStyle, the core's kerf


@pytest.mark.parametrize(
    "values, fragments",
    [
        ({"Kerf": 5.0}, ["PopUp preference Kerf = 5 mm", "0 to 2 mm", "Edit › Preferences"]),
        ({"SheetPaper": "B7"}, ["PopUp preference SheetPaper = 'B7'"]),
        ({"CutLayerName": ""}, ["PopUp preference CutLayerName = ''", "must not be empty"]),
        ({"LabelLayerName": "a/b"}, ["PopUp preference LabelLayerName = 'a/b'", "DXF layer"]),
        ({"GlueLayerName": "cut"}, ["PopUp preference GlueLayerName = 'cut'", "must differ"]),
    ],
)
def test_a_preference_out_of_range_is_one_line(cards, home, tmp_path, values, fragments):
    set_preferences(home, **values)
    out = str(tmp_path / "out")
    proc = popup("sheet", str(cards / "two_cards.FCStd"), "--card", "Good", "--out", out, home=home)
    assert_clean_error(proc, *fragments, "user.cfg")


def test_no_folder_anywhere_is_one_line(cards, home):
    proc = popup("sheet", str(cards / "two_cards.FCStd"), "--card", "Good", home=home)
    assert_clean_error(proc, "--out DIR", "export folder")


def test_colours_round_trip_through_freecads_packing():
    from popupwb import preferences
    from popupwb.sheets.layer_style import nearest_aci

    assert preferences.packed((255, 0, 255)) == 0xFF00FFFF  # 0xRRGGBBAA, as FreeCAD stores it
    assert preferences.rgb_of(0x12345678) == (0x12, 0x34, 0x56)
    assert (nearest_aci((255, 0, 255)), nearest_aci((0, 0, 0)), nearest_aci((250, 5, 5))) == (
        6,
        7,
        1,
    )
