"""TechDraw pages of a CuttingSheet: one page per sheet of its sheet set, drawn like the exported
SVG of that sheet, at 1:1.

A sheet's page (TechDraw::DrawPage) holds:
- a template exactly the paper's size (page_template.py): blank where the sheet is, with a line
  legend and a title block (card, paper, sheet n of m, scale 1:1; TechDraw editable texts) in the
  bottom margin band;
- a symbol view (TechDraw::DrawViewSymbol, page_marks.py): the exported SVG's glue areas and labels
  (and a NOT VALID stamp), one object however many labels;
- a view (DrawViewPart looking down z, CoarseView) of the sheet's cut outline (a hidden
  Part::Feature), its edges formatted in the CUT colour, with the fold lines as cosmetic lines in
  the mountain and valley TechDraw line styles and the MOUNTAIN and VALLEY colours of
  layer_style.SheetStyle.
Page coordinates are sheet coordinates (origin at the paper's lower-left corner). The production
files are export.py's: TechDraw's own DXF puts every line on one layer, without linetypes or
colours. When its window opens, page_window.py hides the view frames and fits the page.

Generated templates are kept in <user data>/PopUp/templates/, named by a digest of their text; the
document keeps its own copy of each (the template's PageResult), so a file opens anywhere.

Pages are found again by two properties of the page, CuttingSheet (the owner's Name, not a link:
a link would leave every new page Touched after the recompute that made it) and SheetIndex; every
update reuses them and removes those of sheets that are gone, or of an older kind (one annotation
per label, before the symbol view).

FreeCAD 0.20 defers removing an object during a recompute to the recompute's end, and then
removes whatever bears that name again at the end of every later recompute: a name removed here
during a recompute is never given to a new object again.
"""

import hashlib
import os

import FreeCAD

from popupwb.sheets.layer_style import SheetStyle
from popupwb.sheets.page_marks import marks_svg
from popupwb.sheets.page_template import TitleBlock, paper_text, template_svg
from popupwb.sheets.sheet_set import paper_size, pieces_by_sheet
from popupwb.sheets.sheet_shapes import cut_outline

# TechDraw cosmetic line styles: 1 continuous, 2 dash, 3 dot, 4 dash-dot, 5 dash-dot-dot.
LINE_STYLES = range(1, 6)
CONTINUOUS = 1
PART_VIEW, SYMBOL_VIEW = "TechDraw::DrawViewPart", "TechDraw::DrawViewSymbol"
_REMOVED_NAMES = set()  # (document, object name) removed during a recompute: never reused


def templates_folder():
    return os.path.join(FreeCAD.getUserAppDataDir(), "PopUp", "templates")


def write_template(svg_text):
    """The path of a template file holding `svg_text` (written once, named by its digest)."""
    folder = templates_folder()
    os.makedirs(folder, exist_ok=True)
    digest = hashlib.sha1(svg_text.encode("utf-8")).hexdigest()[:16]
    path = os.path.join(folder, f"popup_sheet_{digest}.svg")
    if not os.path.isfile(path):
        temporary = f"{path}.{os.getpid()}"
        with open(temporary, "w", encoding="utf-8") as stream:
            stream.write(svg_text)
        os.replace(temporary, path)  # atomic: documents in parallel processes share the folder
    return path


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
    outlines = [s for v in views if v.TypeId == PART_VIEW for s in v.Source]
    return [page] + ([page.Template] if page.Template else []) + views + outlines


def update_pages(owner, sheet_set, mountain_style=4, valley_style=2, not_valid=None):
    """Makes `owner`'s pages show `sheet_set` (a popupcore.SheetSet): one per sheet, reused when
    they exist; pages of sheets beyond the sheet count are removed. `not_valid` (a
    not_valid_stamp.NotValid) puts its stamp on every page, with the labels."""
    count = sheet_set.sheet_count
    by_index = {}
    for page in pages_of(owner):
        if page.SheetIndex < count and page.SheetIndex not in by_index and _current_kind(page):
            by_index[page.SheetIndex] = page
        else:
            remove_page(page)
    styles = {"mountain": mountain_style, "valley": valley_style}
    card = owner.Card.Label if owner.Card is not None else owner.Label
    width, height = paper_size(sheet_set)
    paper = paper_text(sheet_set.options.paper, width, height)
    margin = sheet_set.options.margin
    for index in range(count):
        title = TitleBlock(card, paper, index + 1, count)
        template = write_template(template_svg(width, height, margin, title))
        page = by_index.get(index) or _new_page(owner, index, template)
        page.Label = f"{owner.Label} sheet {index + 1}"
        _draw_sheet(page, sheet_set, index, template, title, styles, not_valid)


