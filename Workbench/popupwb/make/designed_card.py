"""A design the core describes as a card and a list of mechanisms (popupcore.FittedMechanism and
FittedProfile: the shape of popupcore.fit_design's FitResult and design_motion's MotionResult)
turned into FreeCAD features: a PopUpCard of the design's size, one mechanism feature per
FittedMechanism made with popupwb.make (the same make_* a maker's commands call, so a designed
card is edited like a hand-made one), and each fitted outline on its feature.

FittedMechanism.parameters are the core catalogue's fields of its kind in mm and radians (flags as
0/1); the features' Parameter.field names the same fields, and their angle properties are degrees.
A mechanism's host is "central fold" (the card) or "<name>.<part>" of a mechanism made before it;
each feature's Name and Label are the mechanism's name, so its HostPair is the same string. A name
already taken in the document gets FreeCAD's next free one, and the host pairs follow the Label.

Shared by popupwb.fitting.design_from_fit (shape from a model) and popupwb.motion.design_from_motion
(motion from an animation), which add what links the card to its source.
"""

import collections
import math

import numpy as np

from popupwb.model import card_scaffold
from popupwb.mechanism_registry import by_core_kind


def property_values(feature, parameters, mechanism_name):
    """{property name: value} of `feature` from a FittedMechanism's `parameters` (field -> float,
    mm and radians); a field the feature does not have is a ValueError naming it."""
    by_field = {p.field: p for p in feature.PARAMETERS}
    fixed = feature.FIXED_FIELDS
    for field in sorted(set(parameters) & set(fixed)):
        if float(parameters[field]) != fixed[field]:
            raise ValueError(
                f"{mechanism_name}: parameter {field} = {parameters[field]}, a "
                f"{feature.__name__} always has {fixed[field]:g}"
            )
    parameters = {k: v for k, v in parameters.items() if k not in fixed}
    unknown = sorted(set(parameters) - set(by_field))
    if unknown:
        raise ValueError(
            f"{mechanism_name}: parameter(s) {unknown} are not fields of {feature.__name__} "
            f"(known: {sorted(by_field)})"
        )
    values = {}
    for field, value in parameters.items():
        parameter = by_field[field]
        if not math.isfinite(float(value)):
            raise ValueError(f"{mechanism_name}: parameter {field} = {value}, must be finite")
        if parameter.kind == "angle":
            values[parameter.name] = math.degrees(value)
        elif parameter.kind == "bool":
            values[parameter.name] = bool(round(value))
        elif parameter.kind == "integer":
            values[parameter.name] = int(round(value))
        else:
            values[parameter.name] = float(value)
    return values


def host_of(fitted, card, made):
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


def store_profiles(profiles, made):
    """Each outline the core fitted (FittedProfile) goes on its feature, so the card rebuilds the
    same profiled patches (validity and sheets use them)."""
    from popupwb.profiles.editing import set_profile

    for fitted in profiles:
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


def build_card(doc, card_params, mechanisms, profiles=(), name="Card"):
    """Adds to `doc` a PopUpCard of `card_params` (popupcore.CardParams: width, depth and, when
    it has one, paper_thickness), one feature per FittedMechanism in `mechanisms` (hosts before
    what they carry) and the `profiles`; returns (card, {mechanism name: feature}). The caller
    recomputes."""
    from popupwb import make

    card = make.make_card(
        doc, width=float(card_params.width), depth=float(card_params.depth), name=name
    )
    if hasattr(card_params, "paper_thickness"):
        card.PaperThickness = float(card_params.paper_thickness)
    made = collections.OrderedDict()
    for fitted in mechanisms:
        if fitted.name in made:
            raise ValueError(f"{fitted.name}: two mechanisms have this name")
        mechanism = by_core_kind(fitted.kind)
        if mechanism is None:
            raise ValueError(f"{fitted.name}: mechanism kind '{fitted.kind}' has no feature")
        host, host_pair = host_of(fitted, card, made)
        values = property_values(mechanism.feature, dict(fitted.parameters), fitted.name)
        made[fitted.name] = make.make_mechanism(
            mechanism.feature, host, host_pair, name=fitted.name, **values
        )
    store_profiles(profiles, made)
    return card, made


def add_property(obj, kind, name, group, tip, read_only=False):
    """obj.<name> as an App::Property<kind> unless it has one already."""
    if name not in obj.PropertiesList:
        obj.addProperty(f"App::Property{kind}", name, group, tip)
        if read_only:
            obj.setEditorMode(name, 1)


def freecad_matrix(value, what):
    """A FreeCAD.Matrix of a finite 4x4 array; ValueError naming `what` otherwise."""
    import FreeCAD

    matrix = np.asarray(value, dtype=float)
    if matrix.shape != (4, 4) or not np.all(np.isfinite(matrix)):
        raise ValueError(f"{what}: must be a finite 4x4 matrix, got shape {matrix.shape}")
    return FreeCAD.Matrix(*[float(v) for v in matrix.reshape(-1)])
