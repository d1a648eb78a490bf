"""paths.png and motion.gif of `popup animate`, drawn from a card built by hand (a floating layer,
a rotation arm on it, a vertical and a horizontal translation) and a one-bone character whose
motion is known. What is checked comes from geometry, not from the drawing code: closed, the
whole card lies in its page plane x = 0, so its picture seen from +z is a line; open flat it is the
card's rectangle, 2·depth wide and width high; the bone turns from upright to level.
"""

import math
import os
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


# The card as it is printed (issue 26 item 5): each patch carries the artwork its sheet prints.
# Where the pictures are checked against, the card's points are taken to pixels by the open
# card's rectangle in the open frame (its ink box), not by the movie's code.


def _frames(path, indices):
    from PIL import Image

    with Image.open(path) as gif:
        out = []
        for k in indices:
            gif.seek(k)
            out.append(np.asarray(gif.convert("RGB"), dtype=int))
    return out


def _card_to_pixels(opened, pages):
    """A function taking card points (N x 3) to the left panel's pixels, read off the open frame:
    its ink box is the open card's rectangle (the pages' outlines) seen by the tilted camera."""
    from PIL import Image

    from popupwb.motion import motion_movie

    x0, y0, x1, y1 = _ink_box(Image.fromarray(opened.astype(np.uint8)), 0, motion_movie.PANEL_PX, 0)
    corners = np.vstack(pages)
    lo, hi = corners.min(axis=0), corners.max(axis=0)
    tilt = math.radians(motion_movie.TILT_DEGREES)
    scale = (x1 - x0) / (hi[0] - lo[0])

    def to_pixels(points):
        p = np.asarray(points, dtype=float).reshape(-1, 3)
        up = p[:, 1] * math.cos(tilt) + p[:, 2] * math.sin(tilt)
        return np.c_[x0 + 0.5 + (p[:, 0] - lo[0]) * scale, y1 + 0.5 - (up - lo[1]) * scale]

    return to_pixels


def _mask(shape, polygons, grow=0):
    """Pixels inside any of the polygons (each K x 2 pixel corners), grown (or, < 0, shrunk) by
    `grow` pixels."""
    from PIL import Image, ImageDraw, ImageFilter

    image = Image.new("L", (shape[1], shape[0]), 0)
    draw = ImageDraw.Draw(image)
    for polygon in polygons:
        draw.polygon([tuple(map(float, p)) for p in polygon], fill=255)
    if grow:
        size = 2 * abs(grow) + 1
        image = image.filter(
            ImageFilter.MaxFilter(size) if grow > 0 else ImageFilter.MinFilter(size)
        )
    return np.asarray(image) > 0


def _red(pixels):
    return (pixels[..., 0] > 150) & (pixels[..., 1] < 90) & (pixels[..., 2] < 90)


