"""Outlines that follow the model (thesis §5.1.3) through `popup fit`: the truck on wheels of
tools/make_models.py, fitted upright as one box fold (with no minimum part size), gets the wheel arches cut out of the box's
sides; the saved design.FCStd carries them as the features' Profiles, and FreeCAD rebuilds the
same profiled patches.

Areas are re-measured here from the rebuilt patches' corners (Newell), independently of the
core's Clipper areas in report.json; the expected cut comes from how the truck was made (four
wheels of radius 10 under a body raised 8 mm)."""

import json
import math
import os

import numpy as np
import pytest

from cli_runner import popup, read_report, run_design
from test_cli_fit import UPRIGHT, make_models


def _area(loop):
    """Area of a planar 3D polygon (Newell's normal / 2)."""
    p = np.asarray(loop, dtype=float).reshape(-1, 3)
    q = np.roll(p, -1, axis=0)
    return 0.5 * float(np.linalg.norm(np.cross(p, q).sum(axis=0)))


@pytest.fixture(scope="module")
def truck_fit(tmp_path_factory):
    folder = tmp_path_factory.mktemp("truck")
    model = make_models.write_model("truck_with_wheels", str(folder / "truck.stl"))
    out = folder / "fit"
    # One box as long as the truck: its sides are thinner than the glue tabs' minimum
    # (--min-part, 11.1 mm by default), which would have the fitter take a tent instead.
    proc = run_design("fit", model, out, *UPRIGHT, "--max-mechanisms", "1", "--min-part", "0")
    return out, proc, read_report(out)


def test_the_box_sides_take_the_wheel_arches(truck_fit):
    _, _, report = truck_fit
    assert report["valid"] is True
    # One fitted box; the cargo box above the cab's height may come back as its top's depth
    # layer, a box fold nested on it.
    assert report["mechanisms"][0]["type"] == "box_fold"
    assert all(
        m["type"] == "box_fold" and m["host"].startswith("B1.") for m in report["mechanisms"][1:]
    )
    parts = {p["part"]: p for p in report["profiles"] if p["mechanism"] == "B1"}
    # The sides take the arches; the end panels may take the end view's band under the body.
    assert {"L", "R"} <= set(parts) <= {"L", "R", "FL", "FR", "BL", "BR"}
    box = report["mechanisms"][0]["parameters"]
    scale = abs(np.linalg.det(np.asarray(report["model_to_card"])[:3, :3])) ** (1 / 3)
    for p in (parts["L"], parts["R"]):
        assert p["mechanism"] == "B1"
        assert p["area_before_mm2"] == pytest.approx(box["width"] * box["height"], rel=1e-9)
        # Below the body (8 mm up) the side sees only the wheels (radius 10, axles 10 mm up at
        # x = 18 and 82): the band of the box's length × 8 minus, per wheel under the box, the
        # circle segment below a chord 2 mm from its centre, r² acos(d/r) − d √(r² − d²).
        # Cusps narrower than 3 mm (where a wheel meets the ground or the body) stay paper, so
        # the cut is a little less.
        to_model = np.linalg.inv(np.asarray(report["model_to_card"]))
        ends = [
            (to_model @ [0.0, y, 0.0, 1.0])[0]
            for y in (box["offset"], box["offset"] + box["width"])
        ]
        x0, x1 = min(ends), max(ends)
        wheels = [x for x in (18, 82) if x0 <= x - 10 and x + 10 <= x1]
        assert all(x + 10 <= x0 or x - 10 >= x1 or x in wheels for x in (18, 82))
        segment = 100 * math.acos(0.2) - 2 * math.sqrt(96)
        band = (x1 - x0) * 8 - len(wheels) * segment
        # Above the chassis (top at z = 20) the side sees the cargo box (x < 62, top 56) and the
        # cab (x > 68, top 46) of tools/make_models.py: the box, as tall as it is, also loses the
        # 6 mm gap between them and what stands above the cab.
        top = box["height"] / scale
        band += (min(x1, 68) - max(x0, 62)) * max(0.0, min(top, 56) - 20)
        band += max(0.0, x1 - 68) * max(0.0, min(top, 56) - 46)
        cut = (p["area_before_mm2"] - p["area_mm2"]) / scale**2
        assert 0.95 * band <= cut <= band * 1.001, (cut, band)
        assert p["points"] > 8  # round arches, not a rectangle


def test_the_design_carries_the_profiles_and_rebuilds_them(truck_fit, freecad):
    out, _, report = truck_fit
    from popupwb import profiles
    from popupwb.model import card_scaffold

    doc = freecad.openDocument(os.path.join(str(out), "design.FCStd"))
    try:
        box = doc.getObject("B1")
        stored = profiles.stored(box)
        of_box = [p for p in report["profiles"] if p["mechanism"] == "B1"]
        assert sorted(stored) == sorted(p["part"] for p in of_box)
        assert {"L", "R"} <= set(stored)
        doc.recompute()
        assert not [o.Label for o in doc.Objects if "Invalid" in o.State]
        built = card_scaffold.for_card(doc.getObject("Card"))
        patches = {p.name: p for p in built.scaffold.patches}
        for entry in of_box:
            patch = patches[f"{entry['mechanism']}.{entry['part']}"]
            area = _area(patch.outer) - sum(_area(h) for h in patch.holes)
            assert area == pytest.approx(entry["area_mm2"], rel=1e-6)
            ref = stored[entry["part"]]["reference"]
            assert ref[0] * ref[1] == pytest.approx(entry["area_before_mm2"], rel=1e-9)
    finally:
        freecad.closeDocument(doc.Name)


def test_the_profiled_sheets_verify(truck_fit, tmp_path):
    """The box's sides lost most of their ground fold to the wheel arches; the card re-made from
    its cutting file must still fold like the design at every angle asked for, not only open
    flat (docs/DESIGN.md, "Profiles keep their folds exact")."""
    out, _, _ = truck_fit
    sheets = tmp_path / "sheets"
    # The fitted box is 5 mm deep: tabs of 2 mm fit where the default 3 mm do not.
    proc = popup(
        "sheet",
        os.path.join(str(out), "design.FCStd"),
        "--out",
        str(sheets),
        "--tab-width",
        "2",
        "--min-tab-width",
        "1",
    )
    assert proc.returncode == 0, proc.stdout + proc.stderr
    trip = read_report(sheets)["round_trip"]
    assert trip["ok"] is True
    assert trip["angles"] == 13  # the CLI's default sweep, design angle to closed
    assert trip["max_error"] <= trip["tolerance"]
    # And from the DXF alone, as the maker gets it.
    proc = popup(
        "verify", os.path.join(str(out), "design.FCStd"), str(sheets / "sheets.dxf"), "--json"
    )
    assert proc.returncode == 0, proc.stdout + proc.stderr
    verdict = json.loads(proc.stdout)
    assert verdict["ok"] is True and verdict["angles"] == 13, verdict
