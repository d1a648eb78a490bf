"""The stages of an animated pop-up, shared by `popup animate` (cli/animate.py) and the
PopUp_FromAnimation command: read the animation, set the options, design (popupcore.design_motion,
with progress and Cancel), then the FreeCAD card, its check, the plot and the movie.

Stage timing is fitting.fit_run.Stages. Bad input is ValueError (popupcore.DesignError is one)
naming the file or the option, the value and the allowed range.
"""

import collections
import os
import threading

from popupwb import option_fields
from popupwb.fitting.fit_run import Stages, card_size_for_paper, direction  # noqa: F401

TRAJECTORY_SUFFIX = ".json"  # the plain JSON of named trajectories (docs/ANIMATION_INPUT.md)
# The core anneals 0 iterations too (the start layout as it is, which its tests use); a maker's
# run, from the command line or the panel, anneals at least once.
MIN_ITERATIONS = 1
PROGRESS_POLL_S = 0.1


def read_animation(path):
    """(popupcore.Animation, what was read): a trajectory JSON through load_trajectories, any
    other file through load_animation (assimp, in a child process)."""
    from popupwb.core import popupcore

    if path.lower().endswith(TRAJECTORY_SUFFIX):
        animation = popupcore.load_trajectories(path)
    else:
        animation = popupcore.load_animation(path)
    bones = len(animation.bones)
    mesh = animation.mesh
    skin = f", a mesh of {len(mesh.vertices)} vertices" if mesh is not None else ""
    return animation, f"{os.path.basename(path)}: {bones} bones, {animation.frames} frames{skin}"


def motion_options(
    seed=None,
    iterations=None,
    first_frame=None,
    last_frame=None,
    view=None,
    up=None,
    scale=None,
    card_size=None,
    prune_fraction=None,
    motion_weight=None,
    depth_weight=None,
    keep_travel=None,
    auto_frames=None,
    animate_only=None,
    flags=None,
):
    """A popupcore.MotionOptions; None keeps the core's default. ValueError naming the option
    and its range (the core's check; `flags` as option_fields.raise_if_bad's). `animate_only`:
    the names of the chains to animate (the others held still); None or [] animates all."""
    from popupwb.core import popupcore

    options = popupcore.MotionOptions()
    width, depth = card_size if card_size is not None else (None, None)
    values = dict(seed=seed, iterations=iterations, first_frame=first_frame, last_frame=last_frame)
    values.update(view=view, up=up, scale=scale, card_width=width, card_depth=depth)
    values.update(
        prune_fraction=prune_fraction, motion_weight=motion_weight, depth_weight=depth_weight
    )
    values.update(keep_travel=keep_travel, auto_frames=auto_frames)
    values.update(animate_only=list(animate_only) if animate_only else None)
    option_fields.set_options(options, option_fields.fields("MotionOptions"), values)
    return option_fields.raise_if_bad(options, flags)


# One chain as `popup animate --list-chains` and the From-animation panel show it: its name (the
# report's), its bones, its reach on the card (mm) and whether its path moves on the card.
ChainFound = collections.namedtuple("ChainFound", "name bones reach_mm moving")


def chains_found(animation, options):
    """[ChainFound] of the chains design_motion maps with `options` (its view, frames and chain
    options), in the report's order. ValueError (DesignError) names a bad view option."""
    from popupwb.core import popupcore

    targets = popupcore.motion_targets(animation, options.view, options.chains)
    # animation_to_card scales uniformly: a column's length is the file unit in card mm.
    scale = sum(float(targets.animation_to_card[row][0]) ** 2 for row in range(3)) ** 0.5
    return [
        ChainFound(
            chain.name,
            len(chain.bones),
            chain.reach * scale,
            bool(popupcore.path_moves(path, targets.diagonal_mm)),
        )
        for chain, path in zip(targets.chains, targets.paths)
    ]


def chain_line(chain):
    """'Hand.L: 3 bones, reach 52.1 mm, moving' (or 'still')."""
    moving = "moving" if chain.moving else "still"
    return f"{chain.name}: {chain.bones} bones, reach {chain.reach_mm:.1f} mm, {moving}"


def chain_names(text):
    """The names of a comma-separated list ("Hand.L, Foot.R"), blanks dropped."""
    return [name.strip() for name in text.split(",") if name.strip()]


def frames_shown(targets, how_to_choose):
    """A sentence naming the frames the core chose (targets.window, docs/MATH.md "The frame
    window"), `how_to_choose` telling the maker how to name others; "" when they named them."""
    window = dict(getattr(targets, "window", None) or {})
    if not window.get("chosen"):
        return ""
    return (
        f"showing frames {targets.first_frame}-{targets.last_frame}, the stroke a card follows "
        f"best ({how_to_choose} choose others)"
    )


def options_dict(options):
    """The MotionOptions as plain JSON values (for the report): every field of the core's
    table, the view's under "view" and the chains' under "chains"."""
    return option_fields.as_dict(options, option_fields.fields("MotionOptions"))


def design(animation, options, cancel=None, on_progress=None):
    """popupcore.design_motion (GIL released) on a worker thread, calling on_progress(fraction)
    about every PROGRESS_POLL_S from the calling thread while it runs; `cancel` a
    popupcore.CancelFlag or None."""
    from popupwb.core import popupcore

    progress = popupcore.MotionProgress() if hasattr(popupcore, "MotionProgress") else None
    if on_progress is None or progress is None:
        return popupcore.design_motion(animation, options, cancel=cancel, progress=progress)
    outcome = {}

    def work():
        try:
            outcome["result"] = popupcore.design_motion(
                animation, options, cancel=cancel, progress=progress
            )
        except BaseException as error:  # handed back to the caller's thread
            outcome["error"] = error

    worker = threading.Thread(target=work, name="PopUp design_motion", daemon=False)
    worker.start()
    while worker.is_alive():
        worker.join(PROGRESS_POLL_S)
        on_progress(float(progress.value))
    if "error" in outcome:
        raise outcome["error"]
    on_progress(1.0)
    return outcome["result"]
