"""The stages of an animated pop-up, shared by `popup animate` (cli/animate.py) and the
PopUp_FromAnimation command: read the animation, set the options, design (popupcore.design_motion,
with progress and Cancel), then the FreeCAD card, its check, the plot and the movie.

Stage timing is fitting.fit_run.Stages. Bad input is ValueError (popupcore.DesignError is one)
naming the file or the option, the value and the allowed range.
"""

import math
import os
import threading

from popupwb.fitting.fit_run import Stages, card_size_for_paper, direction  # noqa: F401

TRAJECTORY_SUFFIX = ".json"  # the plain JSON of named trajectories (docs/ANIMATION_INPUT.md)
DEFAULT_ITERATIONS = 4000
MAX_ITERATIONS = 10_000_000
MAX_SEED = 2**63 - 1
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


def _finite(value, name, low=None, high=None, low_open=False):
    value = float(value)
    ok = math.isfinite(value)
    if ok and low is not None:
        ok = value > low if low_open else value >= low
    if ok and high is not None:
        ok = value <= high
    if not ok:
        if low is not None and high is not None:
            span = f"from {low:g} to {high:g}"
        elif low is not None:
            span = f"{'>' if low_open else '>='} {low:g}"
        else:
            span = "finite"
        raise ValueError(f"{name} = {value:g}, must be {span}")
    return value


def motion_options(
    seed=1,
    iterations=DEFAULT_ITERATIONS,
    first_frame=None,
    last_frame=None,
    view=None,
    up=None,
    scale=None,
    card_size=None,
    prune_fraction=None,
    motion_weight=None,
    depth_weight=None,
):
    """A popupcore.MotionOptions; ValueError naming the option for a value out of range. None
    keeps the core's default."""
    from popupwb.core import popupcore

    if not 0 <= int(seed) <= MAX_SEED:
        raise ValueError(f"seed = {seed}, must be 0 to {MAX_SEED}")
    if not 1 <= int(iterations) <= MAX_ITERATIONS:
        raise ValueError(f"iterations = {iterations}, must be 1 to {MAX_ITERATIONS}")
    options = popupcore.MotionOptions()
    options.seed = int(seed)
    options.iterations = int(iterations)
    motion_view = options.view
    if first_frame is not None:
        if int(first_frame) < 0:
            raise ValueError(f"first frame = {first_frame}, must be >= 0")
        motion_view.first_frame = int(first_frame)
    if last_frame is not None:
        if int(last_frame) < -1:
            raise ValueError(f"last frame = {last_frame}, must be >= 0 (or -1: the last)")
        motion_view.last_frame = int(last_frame)
    if view is not None:
        motion_view.view = tuple(view)
    if up is not None:
        motion_view.up = tuple(up)
    if scale is not None:
        motion_view.scale = _finite(scale, "scale", 0.0, low_open=True)
    if card_size is not None:
        motion_view.card_width, motion_view.card_depth = (float(v) for v in card_size)
    options.view = motion_view
    if prune_fraction is not None:
        chains = options.chains
        chains.prune_fraction = _finite(prune_fraction, "pruning fraction", 0.0, 1.0)
        options.chains = chains
    if motion_weight is not None:
        options.motion_weight = _finite(motion_weight, "motion weight", 0.0)
    if depth_weight is not None:
        options.depth_weight = _finite(depth_weight, "depth weight", 0.0)
    return options


def _plain(value):
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    try:
        return [float(v) for v in value]
    except TypeError:
        return str(value)


def options_dict(options):
    """The MotionOptions as plain JSON values (for the report)."""
    names = (
        "motion_weight",
        "depth_weight",
        "collision_weight",
        "iterations",
        "search_chains",
        "layer_height_max",
        "seed",
        "outlines",
    )
    view_names = (
        "view",
        "up",
        "scale",
        "centre",
        "margin",
        "card_width",
        "card_depth",
        "first_frame",
        "last_frame",
        "angle_tolerance",
    )
    values = {name: _plain(getattr(options, name, None)) for name in names}
    values["view"] = {name: _plain(getattr(options.view, name, None)) for name in view_names}
    values["chains"] = {"prune_fraction": _plain(options.chains.prune_fraction)}
    return values


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
