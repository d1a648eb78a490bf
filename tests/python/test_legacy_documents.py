"""Documents saved by an older workbench still open: the proxy module paths and class names they
store (tests/data/make_legacy_card.py made them at commit ea71710, before card_scaffold, the
mechanism registry and view providers restored by name) must still import."""

import math
import os
import re
import zipfile

import pytest

LEGACY = ("legacy_card.FCStd", "legacy_card_gui.FCStd")

REOPEN = r"""
import json
doc = FreeCAD.openDocument(%(path)r)
card, tent, sheet = (doc.getObject(n) for n in ("Card", "Tent", "CuttingSheet"))
out = {"verdict": [card.Validity, card.Valid, list(card.Diagnostics)],
       "proxies": {o.Name: type(o.Proxy).__module__ + "." + type(o.Proxy).__name__
                   for o in (card, tent, sheet) if o.Proxy is not None}}
# Change the design so every proxy has to execute with today's code.
tent.Foot = 25.0
card.FoldAngle = 90.0
doc.recompute()
out["states"] = {o.Name: list(o.State) for o in (card, tent, sheet)}
out["faces"] = {o.Name: len(o.Shape.Faces) for o in (card, tent)}
out["slope_backdrop"] = tent.SlopeBackdrop.Value
out["card_height"] = card.Shape.BoundBox.ZLength
out["pieces"] = sheet.PieceCount
out["round_trip"] = sheet.RoundTripOk
# Lengths saved as unsigned PropertyLength come back signed, their values kept, so that a wrong
# value is reported with its range instead of being stored as 0.
out["types"] = {n: card.getTypeIdOfProperty(n) for n in ("Width", "Depth", "PaperThickness")}
out["sizes"] = [card.Width.Value, card.Depth.Value, card.PaperThickness.Value]
card.PaperThickness = -1.0
doc.recompute()
out["thickness_error"] = [card.PaperThickness.Value, card.getStatusString()]
print(json.dumps(out))
"""


def stored_proxies(path, member):
    """(module, class) of every Python proxy `member` (Document.xml or GuiDocument.xml) stores."""
    with zipfile.ZipFile(path) as archive:
        text = archive.read(member).decode("utf-8")
    return set(
        re.findall(r'<Python value="[^"]*" encoded="yes" module="([^"]+)" class="([^"]+)"', text)
    )


@pytest.mark.parametrize("name", LEGACY)
def test_every_stored_proxy_class_still_imports(freecad, data_dir, name):
    import importlib

    path = os.path.join(data_dir, name)
    stored = stored_proxies(path, "Document.xml")
    if name.endswith("_gui.FCStd"):
        stored |= stored_proxies(path, "GuiDocument.xml")
        assert len(stored) == 6  # 3 features, 3 view providers
    else:
        assert len(stored) == 3
    for module, cls in sorted(stored):
        assert hasattr(importlib.import_module(module), cls), f"{module}.{cls}"


@pytest.mark.parametrize("name", LEGACY)
def test_legacy_card_reopens_and_recomputes(run_fresh_freecad, data_dir, name):
    out = run_fresh_freecad(REOPEN % {"path": os.path.join(data_dir, name)})
    assert out["proxies"] == {
        "Card": "popupwb.features.card_feature.PopUpCard",
        "Tent": "popupwb.features.tent_fold.TentFold",
        "CuttingSheet": "popupwb.features.cutting_sheet.CuttingSheet",
    }
    assert out["states"] == {n: ["Up-to-date"] for n in ("Card", "Tent", "CuttingSheet")}
    # Saved before Validity existed, never checked: migrated to NotChecked, Valid kept.
    assert out["verdict"] == ["NotChecked", False, []]
    assert out["faces"] == {"Card": 2, "Tent": 2}  # the card shows its pages, the tent its own
    assert out["slope_backdrop"] == pytest.approx(25.0 + 30.0 - 20.0)  # Foot + Slope - FootBackdrop
    # At 90° each 105 mm page rises 45° out of the plane it lay in at 180°.
    assert out["card_height"] == pytest.approx(105.0 * math.sin(math.radians(45.0)), abs=1e-6)
    assert out["pieces"] == 2 and out["round_trip"] is True
    assert set(out["types"].values()) == {"App::PropertyDistance"}
    assert out["sizes"] == pytest.approx([148.0, 105.0, 0.2])
    value, status = out["thickness_error"]
    assert value == -1.0
    assert "PaperThickness" in status and "-1" in status and "5" in status, status
