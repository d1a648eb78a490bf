"""What keeps a CuttingSheet from its layout, found again and selected in the 3D view: the card
when it does not build, a mechanism in error, else the patches (faces of the mechanism or card
showing them) that the validity check or the layout names. Making sheets (the command and the card
panel) and exporting them call it when they fail, so the maker sees which piece to fix.

The feature keeps only its one-line message (execute() raises); the faulty patches are found
again here by running the check (then the layout) once more, which costs what a recompute costs
and happens only on failure.
"""

import FreeCAD
import FreeCADGui

from popupwb.model import card_scaffold
from popupwb.validity.report_text import offending_patches


def at_fault(sheet):
    """[(object, [sub-element names])] of what keeps `sheet` (a CuttingSheet) from its layout;
    [] when nothing in the card is at fault (no card linked, an option out of range...)."""
    card = sheet.Card
    if card is None or not card_scaffold.is_card(card):
        return []
    built = card_scaffold.for_card(card)
    if built.card_error:
        return [(card, [])]
    if built.errors:
        doc = card.Document
        return [(doc.getObject(name), []) for name in built.errors if doc.getObject(name)]
    return _faces_of(card, built, _faulty_patches(sheet, built))


def _faulty_patches(sheet, built):
    """Patch ids the validity check names, else those of the layout's errors."""
    from popupwb.core import popupcore
    from popupwb.features.cutting_sheet import layout_options
    from popupwb.sheets import export

    try:
        report = popupcore.check_validity(built.scaffold).to_dict()
    except ValueError:
        return set()
    if not report["valid"]:
        return offending_patches(report)
    try:
        sheet_set = export.layout(built.scaffold, **layout_options(sheet))
    except ValueError as error:  # DesignError: its findings name their patches
        return offending_patches({"diagnostics": getattr(error, "diagnostics", [])})
    errors = [d.to_dict() for d in sheet_set.diagnostics if d.severity == "error"]
    return offending_patches({"diagnostics": errors})


def _faces_of(card, built, patch_ids):
    """The patches as faces of the objects showing them: each mechanism shows its own patches,
    one child shape per patch; the card shows either every patch or its own pages."""
    doc = card.Document
    every = list(range(len(built.scaffold.patches)))
    chosen = []
    for name, owned in built.patches.items():
        wanted = set(owned) & set(patch_ids)
        obj = doc.getObject(name)
        if not wanted or obj is None:
            continue
        children = obj.Shape.childShapes() if not obj.Shape.isNull() else []
        shown = every if name == card.Name and len(children) == len(every) else owned
        if len(children) != len(shown):
            chosen.append((obj, []))  # a shape of another make: the whole object
            continue
        faces, first = [], 1
        for child, patch_id in zip(children, shown):
            count = len(child.Faces)
            if patch_id in wanted:
                faces.extend(f"Face{first + n}" for n in range(count))
            first += count
        chosen.append((obj, faces))
    return chosen


def select_at_fault(sheet):
    """Selects what keeps `sheet` from its layout; returns the selected objects' labels."""
    chosen = at_fault(sheet)
    if not chosen:
        return []
    FreeCADGui.Selection.clearSelection()
    for obj, faces in chosen:
        if faces:
            FreeCADGui.Selection.addSelection(obj, faces)
        else:
            FreeCADGui.Selection.addSelection(obj)
    labels = [obj.Label for obj, _ in chosen]
    FreeCAD.Console.PrintMessage(f"{sheet.Label}: selected {', '.join(labels)}, to fix\n")
    return labels
