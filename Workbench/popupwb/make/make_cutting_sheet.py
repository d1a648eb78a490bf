"""make_cutting_sheet: a CuttingSheet laying out a PopUpCard, headless or in the GUI."""

import FreeCAD

from popupwb.model import card_scaffold
from popupwb.features.cutting_sheet import CUSTOM, OPTIONS, PAPERS, CuttingSheet
from popupwb.sheets.sheet_options import defaults, option_named, parse_sides, sides_text
from popupwb.view_provider_by_name import view_provider_class


def make_cutting_sheet(
    card,
    paper=None,
    paper_width=None,
    paper_height=None,
    make_pages=True,
    name="CuttingSheet",
    **options,
):
    """Adds a CuttingSheet of `card` (a PopUpCard) to the card's document.

    `paper` is A4, A3, Letter, Tabloid or Custom (default: the core's); `paper_width` and
    `paper_height` (mm) make it Custom. Other keywords are the layout options of
    sheets/sheet_options.py, by core or property name: margin, spacing, kerf, min_gap, tab_width,
    min_tab_width, min_feature (mm), tab_angle, min_corner_angle (degrees), fold_hints,
    printed_sides ({"P1": "back"}). The caller recomputes.
    """
    if not card_scaffold.is_card(card):
        raise ValueError(
            f"make_cutting_sheet: card {getattr(card, 'Label', card)} must be a PopUpCard"
        )
    if paper is None:
        paper = defaults()["paper"]
    if paper not in PAPERS:
        raise ValueError(f"make_cutting_sheet: paper = {paper!r}, must be one of {PAPERS}")
    by_key = {}
    for option in OPTIONS:
        by_key[option.name] = by_key[option.prop] = option.prop
    unknown = sorted(set(options) - set(by_key))
    if unknown:
        raise TypeError(
            f"make_cutting_sheet: unknown option(s) {unknown}; known: "
            f"{[option.name for option in OPTIONS]}"
        )
    obj = card.Document.addObject("Part::FeaturePython", name)
    CuttingSheet(obj)
    obj.Card = card
    obj.Paper = paper
    if paper_width is not None or paper_height is not None:
        obj.Paper = CUSTOM
        if paper_width is not None:
            obj.PaperWidth = paper_width
        if paper_height is not None:
            obj.PaperHeight = paper_height
    for key, value in options.items():
        if option_named(key).kind == "sides":  # {"P1": "back"} or ["P1=back"]
            value = sides_text(parse_sides(value))
        setattr(obj, by_key[key], value)
    obj.MakePages = make_pages
    if FreeCAD.GuiUp:
        view_provider_class(obj.Proxy)(obj.ViewObject)
    return obj
