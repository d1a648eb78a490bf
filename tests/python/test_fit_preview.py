"""preview.png of `popup fit` (Workbench/popupwb/fitting/preview.py) and the core's rasteriser it
is drawn with (popupcore.render_view): pixel counts against areas derived by hand."""

import numpy as np
import pytest
from matplotlib.path import Path

import popupcore

RECTANGLE = np.array([[0, 0, 0], [100, 0, 0], [100, 50, 0], [0, 50, 0]], dtype=float)


def shade(colour, normal, light, ambient):
    """What render_view paints a face: colour x (ambient + (1 - ambient) |n . light|), 0..255."""
    n = np.asarray(normal, float) / np.linalg.norm(normal)
    l = np.asarray(light, float) / np.linalg.norm(light)  # noqa: E741
    return np.round(255 * np.asarray(colour) * (ambient + (1 - ambient) * abs(n @ l)))


def count_colour(rgb, colour, tolerance=2):
    return int(np.sum(np.all(np.abs(rgb.astype(int) - colour) <= tolerance, axis=-1)))


@pytest.mark.parametrize("supersample", [1, 2])
def test_a_rectangle_covers_its_area_in_pixels(supersample):
    # Seen straight down at 0.5 mm a pixel: 100 x 50 mm is 200 x 100 pixel centres, exactly.
    image = popupcore.render_view(
        [],
        [([RECTANGLE], (1.0, 0.5, 0.0), False)],
        towards_eye=(0, 0, 1),
        up=(0, 1, 0),
        centre=(50, 25, 0),
        mm_per_pixel=0.5,
        width=300,
        height=160,
        light=(0, 0, 1),
        ambient=0.3,
        supersample=supersample,
    )
    assert image.shape == (160, 300, 4)
    orange = shade((1.0, 0.5, 0.0), (0, 0, 1), (0, 0, 1), 0.3)
    assert count_colour(image[..., :3], orange, 0) == 200 * 100
    assert int(np.sum(image[..., 3] == 255)) == 200 * 100
    assert int(np.sum(image[..., 3] == 0)) == 300 * 160 - 200 * 100  # background: transparent
    assert tuple(image[80, 150, :3]) == tuple(orange)  # the middle
    assert tuple(image[0, 0]) == (255, 255, 255, 0)


def test_the_nearer_surface_hides_the_farther_one():
    # A mesh square at z = 10 over half of the rectangle at z = 0, seen from above.
    square = (
        np.array([[0, 0, 10], [50, 0, 10], [50, 50, 10], [0, 50, 10]], dtype=float),
        np.array([[0, 1, 2], [0, 2, 3]], dtype=np.int32),
        (0.0, 0.0, 1.0),
    )
    image = popupcore.render_view(
        [square],
        [([RECTANGLE], (1.0, 0.0, 0.0), False)],
        towards_eye=(0, 0, 1),
        up=(0, 1, 0),
        centre=(50, 25, 0),
        mm_per_pixel=1.0,
        width=100,
        height=50,
        light=(0, 0, 1),
        ambient=0.0,
    )
    rgb = image[..., :3]
    assert count_colour(rgb, (0, 0, 255), 0) == 50 * 50
    assert count_colour(rgb, (255, 0, 0), 0) == 50 * 50
    # Seen from below, the rectangle is the nearer one and hides the square.
    below = popupcore.render_view(
        [square],
        [([RECTANGLE], (1.0, 0.0, 0.0), False)],
        towards_eye=(0, 0, -1),
        up=(0, 1, 0),
        centre=(50, 25, 0),
        mm_per_pixel=1.0,
        width=100,
        height=50,
        light=(0, 0, 1),
        ambient=0.0,
    )
    assert count_colour(below[..., :3], (255, 0, 0), 0) == 100 * 50


def test_holes_are_left_empty():
    hole = np.array([[25, 10, 0], [75, 10, 0], [75, 40, 0], [25, 40, 0]], dtype=float)
    image = popupcore.render_view(
        [],
        [([RECTANGLE, hole], (1.0, 1.0, 1.0), False)],
        towards_eye=(0, 0, 1),
        up=(0, 1, 0),
        centre=(50, 25, 0),
        mm_per_pixel=1.0,
        width=100,
        height=50,
    )
    assert int(np.sum(image[..., 3] == 255)) == 100 * 50 - 50 * 30


