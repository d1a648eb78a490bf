"""paths.png and motion.gif of `popup animate`, drawn from a card built by hand (a floating layer,
a rotation arm on it, a vertical and a horizontal translation) and a one-bone character whose
motion is known. What is checked comes from geometry, not from the drawing code: closed, the
whole card lies in its page plane x = 0, so its picture seen from +z is a line; open flat it is the
card's rectangle, 2·depth wide and width high; the bone turns from upright to level.
"""

import math
import types

import numpy as np
import pytest

from test_design_from_motion import ARM, LAYER, LIFT, SLIDE, _result

WIDTH, DEPTH = 240.0, 140.0
BONE_MM = 60.0


@pytest.fixture
def scaffold(doc):
    from popupwb.model import card_scaffold
    from popupwb.core import popupcore
    from popupwb.motion.design_from_motion import build_design

    design = build_design(doc, _result(popupcore, [LAYER, ARM, LIFT, SLIDE]))
    built = card_scaffold.for_card(design.card)
    assert not built.errors and not built.card_error
    return built.scaffold


def _character(count):
    """A bone from (100, 20) turning from straight up (frame 0) to level (frame 10)."""
    frames = []
    for k in range(count):
        s = k / (count - 1)
        angle = math.pi / 2 * (1.0 - s)
        root = np.array([100.0, 20.0, 0.0])
        tip = root + BONE_MM * np.array([math.cos(angle), math.sin(angle), 0.0])
        frames.append((10.0 * s, [(root, tip)], None))
    return frames


def _chain():
    s = np.linspace(0.0, 1.0, 11)
    angle = math.pi / 2 * (1.0 - s)
    target = np.c_[100.0 + BONE_MM * np.cos(angle), 20.0 + BONE_MM * np.sin(angle)]
    achieved = target + [1.5, -1.0]
    return types.SimpleNamespace(
        name="Arm",
        mapping="rotation",
        status="animated",
        error=0.012,
        s=s,
        target=target,
        achieved=achieved,
    )


def _ink_box(frame, left, right, header):
    """(x0, y0, x1, y1) of the non-white pixels of columns left..right-1 below the header."""
    pixels = np.asarray(frame.convert("RGB"), dtype=int)[header:, left:right]
    ink = np.argwhere(pixels.min(axis=2) < 250)
    (y0, x0), (y1, x1) = ink.min(axis=0), ink.max(axis=0)
    return x0, y0, x1, y1


def test_the_movie_shows_the_card_opening_beside_the_character(scaffold, tmp_path):
    from PIL import Image

    from popupwb.motion import motion_movie

    count = motion_movie.FRAMES
    path, frames, size = motion_movie.write_movie(
        str(tmp_path / "motion.gif"), scaffold, _character(count), title="test"
    )
    assert (frames, size) == (37, (960, 508))
    with Image.open(path) as gif:
        assert gif.n_frames == 37 and gif.size == (960, 508)
        gif.seek(0)
        closed = gif.copy()
        gif.seek(36)
        opened = gif.copy()
    panel, header = motion_movie.PANEL_PX, motion_movie.HEADER_PX
    # Closed: every patch lies in the page plane x = 0, a line seen from +z (a pixel or two
    # wide for the outlines), as tall as the card's page (its depth) -- up the fold from y = 0.
    x0, y0, x1, y1 = _ink_box(closed, 0, panel, header)
    assert x1 - x0 <= 2
    # Open flat: the card's rectangle, 2·depth across and width along the fold, seen by a
    # camera tilted t from the card's normal: the fold foreshortened by cos t.
    tilt = math.radians(motion_movie.TILT_DEGREES)
    x0, y0, x1, y1 = _ink_box(opened, 0, panel, header)
    assert (x1 - x0) / (y1 - y0) == pytest.approx(2 * DEPTH / (WIDTH * math.cos(tilt)), abs=0.02)
    scale = (x1 - x0) / (2 * DEPTH)  # pixels per mm, the same in both halves
    # The bone: upright at the first frame (foreshortened), level at the last.
    x0, y0, x1, y1 = _ink_box(closed, panel + 2, 2 * panel, header)
    assert x1 - x0 <= 4 and (y1 - y0) == pytest.approx(BONE_MM * math.cos(tilt) * scale, abs=4)
    x0, y0, x1, y1 = _ink_box(opened, panel + 2, 2 * panel, header)
    assert y1 - y0 <= 4 and (x1 - x0) == pytest.approx(BONE_MM * scale, abs=4)


