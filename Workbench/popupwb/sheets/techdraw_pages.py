"""TechDraw pages of a CuttingSheet: one page per sheet of its sheet set, at 1:1.

A sheet's page (TechDraw::DrawPage) holds a blank template of the paper's size, a view
(DrawViewPart looking down z, CoarseView) of the sheet's cut outline (a hidden Part::Feature), the
fold lines as cosmetic lines (the mountain and valley TechDraw line styles, the MOUNTAIN and
VALLEY colours of layer_style.SheetStyle) and every label as an annotation (DrawViewAnnotation)
centred on its position. Page coordinates are sheet coordinates (origin at the paper's lower-left
corner). The production files are export.py's: TechDraw's own DXF puts every line on one layer,
without linetypes or colours.

Templates: TechDraw's blank A4 portrait, A4 to A0 landscape and US Letter landscape, and this
workbench's blank A3, Letter and Tabloid portrait (TechDraw has none). A custom paper goes on the
smallest template that holds it at 1:1; when none does, on the one that shows it largest, scaled
down (Scale < 1).

Pages are found again by two properties of the page, CuttingSheet (the owner's Name, not a link:
a link would leave every new page Touched after the recompute that made it) and SheetIndex; every
update reuses them and removes those of sheets that are gone.

FreeCAD 0.20 defers removing an object during a recompute to the recompute's end, and then
removes whatever bears that name again at the end of every later recompute: a name removed here
during a recompute is never given to a new object again.
"""

import dataclasses
import os

import FreeCAD

import popupwb
from popupwb.sheets.layer_style import SheetStyle
from popupwb.sheets.not_valid_stamp import stamp_label
from popupwb.sheets.sheet_shapes import cut_outline, sheet_pieces

_TECHDRAW_TEMPLATES = "Mod/TechDraw/Templates/"
_OWN_TEMPLATES = os.path.join(popupwb.PACKAGE_DIR, "resources", "templates")
# (file, width, height in mm, folder): TechDraw's blank templates first, then ours.
TEMPLATES = (
    ("A4_Portrait_blank.svg", 210.0, 297.0, None),
    ("A4_Landscape_blank.svg", 297.0, 210.0, None),
    ("A3_Landscape_blank.svg", 420.0, 297.0, None),
    ("A2_Landscape_blank.svg", 594.0, 420.0, None),
    ("A1_Landscape_blank.svg", 841.0, 594.0, None),
    ("A0_Landscape_blank.svg", 1189.0, 841.0, None),
    ("USLetter_Landscape_blank.svg", 279.4, 215.9, None),
    ("A3_Portrait_blank.svg", 297.0, 420.0, _OWN_TEMPLATES),
    ("Letter_Portrait_blank.svg", 215.9, 279.4, _OWN_TEMPLATES),
    ("Tabloid_Portrait_blank.svg", 279.4, 431.8, _OWN_TEMPLATES),
)
_FIT = 1e-6  # mm: a paper this much larger than a template still fits it
# Labels give the cap height; TechDraw's TextSize is the font size (osifont's capitals: ~0.7 em).
_CAP_HEIGHT_PER_EM = 0.7
# TechDraw cosmetic line styles: 1 continuous, 2 dash, 3 dot, 4 dash-dot, 5 dash-dot-dot.
LINE_STYLES = range(1, 6)
_REMOVED_NAMES = set()  # (document, object name) removed during a recompute: never reused


def template_for(width, height):
    """(template path, scale) of the page for a paper of width x height mm."""
    resources = FreeCAD.getResourceDir() + _TECHDRAW_TEMPLATES
    candidates = [
        (os.path.join(folder or resources, name), w, h) for name, w, h, folder in TEMPLATES
    ]
    holding = [c for c in candidates if width <= c[1] + _FIT and height <= c[2] + _FIT]
    if holding:
        return min(holding, key=lambda c: c[1] * c[2])[0], 1.0
    path, w, h = max(candidates, key=lambda c: min(c[1] / width, c[2] / height))
    return path, min(w / width, h / height)


def pages_of(owner):
    """The pages drawn for `owner` (a CuttingSheet), by sheet index."""
    pages = [
        o
        for o in owner.Document.Objects
        if o.TypeId == "TechDraw::DrawPage" and getattr(o, "CuttingSheet", None) == owner.Name
    ]
    return sorted(pages, key=lambda page: page.SheetIndex)


def page_objects(page):
    """Everything a page brings: the page, its template, its views and the outline it draws."""
    views = list(page.Views)
    outlines = [s for v in views if v.TypeId == "TechDraw::DrawViewPart" for s in v.Source]
    return [page] + ([page.Template] if page.Template else []) + views + outlines


def update_pages(owner, sheet_set, mountain_style=4, valley_style=2, not_valid=None):
    """Makes `owner`'s pages show `sheet_set`: one per sheet, reused when they exist; pages of
    sheets beyond the sheet count are removed. `not_valid` (a not_valid_stamp.NotValid) puts its
    stamp on every page, as an annotation like the labels."""
    count = len(sheet_set["sheets"])
    by_index = {}
    for page in pages_of(owner):
        if page.SheetIndex < count and page.SheetIndex not in by_index:
            by_index[page.SheetIndex] = page
        else:
            remove_page(page)
    paper = sheet_set["paper"]
    template, scale = template_for(paper["width"], paper["height"])
    styles = {"mountain": mountain_style, "valley": valley_style}
    extra_labels = []
    if not_valid is not None:
        margin = sheet_set["options"]["margin"]
        stamp = stamp_label(paper["width"], paper["height"], margin, not_valid)
        extra_labels.append(dataclasses.asdict(stamp))  # the sheet set's label keys
    for index in range(count):
        page = by_index.get(index) or _new_page(owner, index, template)
        page.Label = f"{owner.Label} sheet {index + 1}"
        _draw_sheet(page, sheet_set, index, template, scale, styles, extra_labels)