def hide_frames(page):
    """No frame or caption around the page's views (GUI only: a view provider property; an open
    window redraws only through TechDraw_ToggleFrame, page_window.py)."""
    if FreeCAD.GuiUp and page.ViewObject is not None:
        if getattr(page.ViewObject, "ShowFrames", False):
            page.ViewObject.ShowFrames = False


def remove_pages(owner):
    """Removes every page of `owner` with what it brought."""
    for page in pages_of(owner):
        remove_page(page)


def remove_page(page):
    """The page's views and outlines first, then its template, then the page: FreeCAD 1.0's
    DrawPage, removed first, reached views it had already dropped and crashed (a legacy
    document's page, replaced during a recompute)."""
    doc = page.Document
    objects = page_objects(page)
    names = [o.Name for o in objects[1:]][::-1] + [page.Name]
    page.Views = []
    for name in names:
        _remove_object(doc, name)


def _current_kind(page):
    """True for a page of this module's current make: one part view and one symbol view."""
    kinds = sorted(v.TypeId for v in page.Views)
    return kinds == [PART_VIEW, SYMBOL_VIEW] and page.Template is not None


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
    page.Scale = 1.0
    template.Template = template_path
    page.Template = template  # before addView, which fails on a page without template
    # The marks first: TechDraw stacks later views on top, and the lines go over the glue areas.
    marks = _add_object(doc, SYMBOL_VIEW, f"{owner.Name}Marks")
    page.addView(marks)
    marks.LockPosition = True
    outline = _add_object(doc, "Part::Feature", f"{owner.Name}Outline")
    outline.Visibility = False
    view = _add_object(doc, PART_VIEW, f"{owner.Name}View")
    page.addView(view)
    view.Source = [outline]
    view.Direction = FreeCAD.Vector(0, 0, 1)
    view.XDirection = FreeCAD.Vector(1, 0, 0)
    view.ScaleType = "Custom"
    view.Scale = 1.0
    view.CoarseView = True  # exact hidden-line removal grows quadratically with the faces
    view.LockPosition = True  # the page is the sheet: a moved view no longer matches it
    return page


def _draw_sheet(page, sheet_set, index, path, title, styles, not_valid):
    label = page.Label
    width, height = paper_size(sheet_set)
    template = page.Template
    if template.Template != path:
        template.Template = path  # resets EditableTexts to the file's (the same values)
    if dict(template.EditableTexts) != title.fields():
        template.EditableTexts = title.fields()
    template.Label = f"{label} template"

    marks = next(v for v in page.Views if v.TypeId == SYMBOL_VIEW)
    marks.Label = f"{label} glue areas and labels"
    marks.Symbol = marks_svg(sheet_set, index, not_valid)
    marks.Scale = 1.0
    marks.X, marks.Y = width / 2.0, height / 2.0  # centred on the paper

    view = next(v for v in page.Views if v.TypeId == PART_VIEW)
    outline = view.Source[0]
    outline.Shape = cut_outline(sheet_set, index)
    outline.Label = f"{label} outline"
    view.Label = f"{label} cuts and folds"
    centre = outline.Shape.BoundBox.Center  # TechDraw centres a view on its shape's box
    view.X, view.Y = centre.x, centre.y
    _recompute(outline, view)  # makeCosmeticLine3D ends the process on a view without geometry
    _format_cuts(view)
    _draw_folds(view, pieces_by_sheet(sheet_set)[index], styles)
    _recompute(marks, view, template, page)


def _recompute(*objects):
    """Recomputes objects changed during the CuttingSheet's own recompute. Those made in it are
    not in the document's recompute order and would stay Touched: they are up to date now."""
    for obj in objects:
        obj.recompute()
        obj.purgeTouched()


def _format_cuts(view):
    """Every edge of the view (the cut outline) in the CUT colour and width."""
    cut = SheetStyle().cut
    # Never read view.GeomFormats back: that corrupts the heap in 0.20 (FREECAD_NOTES.md, trap 8).
    for number in range(len(view.getVisibleEdges())):
        view.formatGeometricEdge(number, CONTINUOUS, cut.line_width, cut.unit_colour(), True)


def _draw_folds(view, pieces, styles):
    style = SheetStyle()
    view.clearCosmeticEdges()
    for piece in pieces:
        for fold in piece.folds:
            layer = style.fold(fold.direction)
            view.makeCosmeticLine3D(
                FreeCAD.Vector(fold.start[0], fold.start[1], 0.0),
                FreeCAD.Vector(fold.end[0], fold.end[1], 0.0),
                styles[fold.direction],
                layer.line_width,
                layer.unit_colour(),
            )
