"""Scaffold objects in headless FreeCAD: geometry at several fold angles, errors that stay local,
save and reopen in a fresh process, and the validity check."""

import json
import math
import os
import shutil

import numpy as np
import pytest

from freecad_documents import assert_same_points, in_error, recompute_ok

REL = 1e-6


@pytest.fixture(scope="module")
def tent_file(data_dir):
    return os.path.join(data_dir, "tent_fold.json")


@pytest.fixture(scope="module")
def broken_file(data_dir):
    return os.path.join(data_dir, "broken_tent.json")


@pytest.fixture(scope="module")
def tent(popup, tent_file):
    return popup.core.load_scaffold(tent_file)


def test_scaffold_shape_follows_the_fold_angle(doc, popup, tent_file, tent):
    obj = popup.make.make_scaffold(doc, tent_file)
    patch_area = sum(p.area() for p in tent.patches)
    size = tent.size()
    boxes = {}
    for angle in (180.0, 90.0, 30.0, 0.0):
        obj.FoldAngle = angle
        recompute_ok(doc, obj)
        shape = obj.Shape
        assert shape.isValid()
        assert len(shape.Faces) == len(tent.patches)
        assert shape.Area == pytest.approx(patch_area, rel=REL)
        # Every face sits exactly where the core's simulator puts its patch.
        state = popup.core.simulate_fold(tent, [math.radians(angle)]).states[0]
        outlines = popup.core.posed_outlines(tent, state)
        for face, outline in zip(shape.childShapes(), outlines):
            face_points = [(v.X, v.Y, v.Z) for v in face.OuterWire.Vertexes]
            assert_same_points(face_points, outline, 1e-9 * size)
        box = shape.BoundBox
        boxes[angle] = np.array([box.XLength, box.YLength, box.ZLength])
    for a in boxes:
        for b in boxes:
            if a < b:
                assert np.abs(boxes[a] - boxes[b]).max() > 1e-3 * size, (a, b)
    assert boxes[0.0][0] < 1e-6 * size  # closed: everything in the page plane x = 0


def test_thickened_scaffold_is_one_solid_of_paper_thickness_per_patch(doc, popup, tent_file, tent):
    obj = popup.make.make_scaffold(doc, tent_file, fold_angle=120.0)
    assert obj.PaperThickness.Value == pytest.approx(tent.paper_thickness)
    obj.Thickened = True
    obj.PaperThickness = 0.5
    recompute_ok(doc, obj)
    assert obj.Shape.isValid()
    assert len(obj.Shape.Solids) == len(tent.patches)
    assert obj.Shape.Volume == pytest.approx(0.5 * sum(p.area() for p in tent.patches), rel=1e-6)


def test_recompute_keeps_the_placement_the_user_gave(doc, popup, tent_file, freecad):
    obj = popup.make.make_scaffold(doc, tent_file)
    recompute_ok(doc, obj)
    x_max = obj.Shape.BoundBox.XMax
    obj.Placement = freecad.Placement(freecad.Vector(10.0, 0.0, 0.0), freecad.Rotation())
    obj.FoldAngle = 180.0 - 1e-9  # same shape, recomputed
    recompute_ok(doc, obj)
    assert obj.Placement.Base.x == 10.0
    assert obj.Shape.BoundBox.XMax == pytest.approx(x_max + 10.0)


def test_thickened_without_thickness_names_the_property(doc, popup, tent_file):
    obj = popup.make.make_scaffold(doc, tent_file, name="Thin")
    obj.Thickened = True
    obj.PaperThickness = 0.0
    doc.recompute()
    assert in_error(obj)
    assert "Thin: PaperThickness = 0 mm, must be > 0 when Thickened" in obj.getStatusString()


def test_fold_angle_out_of_range_puts_only_that_object_in_error(doc, popup, tent_file):
    bad = popup.make.make_scaffold(doc, tent_file, name="Bad")
    good = popup.make.make_scaffold(doc, tent_file, name="Good")
    recompute_ok(doc, bad, good)
    bad.FoldAngle = 200.0
    good.FoldAngle = 45.0
    before = good.Shape.BoundBox.ZLength
    doc.recompute()
    assert in_error(bad)
    assert "Bad: FoldAngle = 200°, must be within 0° and 180°" in bad.getStatusString()
    assert not in_error(good)
    assert good.Shape.BoundBox.ZLength != pytest.approx(before)
    bad.FoldAngle = 45.0
    recompute_ok(doc, bad, good)
    assert bad.Shape.isValid()
    assert bad.Shape.BoundBox.DiagonalLength == pytest.approx(good.Shape.BoundBox.DiagonalLength)


