"""A popupcore.FitResult as FreeCAD features: a PopUpCard of the fitted size, one mechanism feature
per FittedMechanism made with popupwb.make (the same make_* a maker's commands call, so a fitted
design is edited like a hand-made one), and the source model on the card.

FittedMechanism.parameters are the core params struct's field names in mm and radians (bools as
0/1); the features' Parameter.field names the same fields, and their angle properties are degrees.
A mechanism's host is "central fold" (the card) or "<name>.<part>" of a mechanism made before it;
each feature's Name and Label are the mechanism's name, so its HostPair is the same string. A name
already taken in the document gets FreeCAD's next free one, and the host pairs follow the Label.
"""

import collections
import math

from popupwb import card_scaffold
from popupwb.mechanism_registry import by_core_kind

# The card carries the link to the model it was fitted to, and the matrix that put it there.
SOURCE_GROUP = "Source model"

FittedDesign = collections.namedtuple("FittedDesign", "card mechanisms source_model")


def property_values(feature, parameters, mechanism_name):
    """{property name: value} of `feature` from a FittedMechanism's `parameters` (field -> float,
    mm and radians); a field the feature does not have is a ValueError naming it."""
    by_field = {p.field: p for p in feature.PARAMETERS}
    unknown = sorted(set(parameters) - set(by_field))
    if unknown:
        raise ValueError(
            f"{mechanism_name}: parameter(s) {unknown} are not fields of {feature.__name__} "
            f"(known: {sorted(by_field)})"
        )
    values = {}
    for field, value in parameters.items():
        parameter = by_field[field]
        if parameter.kind == "angle":
            values[parameter.name] = math.degrees(value)
        elif parameter.kind == "bool":
            values[parameter.name] = bool(round(value))
        elif parameter.kind == "integer":
            values[parameter.name] = int(round(value))
        else:
            values[parameter.name] = float(value)
    return values


def _host_of(fitted, card, made):
    """(host object, host pair name) of a FittedMechanism: the card for the central fold, else
    the mechanism made earlier under the name before the dot."""
    if fitted.host == card_scaffold.CENTRAL_FOLD:
        return card, card_scaffold.CENTRAL_FOLD
    name, dot, part = fitted.host.rpartition(".")
    if not dot or name not in made:
        raise ValueError(
            f"{fitted.name}: host '{fitted.host}' is neither '{card_scaffold.CENTRAL_FOLD}' nor "
            f"a part of a mechanism made before it ({', '.join(made) or 'none yet'})"
        )
    host = made[name]
    return host, f"{host.Label}.{part}"


def _link_source(card, source_model, model_to_card, source_file):
    import FreeCAD

    have = set(card.PropertiesList)
    if "SourceFile" not in have:
        card.addProperty(
            "App::PropertyString",
            "SourceFile",
            SOURCE_GROUP,
            "The model file the card was designed from (its colours and texture print as "
            "artwork on the cutting sheets while it is there)",
        )
    if "SourceModel" not in have:
        card.addProperty(
            "App::PropertyLink",
            "SourceModel",
            SOURCE_GROUP,
            "The 3D model this card was designed from, placed in the card's frame",
        )
    if "ModelToCard" not in have:
        card.addProperty(
            "App::PropertyMatrix",
            "ModelToCard",
            SOURCE_GROUP,
            "Matrix taking the model file's coordinates to the card's frame (mm)",
        )
        card.setEditorMode("ModelToCard", 1)
    card.SourceModel = source_model
    card.SourceFile = source_file or ""
    card.ModelToCard = FreeCAD.Matrix(*[float(v) for v in model_to_card.reshape(-1)])


def _store_profiles(result, made):
    """Each outline the core fitted (§5.1.3, FitResult.profiles) goes on its feature, so the
    card rebuilds the same profiled patches (validity and sheets use them)."""
    from popupwb.profiles import set_profile

    for fitted in getattr(result, "profiles", ()):
        obj = made.get(fitted.mechanism)
        if obj is None:
            raise ValueError(
                f"profile of {fitted.mechanism}.{fitted.part}: no mechanism {fitted.mechanism}"
            )
        set_profile(
            obj,
            fitted.part,
            [tuple(q) for q in fitted.outer],
            [[tuple(q) for q in hole] for hole in fitted.holes],
            reference=tuple(fitted.reference),
        )


def build_design(doc, result, model=None, name="Card", source_file=None):
    """Adds the card, its mechanisms and (given the ModelMesh `model`) the source model to `doc`
    from `result` (a popupcore.FitResult); recomputes; returns a FittedDesign. `source_file` is
    the model file, kept on the card for the artwork. The caller checks validity
    (popupwb.validity.run_check(card))."""
    from popupwb import make
    from popupwb.fitting.model_source import add_source_model

    card = make.make_card(
        doc, width=float(result.card.width), depth=float(result.card.depth), name=name
    )
    if hasattr(result.card, "paper_thickness"):
        card.PaperThickness = float(result.card.paper_thickness)
    made = collections.OrderedDict()
    for fitted in result.mechanisms:
        mechanism = by_core_kind(fitted.type)
        if mechanism is None:
            raise ValueError(f"{fitted.name}: mechanism type '{fitted.type}' has no feature")
        host, host_pair = _host_of(fitted, card, made)
        values = property_values(mechanism.feature, dict(fitted.parameters), fitted.name)
        obj = make.make_mechanism(mechanism.feature, host, host_pair, name=fitted.name, **values)
        made[fitted.name] = obj
    _store_profiles(result, made)
    source_model = None
    if model is not None:
        model_to_card = _matrix(result.model_to_card)
        source_model = add_source_model(doc, model, model_to_card, card.Placement)
        _link_source(card, source_model, model_to_card, source_file)
    doc.recompute()
    return FittedDesign(card, list(made.values()), source_model)


def _matrix(value):
    import numpy as np

    matrix = np.asarray(value, dtype=float)
    if matrix.shape != (4, 4) or not np.all(np.isfinite(matrix)):
        raise ValueError(f"model_to_card: must be a finite 4x4 matrix, got shape {matrix.shape}")
    return matrix