def test_a_square_printed_on_a_page_folds_with_it(scaffold, tmp_path):
    """A red square just above the ground page, printed on it, is where the page carries it at
    every fold angle: the page's posed outline (the simulator's) places its corners."""
    from popupwb.core import popupcore
    from popupwb.motion import motion_movie

    ids = [p.id for p in scaffold.patches]
    ground = ids.index(scaffold.ground)
    page = np.asarray(scaffold.patches[ground].outer, dtype=float).reshape(-1, 3)
    lo, hi = page.min(axis=0), page.max(axis=0)
    far = lo[0] + 0.7 * (hi[0] - lo[0])  # away from the fold, where no mechanism stands
    square = np.array(
        [[far, 40.0, 1.0], [far + 30.0, 40.0, 1.0], [far + 30.0, 70.0, 1.0], [far, 70.0, 1.0]]
    )
    mesh = popupcore.ModelMesh(square, np.array([[0, 1, 2], [0, 2, 3]]), source="square")
    mesh.colours = np.tile([1.0, 0.0, 0.0], (4, 1))
    body = types.SimpleNamespace(mechanism="", parts=[], mesh=mesh)
    count = 9
    path, _, _ = motion_movie.write_movie(
        str(tmp_path / "m.gif"), scaffold, _character(count), count=count, printed=[body]
    )
    frames = _frames(path, range(count))
    backdrop = ids.index(scaffold.backdrop)
    pages = [np.asarray(scaffold.patches[i].outer).reshape(-1, 3) for i in (ground, backdrop)]
    to_pixels = _card_to_pixels(frames[-1], pages)
    # The square's corners in the page's frame: the page is a rectangle, its corners posed by
    # the simulator carry any point of it.
    origin, a, b = page[0], page[1] - page[0], page[-1] - page[0]
    local = np.linalg.lstsq(np.c_[a, b], (square - [0, 0, 1.0] - origin).T, rcond=None)[0].T
    angles = np.linspace(math.pi, 0.0, count)[::-1]
    states = list(popupcore.simulate_fold(scaffold, list(angles[::-1])).states)[::-1]
    for k in range(2, count):  # closed and nearly so, the page is seen edge-on
        posed = np.asarray(popupcore.posed_outlines(scaffold, states[k])[ground]).reshape(-1, 3)
        o, pa, pb = posed[0], posed[1] - posed[0], posed[-1] - posed[0]
        corners = to_pixels(o + local[:, :1] * pa + local[:, 1:] * pb)
        panel = frames[k][:, : motion_movie.PANEL_PX]
        red = _red(panel)
        inside = _mask(panel.shape, [corners], -2)
        near = _mask(panel.shape, [corners], 2)
        assert inside.sum() > 100 and red[inside].mean() > 0.95, k
        assert not red[~near].any(), k


@pytest.fixture(scope="module")
def figure_movie(tmp_path_factory):
    """(scaffold, printed parts, the open frame) of figure.glb's design and movie, and the
    movie's bytes."""
    from popupwb.motion import motion_movie, motion_run
    from popupwb.motion.design_from_motion import printed_character

    source = os.path.join(os.environ["POPUP_SOURCE_DIR"], "tests/data/animations/figure.glb")
    animation, _ = motion_run.read_animation(source)
    result = motion_run.design(animation, motion_run.motion_options())
    printed = printed_character(animation, result)
    targets = result.targets
    people = motion_movie.character_frames(
        animation, targets.animation_to_card, targets.first_frame, targets.last_frame
    )
    path = str(tmp_path_factory.mktemp("figure") / "motion.gif")
    motion_movie.write_movie(path, result.scaffold, people, printed=printed)
    (opened,) = _frames(path, [motion_movie.FRAMES - 1])
    with open(path, "rb") as f:
        written = f.read()
    return types.SimpleNamespace(
        scaffold=result.scaffold,
        printed=printed,
        opened=opened,
        bytes=written,
        make=lambda p: (motion_movie.write_movie(p, result.scaffold, people, printed=printed)),
    )


def _flat_projection(mesh, z, to_pixels):
    """The mesh's triangles seen along the card's normal onto the plane at height z (as the
    artwork of a patch lying there is rendered), in pixels."""
    vertices = np.asarray(mesh.vertices, dtype=float).reshape(-1, 3)
    on_plane = np.c_[vertices[:, :2], np.full(len(vertices), z)]
    pixels = to_pixels(on_plane)
    return [pixels[t] for t in np.asarray(mesh.triangles).reshape(-1, 3)]


def _ink(panel, paper):
    """Pixels darker than the paper's colour: the grey figure printed on it."""
    return panel.max(axis=2) < paper.max() - 20