def remove_pages(owner):
    """Removes every page of `owner` with what it brought."""
    for page in pages_of(owner):
        remove_page(page)


def remove_page(page):
    doc = page.Document
    for name in [o.Name for o in page_objects(page)]:
        _remove_object(doc, name)  # the page first: TechDraw then drops its views itself


def _remove_object(doc, name):
    if doc.Recomputing:
        _REMOVED_NAMES.add((doc.Name, name))
    if doc.getObject(name) is not None:
        doc.removeObject(name)


def _add_object(doc, type_id, name):
    """doc.addObject, under a name this module never removed during a recompute."""
    candidate, number = name, 0
    while (doc.Name, candidate) in _REMOVED_NAMES or doc.getObject(candidate) is not None:
        number += 1
        candidate = f"{name}{number:03d}"
    return doc.addObject(type_id, candidate)


def _new_page(owner, index, template_path):
    doc = owner.Document
    template = _add_object(doc, "TechDraw::DrawSVGTemplate", f"{owner.Name}Template")
    page = _add_object(doc, "TechDraw::DrawPage", f"{owner.Name}Page")
    page.addProperty(
        "App::PropertyString", "CuttingSheet", "PopUp", "Name of the CuttingSheet drawing this page"
    )
    page.addProperty(
        "App::PropertyInteger", "SheetIndex", "PopUp", "The sheet this page shows (0 = first)"
    )
    page.CuttingSheet = owner.Name
    page.SheetIndex = index
    for name in ("CuttingSheet", "SheetIndex"):
        page.setEditorMode(name, 1)
    page.KeepUpdated = True
    template.Template = template_path
    page.Template = template  # before addView, which fails on a page without template
    outline = _add_object(doc, "Part::Feature", f"{owner.Name}Outline")
    outline.Visibility = False
    view = _add_object(doc, "TechDraw::DrawViewPart", f"{owner.Name}View")
    page.addView(view)
    view.Source = [outline]
    view.Direction = FreeCAD.Vector(0, 0, 1)
    view.XDirection = FreeCAD.Vector(1, 0, 0)
    view.ScaleType = "Custom"
    view.CoarseView = True  # exact hidden-line removal grows quadratically with the faces
    view.LockPosition = True  # the page is the sheet: a moved view no longer matches it
    return page


def _draw_sheet(page, sheet_set, index, template, scale, styles, extra_labels=()):
    label = page.Label
    if page.Template.Template != template:
        page.Template.Template = template
    page.Template.Label = f"{label} template"
    view = next(v for v in page.Views if v.TypeId == "TechDraw::DrawViewPart")
    outline = view.Source[0]
    outline.Shape = cut_outline(sheet_set, index)
    outline.Label = f"{label} outline"
    view.Label = f"{label} view"
    centre = outline.Shape.BoundBox.Center  # TechDraw centres a view on its shape's box
    view.Scale = scale
    view.X, view.Y = centre.x * scale, centre.y * scale
    _recompute(outline, view)  # makeCosmeticLine3D ends the process on a view without geometry
    _draw_folds(view, sheet_pieces(sheet_set, index), styles)
    labels = [label for piece in sheet_pieces(sheet_set, index) for label in piece["labels"]]
    _draw_labels(page, labels + list(extra_labels), scale)
    _recompute(view, page.Template, page)


def _recompute(*objects):
    """Recomputes objects changed during the CuttingSheet's own recompute. Those made in it are
    not in the document's recompute order and would stay Touched: they are up to date now."""
    for obj in objects:
        obj.recompute()
        obj.purgeTouched()


def _draw_folds(view, pieces, styles):
    style = SheetStyle()
    view.clearCosmeticEdges()
    for piece in pieces:
        for fold in piece["folds"]:
            layer = style.fold(fold["direction"])
            view.makeCosmeticLine3D(
                FreeCAD.Vector(fold["from"][0], fold["from"][1], 0.0),
                FreeCAD.Vector(fold["to"][0], fold["to"][1], 0.0),
                styles[fold["direction"]],
                layer.line_width,
                layer.unit_colour(),
            )


def _draw_labels(page, labels, scale):
    doc = page.Document
    colour = SheetStyle().label.unit_colour()
    annotations = [v for v in page.Views if v.TypeId == "TechDraw::DrawViewAnnotation"]
    for extra in annotations[len(labels) :]:
        page.removeView(extra)  # now, not when the removal happens at the recompute's end
        _remove_object(doc, extra.Name)
    for number, label in enumerate(labels):
        if number < len(annotations):
            annotation = annotations[number]
        else:
            annotation = _add_object(doc, "TechDraw::DrawViewAnnotation", f"{page.Name}Label")
            page.addView(annotation)
            annotation.LockPosition = True
        annotation.Label = f"{page.Label} {label['kind']} {label['text']}"
        annotation.Text = [label["text"]]
        annotation.X = label["position"][0] * scale
        annotation.Y = label["position"][1] * scale
        annotation.TextSize = label["height"] * scale / _CAP_HEIGHT_PER_EM
        annotation.Rotation = label["angle"]
        annotation.TextColor = colour
        _recompute(annotation)