def test_bad_design_file_puts_only_that_object_in_error(doc, popup, tent_file, tmp_path):
    design = json.loads(open(tent_file).read())
    design["patches"] = "not a list"
    bad_file = tmp_path / "bad_design.json"
    bad_file.write_text(json.dumps(design))
    bad = popup.make.make_scaffold(doc, str(bad_file), name="Bad")
    good = popup.make.make_scaffold(doc, tent_file, fold_angle=60.0, name="Good")
    doc.recompute()
    assert in_error(bad)
    message = bad.getStatusString()
    assert message.startswith("Bad: DesignFile '") and "is not a valid design: " in message
    assert "patches" in message
    assert not in_error(good) and good.Shape.isValid()
    bad.DesignFile = tent_file  # fixing the value recovers
    recompute_ok(doc, bad, good)
    assert bad.Shape.isValid()


def test_unreachable_fold_angle_names_the_locked_angle(doc, popup, broken_file):
    # broken_tent.json is designed at 90° and jams at about 113° when opened.
    broken = popup.core.load_scaffold(broken_file)
    sweep = popup.core.simulate_fold(broken, [math.pi])
    assert not sweep.complete and 100.0 < math.degrees(sweep.locked_at) < 180.0
    obj = popup.make.make_scaffold(doc, broken_file, fold_angle=90.0, name="Broken")
    recompute_ok(doc, obj)
    obj.FoldAngle = 180.0
    doc.recompute()
    assert in_error(obj)
    message = obj.getStatusString()
    assert "Broken: FoldAngle = 180° cannot be reached" in message
    assert f"the design locks at {math.degrees(sweep.locked_at):.2f}°" in message


def test_make_scaffold_refuses_a_missing_file(doc, popup, tmp_path):
    with pytest.raises(FileNotFoundError, match="does not exist"):
        popup.make.make_scaffold(doc, str(tmp_path / "nowhere.json"))
    assert doc.Objects == []


def test_design_is_parsed_once_per_content(popup, tent_file, tmp_path):
    copy = tmp_path / "copy.json"
    shutil.copy(tent_file, copy)
    first = popup.scaffold_feature.load_design(str(copy))
    assert popup.scaffold_feature.load_design(str(copy)) is first
    assert popup.scaffold_feature.load_design(tent_file) is first  # same text, same parse
    copy.write_text(copy.read_text() + "\n")
    assert popup.scaffold_feature.load_design(str(copy)) is not first


def test_proxy_state_is_json(doc, popup, tent_file):
    obj = popup.make.make_scaffold(doc, tent_file)
    for state in (obj.Proxy.__getstate__(), obj.Proxy.dumps()):
        json.dumps(state)
    assert obj.Version == "1"
    assert obj.getEditorMode("Version") == ["ReadOnly"]
    assert obj.getEditorMode("Diagnostics") == ["ReadOnly"]


def shape_figures(obj):
    shape = obj.Shape
    box = shape.BoundBox
    return {
        "area": shape.Area,
        "volume": shape.Volume,
        "bbox": [box.XMin, box.YMin, box.ZMin, box.XMax, box.YMax, box.ZMax],
        "vertices": [[v.X, v.Y, v.Z] for v in shape.Vertexes],
    }


REOPEN_SCRIPT = """
import json
doc = FreeCAD.openDocument({path!r})
obj = doc.getObject("Scaffold")
out = {{"proxy": obj.Proxy is not None, "version": obj.Version, "valid": obj.Valid,
        "diagnostics": list(obj.Diagnostics), "fold_angle": obj.FoldAngle.Value,
        "design_exists": bool(obj.DesignFile) and __import__("os").path.isfile(obj.DesignFile)}}
obj.touch()
doc.recompute()
out["state"] = list(obj.State)
shape = obj.Shape
box = shape.BoundBox
out.update(area=shape.Area, volume=shape.Volume,
           bbox=[box.XMin, box.YMin, box.ZMin, box.XMax, box.YMax, box.ZMax],
           vertices=[[v.X, v.Y, v.Z] for v in shape.Vertexes])
print(json.dumps(out))
"""


