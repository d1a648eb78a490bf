"""A popupcore.FitResult as FreeCAD features: the card and its mechanism features as
popupwb.make.designed_card builds them (shared with the motion designs), and the source model on the
card (a Mesh feature in the card's frame, the file it came from and the matrix that put it there).
"""

import collections

import numpy as np

from popupwb.make.designed_card import add_property, build_card, freecad_matrix, property_values

# The card carries the link to the model it was fitted to, and the matrix that put it there.
SOURCE_GROUP = "Source model"

FittedDesign = collections.namedtuple("FittedDesign", "card mechanisms source_model")

__all__ = ["FittedDesign", "SOURCE_GROUP", "build_design", "property_values"]


def link_source(card, source_model, model_to_card, source_file):
    add_property(
        card,
        "String",
        "SourceFile",
        SOURCE_GROUP,
        "The model file the card was designed from (its colours and texture print as "
        "artwork on the cutting sheets while it is there)",
    )
    add_property(
        card,
        "Link",
        "SourceModel",
        SOURCE_GROUP,
        "The 3D model this card was designed from, placed in the card's frame",
    )
    add_property(
        card,
        "Matrix",
        "ModelToCard",
        SOURCE_GROUP,
        "Matrix taking the model file's coordinates to the card's frame (mm)",
        read_only=True,
    )
    card.SourceModel = source_model
    card.SourceFile = source_file or ""
    card.ModelToCard = freecad_matrix(model_to_card, "model_to_card")


def build_design(doc, result, model=None, name="Card", source_file=None):
    """Adds the card, its mechanisms and (given the ModelMesh `model`) the source model to `doc`
    from `result` (a popupcore.FitResult); recomputes; returns a FittedDesign. `source_file` is
    the model file, kept on the card for the artwork. The caller checks validity
    (popupwb.validity.run_check(card))."""
    from popupwb.model.model_source import add_source_model

    card, made = build_card(
        doc, result.card, result.mechanisms, getattr(result, "profiles", ()), name=name
    )
    source_model = None
    if model is not None:
        model_to_card = np.asarray(result.model_to_card, dtype=float)
        freecad_matrix(model_to_card, "model_to_card")  # refuses a bad matrix before adding
        source_model = add_source_model(doc, model, model_to_card, card.Placement)
        link_source(card, source_model, model_to_card, source_file)
    doc.recompute()
    return FittedDesign(card, list(made.values()), source_model)