def test_the_open_card_shows_the_body_on_its_pages_without_the_limbs(figure_movie):
    """figure.glb (a plain grey model): on the open card's pages, where no mechanism lies, the
    body's footprint (the posed body seen along the card's normal) is printed and the limbs'
    footprints, cut away from the body, are not."""
    from popupwb.motion import motion_movie

    scaffold, printed, opened = figure_movie.scaffold, figure_movie.printed, figure_movie.opened
    assert len(printed) >= 2  # the body and at least one limb
    ids = [p.id for p in scaffold.patches]
    outlines = [np.asarray(p.outer, dtype=float).reshape(-1, 3) for p in scaffold.patches]
    pages = [ids.index(scaffold.ground), ids.index(scaffold.backdrop)]
    to_pixels = _card_to_pixels(opened, [outlines[i] for i in pages])
    panel = opened[:, : motion_movie.PANEL_PX]
    on_page = _mask(panel.shape, [to_pixels(outlines[pages[0]])], -2)
    on_page |= _mask(panel.shape, [to_pixels(outlines[pages[1]])], -2)  # not the fold's line
    others = [to_pixels(o) for i, o in enumerate(outlines) if i not in pages]
    on_page &= ~_mask(panel.shape, others, 3)  # where the pages alone are seen
    body = _mask(panel.shape, _flat_projection(printed[0].mesh, 0.0, to_pixels))
    limbs = _mask(
        panel.shape, [t for p in printed[1:] for t in _flat_projection(p.mesh, 0, to_pixels)]
    )
    blank = on_page & ~_mask(panel.shape, _flat_projection(printed[0].mesh, 0.0, to_pixels), 3)
    paper = np.median(panel[blank & ~limbs], axis=0)
    ink = _ink(panel, paper)
    assert not ink[blank & ~limbs].any()  # the page is plain where nothing is printed
    body_seen = on_page & _mask(panel.shape, _flat_projection(printed[0].mesh, 0.0, to_pixels), -2)
    assert body_seen.sum() > 300 and ink[body_seen].mean() > 0.6
    cut_away = blank & limbs
    assert cut_away.sum() > 50 and ink[cut_away].mean() < 0.02


def test_each_limb_is_printed_on_its_moving_parts(figure_movie):
    """figure.glb: on each part a limb is printed on that lies flat on the open card (a floating
    layer's platform, a horizontal translation's moving part) and under no other part, the
    limb's footprint (its posed mesh seen along the card's normal) is grey and the rest is the
    paper's beige."""
    from popupwb.motion import motion_movie

    scaffold, printed, opened = figure_movie.scaffold, figure_movie.printed, figure_movie.opened
    ids = [p.id for p in scaffold.patches]
    outlines = [np.asarray(p.outer, dtype=float).reshape(-1, 3) for p in scaffold.patches]
    pages = [ids.index(scaffold.ground), ids.index(scaffold.backdrop)]
    to_pixels = _card_to_pixels(opened, [outlines[i] for i in pages])
    panel = opened[:, : motion_movie.PANEL_PX]
    grey = np.abs(panel[..., 0] - panel[..., 2]) < 20
    beige = panel[..., 0] - panel[..., 2] > 40
    names = [p.name for p in scaffold.patches]
    checked = 0
    for limb in printed[1:]:
        for part in limb.parts:
            i = names.index(f"{limb.mechanism}.{part}")
            z = outlines[i][:, 2]
            if np.ptp(z) > 1e-6:
                continue  # not lying flat: foreshortened, left to the eye
            above = [to_pixels(o) for o in outlines if o[:, 2].max() > z[0] + 1e-6]
            seen = _mask(panel.shape, [to_pixels(outlines[i])], -2)
            seen &= ~_mask(panel.shape, above, 3)
            footprint = _flat_projection(limb.mesh, z[0], to_pixels)
            on_limb = seen & _mask(panel.shape, footprint, -2)
            off_limb = seen & ~_mask(panel.shape, footprint, 3)
            if on_limb.sum() < 30:
                continue  # the limb hardly reaches it
            assert grey[on_limb].mean() > 0.8, names[i]
            assert off_limb.sum() == 0 or beige[off_limb].mean() > 0.9, names[i]
            checked += 1
    assert checked >= 1


def test_the_movie_with_artwork_is_the_same_file_twice(figure_movie, tmp_path):
    path = str(tmp_path / "again.gif")
    figure_movie.make(path)
    with open(path, "rb") as f:
        assert f.read() == figure_movie.bytes
