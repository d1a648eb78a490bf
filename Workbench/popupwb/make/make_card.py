"""make_card: a PopUpCard of a paper size, headless or in the GUI."""

import FreeCAD

from popupwb.features.card_feature import CUSTOM, PRESET_NAMES, PopUpCard
from popupwb.view_provider_by_name import view_provider_class


def make_card(doc, preset="A5", width=None, depth=None, fold_angle=180.0, name="Card"):
    """Adds a PopUpCard to `doc` (the active document, or a new one, when None).

    `preset` is one of A4, A5, A6, Letter, HalfLetter (the sheet folded in half across its long
    side) or Custom; `width` (along the fold) and `depth` (each page) in mm override it and make
    the card Custom. The caller recomputes.
    """
    if preset not in PRESET_NAMES:
        raise ValueError(f"make_card: preset = {preset!r}, must be one of {PRESET_NAMES}")
    doc = doc or FreeCAD.ActiveDocument or FreeCAD.newDocument()
    obj = doc.addObject("Part::FeaturePython", name)
    PopUpCard(obj)
    obj.Preset = preset
    if width is not None or depth is not None:
        obj.Preset = CUSTOM
        if width is not None:
            obj.Width = width
        if depth is not None:
            obj.Depth = depth
    obj.FoldAngle = fold_angle
    if FreeCAD.GuiUp:
        view_provider_class(obj.Proxy)(obj.ViewObject)
    return obj
