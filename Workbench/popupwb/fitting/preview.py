"""preview.png of `popup fit`: the model and the pop-up side by side, both in the card's frame at
the design state (the card open flat, 180°), seen from the same camera on the viewer's side (+x)
at the same scale.

Drawn by the core's z-buffer rasteriser (popupcore.render_view: every triangle of a scanned model
in a fraction of a second, hidden surfaces hidden), supersampled and framed with Pillow; faces
are flat-shaded by their normal so the boxes read as solids. No display, no FreeCAD GUI.
"""

import numpy as np

IMAGE_SIZE_PX = (1600, 800)
SUPERSAMPLE = 2  # drawn this many times finer, then averaged: smooth edges
TITLE_PX = 34  # the strip above the panels: the title, then each panel's caption
CAPTION_PX = 26
MARGIN = 0.06  # free border around the scene, a fraction of the panel
LIGHT = (0.6, -0.3, 0.75)
AMBIENT = 0.45
MODEL_COLOUR = (0.55, 0.65, 0.85)
PAPER_COLOUR = (0.95, 0.88, 0.70)
CARD_COLOUR = (0.85, 0.85, 0.85)
EDGE_COLOUR = (0.2, 0.2, 0.2)
CAMERA = {"elev": 28.0, "azim": 25.0}  # degrees: from the +x side, a little to the right
FONT_FILE = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"


def camera_axes(elev=CAMERA["elev"], azim=CAMERA["azim"]):
    """(towards_eye, up, right) unit vectors of the camera, as matplotlib's view_init(elev, azim)
    places it: up is +z seen from the eye."""
    e, a = np.radians(elev), np.radians(azim)
    eye = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
    up = np.array([0.0, 0.0, 1.0]) - np.sin(e) * eye
    up /= np.linalg.norm(up)
    return eye, up, np.cross(up, eye)


def fit_view(points, width, height, margin=MARGIN):
    """(centre, mm_per_pixel) that fit `points` (Nx3, card mm) in width x height pixels with a
    `margin` border, seen by camera_axes()."""
    _, up, right = camera_axes()
    across, along = points @ right, points @ up
    lo, hi = np.array([across.min(), along.min()]), np.array([across.max(), along.max()])
    usable = (1.0 - 2.0 * margin) * np.array([width, height], dtype=float)
    mm_per_pixel = max(float(np.max((hi - lo) / usable)), 1e-9)
    mid = 0.5 * (lo + hi)
    return mid[0] * right + mid[1] * up, mm_per_pixel


def render_panel(meshes, polygons, centre, mm_per_pixel, width, height):
    """One panel as an RGB uint8 array (height x width x 3) on white: popupcore.render_view,
    drawn SUPERSAMPLE times finer and averaged."""
    from popupwb.core import popupcore

    eye, up, _ = camera_axes()
    rgba = popupcore.render_view(
        meshes,
        polygons,
        towards_eye=eye,
        up=up,
        centre=centre,
        mm_per_pixel=mm_per_pixel,
        width=width,
        height=height,
        light=LIGHT,
        ambient=AMBIENT,
        background=(1.0, 1.0, 1.0),
        edge_colour=EDGE_COLOUR,
        edge_px=1.2,
        supersample=SUPERSAMPLE,
    )
    return np.ascontiguousarray(rgba[..., :3])


def _loops(patch):
    """A patch given as one Kx3 outline, or as a list of loops (outline, then holes)."""
    if isinstance(patch, np.ndarray) and patch.ndim == 2:
        return [np.asarray(patch, dtype=float).reshape(-1, 3)]
    return [np.asarray(loop, dtype=float).reshape(-1, 3) for loop in patch]


def _scale_bar_mm(mm_per_pixel, width):
    """A round length (1, 2 or 5 times a power of ten) near a fifth of the panel."""
    target = 0.2 * width * mm_per_pixel
    power = 10.0 ** np.floor(np.log10(target))
    return max(s * power for s in (1, 2, 5) if s * power <= target)


def _font(size):
    from PIL import ImageFont

    try:
        return ImageFont.truetype(FONT_FILE, size)
    except OSError:
        return ImageFont.load_default()


def write_preview(path, model_vertices, model_triangles, patches, card_patches=(), title=""):
    """Writes the side-by-side PNG to `path`.

    `model_vertices` (Nx3) and `model_triangles` (Mx3) are the model in the card's frame (mm);
    `patches` the pop-up's patches at the design state, each a Kx3 outline or a list of loops
    (outline, then holes); `card_patches` the indices of the card's own pages among them (drawn
    grey, under the model on the left too)."""
    from PIL import Image, ImageDraw

    vertices = np.asarray(model_vertices, dtype=float).reshape(-1, 3)
    triangles = np.asarray(model_triangles, dtype=np.int32).reshape(-1, 3)
    loops = [_loops(p) for p in patches]
    card = set(card_patches)
    everything = np.vstack([vertices] + [loop for patch in loops for loop in patch])

    width, height = IMAGE_SIZE_PX[0] // 2, IMAGE_SIZE_PX[1] - TITLE_PX - CAPTION_PX
    centre, mm_per_pixel = fit_view(everything, width, height)
    pages = [(loops[i], CARD_COLOUR, True) for i in sorted(card)]
    model = [(vertices, triangles, MODEL_COLOUR)]
    popup = [(p, CARD_COLOUR if i in card else PAPER_COLOUR, True) for i, p in enumerate(loops)]
    left = render_panel(model, pages, centre, mm_per_pixel, width, height)
    right = render_panel([], popup, centre, mm_per_pixel, width, height)

    image = Image.new("RGB", IMAGE_SIZE_PX, "white")
    image.paste(Image.fromarray(left), (0, TITLE_PX + CAPTION_PX))
    image.paste(Image.fromarray(right), (width, TITLE_PX + CAPTION_PX))
    draw = ImageDraw.Draw(image)
    if title:
        draw.text((IMAGE_SIZE_PX[0] // 2, 6), title, fill="black", font=_font(20), anchor="ma")
    captions = (
        "model (in the card's frame, on the open card)",
        "pop-up at the design state (open flat, 180°)",
    )
    for i, caption in enumerate(captions):
        draw.text(
            (i * width + width // 2, TITLE_PX), caption, fill="black", font=_font(15), anchor="ma"
        )
    bar = _scale_bar_mm(mm_per_pixel, width)
    for x0 in (20, width + 20):
        y = IMAGE_SIZE_PX[1] - 20
        draw.line((x0, y, x0 + bar / mm_per_pixel, y), fill="black", width=3)
        draw.text((x0, y - 20), f"{bar:g} mm", fill="black", font=_font(14))
    draw.line((width, TITLE_PX + CAPTION_PX, width, IMAGE_SIZE_PX[1]), fill=(200, 200, 200))
    image.save(path)
    return path


def scaffold_outlines(scaffold):
    """The loops of every patch of a popupcore.Scaffold at its design state (each a list: the
    outline, then its holes), and the indices of the card's pages among them."""
    outlines = [
        [np.asarray(patch.outer, dtype=float).reshape(-1, 3)]
        + [np.asarray(h, dtype=float).reshape(-1, 3) for h in patch.holes]
        for patch in scaffold.patches
    ]
    ids = [patch.id for patch in scaffold.patches]
    card = [ids.index(i) for i in (scaffold.ground, scaffold.backdrop) if i in ids]
    return outlines, card