def test_scaffold_survives_save_and_reopen(doc, popup, tent_file, tmp_path, run_fresh_freecad):
    # The design lives in the document: the source file is gone before the reopen.
    design = tmp_path / "tent_copy.json"
    shutil.copy(tent_file, design)
    obj = popup.make.make_scaffold(doc, str(design), fold_angle=63.0)
    obj.Thickened = True
    recompute_ok(doc, obj)
    popup.validity.run_check(obj)
    expected = shape_figures(obj)
    path = str(tmp_path / "scaffold.FCStd")
    doc.saveAs(path)
    design.unlink()

    reopened = run_fresh_freecad(REOPEN_SCRIPT.format(path=path))
    assert reopened["proxy"], "proxy not restored: is the sandbox Mod/PopUp symlink in place?"
    assert reopened["version"] == "1"
    assert reopened["design_exists"]
    assert reopened["fold_angle"] == pytest.approx(63.0)
    assert reopened["valid"] == obj.Valid and reopened["diagnostics"] == list(obj.Diagnostics)
    assert "Invalid" not in reopened["state"]
    assert reopened["area"] == pytest.approx(expected["area"], rel=1e-12)
    assert reopened["volume"] == pytest.approx(expected["volume"], rel=1e-12)
    assert reopened["bbox"] == pytest.approx(expected["bbox"], abs=1e-9)
    assert np.array(reopened["vertices"]) == pytest.approx(np.array(expected["vertices"]), abs=1e-9)


def test_check_validity_accepts_a_valid_design(doc, popup, tent_file):
    obj = popup.make.make_scaffold(doc, tent_file)
    report = popup.validity.run_check(obj)
    assert report["valid"] is True and obj.Valid is True
    assert report["foldable"] and report["stable"]
    assert report["intersection_free"] and report["enclosed"]
    assert list(obj.Diagnostics) == [
        popup.validity.format_diagnostic(d) for d in report["diagnostics"]
    ]
    assert popup.validity.format_report(report).startswith("VALID")


def test_check_validity_rejects_a_broken_design(doc, popup, broken_file):
    obj = popup.make.make_scaffold(doc, broken_file)
    report = popup.validity.run_check(obj)
    assert report["valid"] is False and obj.Valid is False
    assert report["foldable"] is False
    assert len(obj.Diagnostics) >= 1
    for line in obj.Diagnostics:
        code, _, message = line.partition(": ")
        assert code and message
    text = popup.validity.format_report(report)
    assert text.startswith("INVALID") and "NOT foldable" in text
    assert obj.Diagnostics[0] in text


def test_changing_the_design_resets_the_verdict(doc, popup, tent_file, broken_file):
    obj = popup.make.make_scaffold(doc, tent_file)
    recompute_ok(doc, obj)
    popup.validity.run_check(obj)
    assert obj.Valid
    assert "Touched" not in obj.State  # the verdict is output, it does not trigger a recompute
    obj.DesignFile = broken_file
    assert obj.Valid is False and list(obj.Diagnostics) == []


def test_check_validity_of_an_unreadable_design_reports_instead_of_raising(doc, popup, tmp_path):
    bad_file = tmp_path / "broken.json"
    bad_file.write_text("{ this is not json")
    obj = popup.make.make_scaffold(doc, str(bad_file))
    report = popup.validity.run_check(obj)
    assert report["valid"] is False and obj.Valid is False
    assert obj.Diagnostics[0].startswith("design_error: Scaffold: DesignFile '")
    assert popup.validity.format_report(report).startswith("INVALID")


def test_format_report_lists_verdicts_numbers_and_findings(popup):
    report = {
        "valid": False,
        "foldable": False,
        "stable": True,
        "intersection_free": True,
        "enclosed": True,
        "locked_at_deg": 42.0,
        "max_hinge_residual": 1e-9,
        "model_size": 210.0,
        "diagnostics": [{"code": "motion_locked", "message": "hinge 3: the motion stops"}],
    }
    lines = popup.validity.format_report(report).splitlines()
    assert lines[0] == "INVALID: NOT foldable, stable, intersection-free, enclosed"
    assert any("42.00°" in line for line in lines)
    assert any("210 mm" in line for line in lines)
    assert lines[-1].strip() == "motion_locked: hinge 3: the motion stops"


def test_popupcore_is_found_from_the_build_dir_alone(run_fresh_freecad):
    # With no popupcore on sys.path, popupwb.core falls back on $POPUP_BUILD_DIR/python.
    build_python = os.path.realpath(os.path.join(os.environ["POPUP_BUILD_DIR"], "python"))
    script = f"""
import glob, json, os, sys
sys.path[:] = [p for p in sys.path if not glob.glob(os.path.join(p or ".", "popupcore*"))]
assert "popupcore" not in sys.modules
from popupwb.core import popupcore
print(json.dumps({{"file": os.path.realpath(popupcore.__file__)}}))
"""
    found = run_fresh_freecad(script)
    assert os.path.dirname(found["file"]) == build_python
