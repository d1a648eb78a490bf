"""What a command acts on, read from the GUI selection (or the document's only candidate), with a
message saying what to select when nothing fits. Every command that reads the selection asks here.
"""

import FreeCADGui

from popupwb.model import card_scaffold
from popupwb.features.cutting_sheet import is_cutting_sheet
from popupwb.features.scaffold_feature import is_scaffold

HOSTS = "a card or a mechanism offering base patch pairs (box fold, floating layer, v-fold)"


class SelectionError(ValueError):
    """Nothing suitable is selected and the document has no single candidate; the message says
    what to select."""


def selected_objects(doc):
    """The selected objects of `doc`, in selection order ([] without a document)."""
    return list(FreeCADGui.Selection.getSelection(doc.Name)) if doc is not None else []


def _is_popup(obj):
    return card_scaffold.is_card(obj) or card_scaffold.is_mechanism(obj)


def _the_only(doc, candidates, kind, what_to_select):
    """The single candidate, else a SelectionError naming the candidates (or their absence)."""
    if doc is None:
        raise SelectionError("no document is open")
    if len(candidates) == 1:
        return candidates[0]
    if not candidates:
        raise SelectionError(f"select {what_to_select} (the document has no {kind})")
    labels = ", ".join(o.Label for o in candidates)
    raise SelectionError(f"select {what_to_select} (the document has several: {labels})")


def cards_of(doc):
    return [o for o in doc.Objects if card_scaffold.is_card(o)] if doc is not None else []


def selected_card(doc):
    """The card of the first selected card or mechanism, else the document's only card."""
    for obj in selected_objects(doc):
        if _is_popup(obj):
            try:
                return card_scaffold.root_card(obj)
            except ValueError as error:  # a mechanism whose Host chain is broken
                raise SelectionError(str(error)) from error
    return _the_only(doc, cards_of(doc), "card", "a card or one of its mechanisms")


def selected_host(doc):
    """The first selected card or mechanism offering base patch pairs, else the document's only
    card; a selected mechanism that offers none is refused rather than passed over."""
    selected = [o for o in selected_objects(doc) if _is_popup(o)]
    for obj in selected:
        if card_scaffold.host_pair_names(obj):
            return obj
    if selected:
        raise SelectionError(f"{selected[0].Label} offers no base patch pair: select {HOSTS}")
    return _the_only(doc, cards_of(doc), "card", HOSTS)


def selected_cutting_sheet(doc):
    """The first selected CuttingSheet, else the document's only one."""
    for obj in selected_objects(doc):
        if is_cutting_sheet(obj):
            return obj
    sheets = [o for o in doc.Objects if is_cutting_sheet(o)] if doc is not None else []
    return _the_only(doc, sheets, "cutting sheet", "a cutting sheet")


def selected_designs(doc):
    """What a validity check runs on: the selected Scaffolds and cards, a selected mechanism
    standing for its card, each once; every Scaffold and card of the document when none is
    selected."""
    designs = []
    for obj in selected_objects(doc):
        if is_scaffold(obj) or _is_popup(obj):
            try:
                design = obj if is_scaffold(obj) else card_scaffold.root_card(obj)
            except ValueError as error:
                raise SelectionError(str(error)) from error
            if all(design is not other for other in designs):
                designs.append(design)
    if designs:
        return designs
    everything = (
        [o for o in doc.Objects if is_scaffold(o) or card_scaffold.is_card(o)] if doc else []
    )
    if not everything:
        raise SelectionError("select a Scaffold or a card (the document has none)")
    return everything


def selected_model(doc):
    """The first selected Mesh::Feature or Part shape (not a PopUp object), else the document's
    only one: what PopUp_FromModel designs a card from."""
    from popupwb.model.model_source import is_model_object, top_level_models

    for obj in selected_objects(doc):
        if is_model_object(obj):
            return obj
    return _the_only(
        doc,
        top_level_models(doc) if doc is not None else [],
        "mesh or Part shape",
        "a mesh or a Part shape",
    )
