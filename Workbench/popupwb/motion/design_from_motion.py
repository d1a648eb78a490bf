"""A popupcore.MotionResult as FreeCAD features: the card and its motion-mechanism features as
popupwb.make.designed_card builds them (shared with the shape designs of popup fit), each mechanism
marked with the chain it moves, and the card linked to its animation: the file's path, the frame
range and the matrix from the file's units to the card, and, for a skinned character, Mesh
features of the character posed at the last frame (the open card's pose, thesis §6.4) in the
card's frame, split as the card prints it (popupcore.printed_parts, thesis Fig 6.9): the body is
the card's SourceModel, printed on the pages and the parts that stand still, and each limb a
mechanism carries is that mechanism's LimbModel, printed on its moving parts (LimbParts) alone.

Dragging the card's FoldAngle moves the mechanisms as the simulator folds them: the motion.
"""

import collections
import os

import numpy as np

from popupwb.make.designed_card import add_property, build_card, freecad_matrix

ANIMATION_GROUP = "Source animation"
CHAIN_GROUP = "Motion"

MotionDesign = collections.namedtuple("MotionDesign", "card mechanisms posed_mesh")


def _link_animation(card, source_file, animation_to_card, first_frame, last_frame):
    add_property(
        card,
        "String",
        "SourceAnimation",
        ANIMATION_GROUP,
        "The animation file the card's motion was designed from",
    )
    add_property(
        card,
        "Matrix",
        "AnimationToCard",
        ANIMATION_GROUP,
        "Matrix taking the animation file's coordinates to the card's frame (mm)",
        read_only=True,
    )
    add_property(
        card, "Integer", "FirstFrame", ANIMATION_GROUP, "Frame shown closed (fold angle 0)", True
    )
    add_property(
        card, "Integer", "LastFrame", ANIMATION_GROUP, "Frame shown open flat (180 degrees)", True
    )
    card.SourceAnimation = os.path.abspath(source_file) if source_file else ""
    card.AnimationToCard = freecad_matrix(animation_to_card, "animation_to_card")
    card.FirstFrame = int(first_frame)
    card.LastFrame = int(last_frame)


def _mark_chains(chains, made):
    """Each mechanism's Chain property names the chain(s) of the character it moves."""
    moved = collections.defaultdict(list)
    for chain in chains:
        for name in chain.mechanisms:
            moved[name].append(chain.name)
    for name, obj in made.items():
        if name in moved:
            add_property(
                obj, "String", "Chain", CHAIN_GROUP, "The character's chain(s) it moves", True
            )
            obj.Chain = ", ".join(moved[name])


def printed_character(animation, result):
    """popupcore.printed_parts of the character (the body first, then each limb with triangles),
    or [] without a skinned mesh (BVH, trajectories) or a body with no triangle."""
    from popupwb.core import popupcore

    if animation is None or animation.mesh is None:
        return []
    parts = popupcore.printed_parts(animation, result)
    if not parts or not any(len(p.mesh.triangles) for p in parts):
        return []
    return parts[:1] + [p for p in parts[1:] if len(p.mesh.triangles)]


def _add_limb(doc, card, made, limb, frame):
    """The limb's Mesh feature, linked from the mechanism that carries it (LimbModel) with the
    parts it prints on (LimbParts)."""
    from popupwb.model.model_source import add_source_model

    mechanism = made[limb.mechanism]
    mesh = add_source_model(doc, limb.mesh, np.eye(4), card.Placement, name="Limb")
    mesh.Label = f"Limb {', '.join(limb.chains)} (frame {frame})"
    add_property(
        mechanism, "Link", "LimbModel", CHAIN_GROUP, "The limb printed on its moving parts"
    )
    add_property(
        mechanism, "StringList", "LimbParts", CHAIN_GROUP, "Its parts the limb is printed on", True
    )
    mechanism.LimbModel = mesh
    mechanism.LimbParts = list(limb.parts)
    return mesh


def _add_character(doc, card, made, printed, frame):
    """The body as the card's SourceModel and each limb on its mechanism; the body's feature."""
    from popupwb.fitting.design_from_fit import link_source
    from popupwb.model.model_source import add_source_model

    body = add_source_model(doc, printed[0].mesh, np.eye(4), card.Placement, name="PosedCharacter")
    body.Label = f"PosedCharacter (frame {frame})"
    # Already in the card's frame: the card's artwork reads it as it is (no file to reload,
    # the animation's bind pose is not the pose the card shows).
    link_source(card, body, np.eye(4), "")
    for limb in printed[1:]:
        _add_limb(doc, card, made, limb, frame)
    return body


def build_design(doc, result, animation=None, source_file=None, name="Card"):
    """Adds the card and its mechanisms of `result` (a popupcore.MotionResult, or anything with
    its card, mechanisms, profiles, chains and targets) to `doc`, linked to `source_file` and,
    given the popupcore.Animation, to its mesh posed at the last frame (the body, and a limb per
    mechanism that carries one); recomputes; returns a
    MotionDesign. The caller checks validity (popupwb.validity.run_check(card))."""
    targets = result.targets
    matrix = np.asarray(targets.animation_to_card, dtype=float)
    freecad_matrix(matrix, "animation_to_card")  # refuses a bad matrix before adding anything
    card, made = build_card(
        doc, result.card, result.mechanisms, getattr(result, "profiles", ()), name=name
    )
    _mark_chains(getattr(result, "chains", ()), made)
    _link_animation(card, source_file, matrix, targets.first_frame, targets.last_frame)
    printed = printed_character(animation, result)
    posed = _add_character(doc, card, made, printed, targets.last_frame) if printed else None
    doc.recompute()
    return MotionDesign(card, list(made.values()), posed)
