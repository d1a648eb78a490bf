"""A feature's expected error is one console line naming object, property, value and range, and
the object is still Invalid with that message; a real bug keeps its traceback
(features/one_line_errors.py). Run in a fresh FreeCAD process: its console writes to the
process's own output, which is what is read here (freecadcmd: a module import prints nothing)."""

import json
import os
import subprocess

from conftest import TIME_SCALE

SCRIPT = r"""
import json, os, sys
import FreeCAD
import popupwb.make as make
from popupwb.model import card_scaffold

def state(obj):
    return {"state": list(obj.State), "status": obj.getStatusString()}

out = {}
doc = FreeCAD.newDocument("E")
card = make.make_card(doc, preset="A5")
box = make.make_box_fold(card, Offset=40, Width=60, DepthGround=30, DepthBackdrop=30, Height=30)
doc.recompute()
case = os.environ["ONE_LINE_CASE"]
if case == "expected":
    card.FoldAngle = 200
    doc.recompute()
    out["card"] = state(card)
    card.FoldAngle = 90
    box.Height = -5
    doc.recompute()
    out["box"] = state(box)
    box.Height = 30
    doc.recompute()
    sheet = make.make_cutting_sheet(card, paper="A3", make_pages=False, TabAngle=95)
    doc.recompute()
    out["sheet"] = state(sheet)
else:  # a bug: an exception type no feature raises on purpose
    def broken(card):
        raise KeyError("not a design error")
    card_scaffold.for_card = broken
    card.touch()
    doc.recompute()
    out["card"] = state(card)
out["tracebacklimit"] = getattr(sys, "tracebacklimit", None)
print("RESULT " + json.dumps(out))
"""


def run(case, tmp_path):
    """freecadcmd on SCRIPT. FreeCAD 1.1's freecadcmd ignores PYTHONPATH: popupwb comes from the
    sandbox Mod folder (the tests take the sandbox_mod fixture), popupcore from POPUP_BUILD_DIR."""
    script = tmp_path / "one_line_errors.py"
    script.write_text(SCRIPT)
    process = subprocess.run(
        ["freecadcmd", str(script)],
        env=dict(os.environ, ONE_LINE_CASE=case),
        capture_output=True,
        text=True,
        timeout=120 * TIME_SCALE,
    )
    output = process.stdout + process.stderr
    assert "RESULT " in output, output
    result = json.loads(output.split("RESULT ", 1)[1].splitlines()[0])
    return result, output


def test_bad_values_print_one_line_each_and_leave_the_objects_invalid(tmp_path, sandbox_mod):
    result, output = run("expected", tmp_path)
    assert "Traceback" not in output, output
    card, box, sheet = result["card"], result["box"], result["sheet"]
    assert "Invalid" in card["state"], card
    assert card["status"] == "Card: FoldAngle = 200°, must be within 0° and 180°", card
    assert f"PopUp: {card['status']}\n" in output, output
    assert "Invalid" in box["state"] and box["status"].startswith("BoxFold: Height = -5 mm"), box
    assert f"PopUp: {box['status']}\n" in output, output
    assert "Invalid" in sheet["state"] and "TabAngle" in sheet["status"], sheet
    assert "95" in sheet["status"] and "must be" in sheet["status"], sheet
    assert result["tracebacklimit"] is None  # restored after each error


def test_a_real_bug_keeps_its_traceback(tmp_path, sandbox_mod):
    result, output = run("bug", tmp_path)
    assert "Invalid" in result["card"]["state"], result
    assert "Traceback (most recent call last)" in output, output
    assert "not a design error" in output, output
    assert result["tracebacklimit"] is None
