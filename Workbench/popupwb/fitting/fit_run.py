"""The stages of a design from a model, in order and timed, shared by `popup fit` (cli/fit.py) and
the PopUp_FromModel command: read, clean, fit (popupcore), build the card's features, check,
measure.

Each stage is one function; Stages records (stage, seconds) and says what it starts through a
`say(text)` callable (stderr for the CLI, the report view in the GUI). Bad input is ValueError
(popupcore.DesignError is one) naming the file and what is wrong.
"""

import concurrent.futures
import contextlib
import math
import os
import time

import numpy as np

from popupwb import option_fields

# Detail level 0 (coarse) .. 1 (fine) sets the smallest primitive (FitOptions.min_shape), as a
# fraction of the model's diagonal: 0.08 .. 0.02, the core's default 0.05 at 0.5.
COARSEST_SHAPE = 0.08
FINEST_SHAPE = 0.02
DEFAULT_DETAIL = 0.5
# The card fits on the paper with the cutting sheet's margin and this much more on each side.
CARD_CLEARANCE_MM = 2.0


class Stages:
    """(stage, seconds) of every stage run, in order; `say` hears what each starts."""

    def __init__(self, say=None):
        self.timings = []
        self.say = say or (lambda text: None)
        self.started = time.perf_counter()

    @contextlib.contextmanager
    def stage(self, name, text):
        self.say(text)
        start = time.perf_counter()
        try:
            yield
        finally:
            self.timings.append((name, time.perf_counter() - start))

    def background(self, name, text, work):
        """work() started on its own thread now, timed as `name` from its start to its end;
        returns a function that waits for its result (or raises what it raised). For a core
        call that releases the GIL (fit_metrics), so what follows overlaps it."""
        self.say(text)
        start = time.perf_counter()
        timed = []

        def timed_work():
            try:
                return work()
            finally:
                timed.append((name, time.perf_counter() - start))

        pool = concurrent.futures.ThreadPoolExecutor(max_workers=1)
        future = pool.submit(timed_work)
        pool.shutdown(wait=False)

        def result():
            try:
                return future.result()
            finally:
                self.timings.extend(timed)
                timed.clear()

        return result

    def add(self, timings):
        """Adds stages timed elsewhere (FitResult.timings: [(stage, seconds)])."""
        self.timings.extend((str(name), float(seconds)) for name, seconds in timings)

    def total(self):
        return time.perf_counter() - self.started


def read_model(path):
    """(popupcore.ModelMesh, what was read) of a model file or an .FCStd's meshes and shapes."""
    from popupwb.model import model_file, model_source

    if path.lower().endswith(".fcstd"):
        model, labels = model_source.model_of_document(path)
        return model, f"{', '.join(labels)} of {os.path.basename(path)}"
    model = model_file.load_model(path)  # kept for the sheets' artwork, which reads it again
    return model, os.path.basename(path)


def clean_model(model):
    """(cleaned ModelMesh, {repair: count}) through popupcore.clean_model."""
    from popupwb.core import popupcore

    cleaned, repairs = popupcore.clean_model(model)
    # Counts stay ints; a flag such as "closed" stays a bool.
    return cleaned, {str(k): v if isinstance(v, bool) else int(v) for k, v in dict(repairs).items()}


def min_shape_of_detail(detail):
    if not (math.isfinite(detail) and 0.0 <= detail <= 1.0):
        raise ValueError(f"detail = {detail:g}, must be from 0 (coarse) to 1 (fine)")
    return COARSEST_SHAPE + (FINEST_SHAPE - COARSEST_SHAPE) * detail


def card_size_for_paper(paper):
    """(width along the fold, depth of each page) in mm of the largest card that, open flat, fits
    on `paper` (a name or WxH) inside the cutting sheet's margin."""
    from popupwb.core import popupcore

    _, width, height = popupcore.paper_size(paper)
    margin = popupcore.SheetOptions().margin + CARD_CLEARANCE_MM
    short, long_ = sorted((float(width), float(height)))
    return short - 2 * margin, 0.5 * (long_ - 2 * margin)


def direction(text, flag):
    """A 3-vector from "X,Y,Z"; ValueError naming `flag` for anything else or a zero vector."""
    parts = [p.strip() for p in str(text).split(",")]
    try:
        values = [float(p) for p in parts]
    except ValueError:
        values = []
    if len(values) != 3 or not all(math.isfinite(v) for v in values):
        raise ValueError(f"{flag} {text}: must be three finite numbers X,Y,Z (e.g. 0,0,1)")
    if math.sqrt(sum(v * v for v in values)) < 1e-12:
        raise ValueError(f"{flag} {text}: must not be the zero vector")
    return tuple(values)


def fit_options(
    max_mechanisms=None,
    seed=None,
    up=None,
    facing=None,
    detail=DEFAULT_DETAIL,
    card_size=None,
    min_part_mm=None,
    depth_layers=None,
    flags=None,
):
    """A popupcore.FitOptions; None keeps the core's default. ValueError naming the option and
    its range (the core's check; `flags` as option_fields.raise_if_bad's)."""
    from popupwb.core import popupcore

    options = popupcore.FitOptions()
    width, depth = card_size if card_size is not None else (None, None)
    values = dict(max_mechanisms=max_mechanisms, seed=seed, card_width=width, card_depth=depth)
    values.update(min_shape=min_shape_of_detail(float(detail)), up=up, facing=facing)
    values.update(min_part_mm=min_part_mm, depth_layers=depth_layers)
    option_fields.set_options(options, option_fields.fields("FitOptions"), values)
    return option_fields.raise_if_bad(options, flags)


def options_dict(options):
    """The FitOptions as plain JSON values (for the report), every field of the core's table."""
    return option_fields.as_dict(options, option_fields.fields("FitOptions"))


def fit(model, options, cancel=None):
    """popupcore.fit_design (GIL released; `cancel` a popupcore.CancelFlag or None)."""
    from popupwb.core import popupcore

    return popupcore.fit_design(model, options, cancel)


def uniform_scale(matrix):
    """The scale of a similarity 4x4 `matrix` (cube root of |det| of its 3x3 block)."""
    return abs(float(np.linalg.det(np.asarray(matrix, dtype=float)[:3, :3]))) ** (1.0 / 3.0)


def standing_model(model, result):
    """The model the pop-up shows: without the plate it stands on when the fit found one (its top
    became the card's page, docs/MATH.md), else the model itself."""
    from popupwb.core import popupcore

    plate = getattr(result, "plate", None)
    return model if plate is None else popupcore.above_plate(model, plate)


def measure(model, result, scaffold, options):
    """popupcore.fit_metrics of the delivered pop-up (`scaffold`, the card's at 180°) against the
    model, with the fit's own threshold in mm."""
    from popupwb.core import popupcore

    matrix = np.asarray(result.model_to_card, dtype=float)
    diagonal_mm = float(model.diagonal()) * uniform_scale(matrix)
    prisms = [np.asarray(p.corners, dtype=float).reshape(-1, 3) for p in result.primitives]
    return popupcore.fit_metrics(
        model, matrix, scaffold, prisms, float(options.threshold) * diagonal_mm
    )