def test_a_point_far_off_the_screen_is_drawn_up_to_the_edge():
    # A sliver reaching a million kilometres away: its outline is clipped to the picture, not
    # stepped along pixel by pixel, and the part on the screen is filled.
    far = np.array([[0, 0, 0], [1e12, 0, 0], [1e12, 50, 0], [0, 50, 0]], dtype=float)
    image = popupcore.render_view(
        [],
        [([far], (1.0, 1.0, 1.0), True)],
        towards_eye=(0, 0, 1),
        up=(0, 1, 0),
        centre=(50, 25, 0),
        mm_per_pixel=1.0,
        width=100,
        height=50,
        edge_px=1.0,
    )
    assert int(np.sum(image[..., 3] == 255)) == 100 * 50


@pytest.mark.parametrize(
    "option, value, message",
    [
        ("mm_per_pixel", 0.0, "mm_per_pixel"),
        ("width", 0, "1..8192"),
        ("supersample", 5, "1..4"),
        ("ambient", 2.0, r"\[0, 1\]"),
        ("up", (0, 0, 1), "not along towards_eye"),
    ],
)
def test_bad_camera_values_are_named(option, value, message):
    with pytest.raises(popupcore.DesignError, match=message):
        popupcore.render_view([], [], **{"towards_eye": (0, 0, 1), "up": (0, 1, 0), option: value})


def test_a_triangle_index_out_of_range_is_refused():
    mesh = (RECTANGLE, np.array([[0, 1, 7]], dtype=np.int32), (1, 1, 1))
    with pytest.raises(popupcore.DesignError, match=r"meshes\[0\].*0\.\.3"):
        popupcore.render_view([mesh], [])


def test_the_preview_shows_each_patch_over_its_projected_area(tmp_path):
    """A patch standing on the card, in the right panel: the pixels of its shade fill the patch's
    outline projected by the preview's own camera (derived here from camera_axes and fit_view),
    up to the outline's width along its border, and none fall outside it."""
    from matplotlib.image import imread

    from popupwb.fitting import preview

    params = popupcore.CardParams()
    params.width, params.depth = 100.0, 80.0
    outlines, card = preview.scaffold_outlines(popupcore.make_card(params))
    wall = np.array([[20, 30, 0], [20, 70, 0], [20, 70, 30], [20, 30, 30]], dtype=float)
    vertices = np.array([[-20, 30, 0], [20, 30, 0], [0, 70, 0], [0, 50, 40]], dtype=float)
    triangles = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    path = preview.write_preview(
        str(tmp_path / "p.png"), vertices, triangles, outlines + [[wall]], card, "test"
    )
    image = np.round(255 * imread(path)[..., :3]).astype(int)
    assert image.shape[:2] == (preview.IMAGE_SIZE_PX[1], preview.IMAGE_SIZE_PX[0])

    width = preview.IMAGE_SIZE_PX[0] // 2
    top = preview.TITLE_PX + preview.CAPTION_PX
    height = preview.IMAGE_SIZE_PX[1] - top
    everything = np.vstack([vertices, wall] + [loop for patch in outlines for loop in patch])
    centre, mm_per_pixel = preview.fit_view(everything, width, height)
    _, up, right = preview.camera_axes()
    corners = np.column_stack(
        [
            width / 2 + (wall - centre) @ right / mm_per_pixel,
            height / 2 - (wall - centre) @ up / mm_per_pixel,
        ]
    )
    x, y = corners[:, 0], corners[:, 1]
    area = 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))
    perimeter = np.sum(np.linalg.norm(corners - np.roll(corners, -1, axis=0), axis=1))
    assert area > 2000  # large enough to count

    panel = image[top:, width:]
    paper = shade(preview.PAPER_COLOUR, (1, 0, 0), preview.LIGHT, preview.AMBIENT)
    is_paper = np.all(np.abs(panel - paper) <= 2, axis=-1)
    rows, columns = np.mgrid[0:height, 0:width]
    centres = np.column_stack([columns.ravel() + 0.5, rows.ravel() + 0.5])
    inside = Path(corners).contains_points(centres).reshape(height, width)
    # Paper inside, but for a band of the outline's width (1.2 px) plus a blended pixel.
    assert area - 2.5 * perimeter <= np.sum(is_paper & inside) <= area
    assert np.sum(is_paper & ~inside) == 0
    # The model is not drawn on the pop-up side, the card is, the rest is white.
    white = np.all(panel == 255, axis=-1)
    assert np.sum(white & inside) == 0
    assert np.sum(white) > 0.5 * width * height
