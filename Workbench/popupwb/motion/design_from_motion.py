"""A popupcore.MotionResult as FreeCAD features: the card and its motion-mechanism features as
popupwb.make.designed_card builds them (shared with the shape designs of popup fit), each mechanism
marked with the chain it moves, and the card linked to its animation: the file's path, the frame
range and the matrix from the file's units to the card, and, for a skinned character, a Mesh
feature of the character posed at the last frame (the open card's pose, thesis §6.4) in the
card's frame. That mesh is the card's SourceModel, so the cutting sheets print it as artwork as
they print a fitted model.

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


def posed_mesh_in_card(animation, frame, animation_to_card):
    """The skinned mesh of `animation` at `frame`, in the card's frame (mm), or None without a
    mesh (BVH, trajectories)."""
    from popupwb.core import popupcore
    from popupwb.model.model_source import in_card_frame

    if animation is None or animation.mesh is None:
        return None
    mesh = popupcore.posed_mesh(animation, float(frame))
    if len(mesh.triangles) == 0:
        return None
    return in_card_frame(mesh, animation_to_card)


def build_design(doc, result, animation=None, source_file=None, name="Card"):
    """Adds the card and its mechanisms of `result` (a popupcore.MotionResult, or anything with
    its card, mechanisms, profiles, chains and targets) to `doc`, linked to `source_file` and,
    given the popupcore.Animation, to its mesh posed at the last frame; recomputes; returns a
    MotionDesign. The caller checks validity (popupwb.validity.run_check(card))."""
    from popupwb.fitting.design_from_fit import link_source
    from popupwb.model.model_source import add_source_model

    targets = result.targets
    matrix = np.asarray(targets.animation_to_card, dtype=float)
    freecad_matrix(matrix, "animation_to_card")  # refuses a bad matrix before adding anything
    card, made = build_card(
        doc, result.card, result.mechanisms, getattr(result, "profiles", ()), name=name
    )
    _mark_chains(getattr(result, "chains", ()), made)
    _link_animation(card, source_file, matrix, targets.first_frame, targets.last_frame)
    posed = None
    mesh = posed_mesh_in_card(animation, targets.last_frame, matrix)
    if mesh is not None:
        posed = add_source_model(doc, mesh, np.eye(4), card.Placement, name="PosedCharacter")
        posed.Label = f"PosedCharacter (frame {targets.last_frame})"
        # Already in the card's frame: the card's artwork reads it as it is (no file to reload,
        # the animation's bind pose is not the pose the card shows).
        link_source(card, posed, np.eye(4), "")
    doc.recompute()
    return MotionDesign(card, list(made.values()), posed)