def test_the_movie_is_the_same_file_twice(scaffold, tmp_path):
    from popupwb.motion import motion_movie

    written = []
    for name in ("a.gif", "b.gif"):
        path = str(tmp_path / name)
        motion_movie.write_movie(path, scaffold, _character(9), [_chain()], count=9)
        with open(path, "rb") as f:
            written.append(f.read())
    assert written[0] == written[1]


def test_a_character_of_another_length_is_refused(scaffold, tmp_path):
    from popupwb.motion import motion_movie

    with pytest.raises(ValueError, match="character: 5 frames, must be 9"):
        motion_movie.write_movie(str(tmp_path / "m.gif"), scaffold, _character(5), count=9)


def test_the_paths_plot_is_written_and_deterministic(tmp_path):
    from PIL import Image

    from popupwb.motion.paths_plot import IMAGE_SIZE_PX, write_paths_plot

    paths = []
    for name in ("a.png", "b.png"):
        paths.append(write_paths_plot(str(tmp_path / name), [_chain()], WIDTH, DEPTH, "t"))
    with Image.open(paths[0]) as image:
        assert image.size == IMAGE_SIZE_PX
        pixels = np.asarray(image.convert("RGB"), dtype=int)
    # The chain's colour (the cycle's first, #1f77b4) reached the picture.
    blue = np.all(np.abs(pixels - [0x1F, 0x77, 0xB4]) < 8, axis=2)
    assert blue.sum() > 200
    with open(paths[0], "rb") as a, open(paths[1], "rb") as b:
        assert a.read() == b.read()


def test_the_paths_plot_labels_each_chain_with_its_error_and_reach_floor():
    from popupwb.motion.paths_plot import chain_paths

    chain = _chain()
    assert chain_paths([chain])[0][0] == "Arm: rotation, E = 0.012"  # no floor known: none said
    chain.floor = 0.0071
    assert chain_paths([chain])[0][0] == "Arm: rotation, E = 0.012 (floor 0.007)"
    entry = {
        "name": "Hand",
        "mechanism": "stationary",
        "status": "stationary",
        "error": 0.15,
        "floor": 0.1019,
        "target": [[0, 0]],
        "achieved": [[0, 0]],
    }
    assert chain_paths([entry])[0][0] == "Hand: stationary, E = 0.150 (floor 0.102) [stationary]"


def test_the_character_frames_follow_the_bvh(tmp_path):
    """The right half of the movie: the hand-written BVH's hand is where its channels put it, at
    the movie's fractional frames, mapped by animation_to_card (here a scale and a shift)."""
    import bvh_samples

    from popupwb.core import popupcore
    from popupwb.motion.motion_movie import character_frames

    animation = popupcore.load_animation(bvh_samples.write_bvh(tmp_path / "wave.bvh"))
    matrix = np.diag([2.0, 2.0, 2.0, 1.0])
    matrix[:3, 3] = (10.0, 20.0, 0.0)
    frames = character_frames(animation, matrix, 0, bvh_samples.FRAMES - 1, count=7)
    assert [f for f, _, _ in frames] == pytest.approx([5.0 * k for k in range(7)])
    assert animation.mesh is None  # a BVH has no mesh (animation.hpp)
    for frame, segments, triangles in frames:
        assert triangles is None
        assert len(segments) == len(animation.bones) - 1  # one per bone with a parent
        hand = 2.0 * np.array(bvh_samples.hand(frame)) + (10.0, 20.0, 0.0)
        nearest = min(np.linalg.norm(np.asarray(b) - hand) for _, b in segments)
        # assimp keeps keys in single precision: ~1e-7 of the figure's 40 units, times 2.
        assert nearest < 1e-4, frame
