"""The card's half of motion.gif, drawn as it will be printed: each patch of the folding card
filled, through a z-buffer, with the artwork its sheet prints on it (the character's body on the
pages and the parts that stand still, each limb on its mechanism's moving parts: thesis Fig 6.9,
as sheets/print_artwork.render_sheet_artwork prints them), else with the paper's colour.

Each patch's artwork is rendered once (popupcore.render_artworks) at the design state, in the
patch's own frame, at a resolution fit for the panel. Each frame carries it onto the posed patch
by the patch's rigid motion and the orthographic camera: one affine map per patch and frame, from
a panel pixel to the image's pixel, applied to every pixel the patch wins in the z-buffer. Only
the printed (normal) side carries the artwork, as on the sheets: a patch seen from behind shows
blank paper.
"""

import math

import numpy as np

from popupwb.sheets.print_artwork import LIMB_BEHIND_MM

# Artwork pixels per panel pixel: a little finer than the panel, so nearest sampling is sharp.
OVERSAMPLE = 1.5
MIN_PIXELS_PER_MM = 1.0
MAX_PIXELS_PER_MM = 8.0
EDGE_ON_PX2 = 2.0  # a patch seen under this doubled area (pixels²) is drawn as a line


class CardArtwork:
    """The printed artwork of a scaffold's patches at its design state, in one flat atlas:
    patch index i's image is atlas[offset[i] : offset[i] + width[i] * height[i]] (row-major,
    row 0 at the top), its pixel (column c, row r) spanning the design-state points
    corner[i] + [c, c + 1] step_u[i] + [r, r + 1] step_v[i]; has[i] False without one."""

    def __init__(self, count, images):
        self.has = np.zeros(count, dtype=bool)
        self.back = np.zeros(count, dtype=bool)
        self.corner = np.zeros((count, 3))
        self.step_u = np.zeros((count, 3))
        self.step_v = np.zeros((count, 3))
        self.normal = np.zeros((count, 3))
        self.offset = np.zeros(count, dtype=np.int64)
        self.width = np.zeros(count, dtype=np.int64)
        self.height = np.zeros(count, dtype=np.int64)
        pixels, at = [], 0
        for i, art in sorted(images.items()):
            rgba = np.asarray(art.rgba)
            if not rgba[..., 3].any():
                continue  # nothing of the character on it: plain paper
            frame = art.frame
            u, v = (np.asarray(frame[k], dtype=float) for k in ("u", "v"))
            step = float(art.mm_per_pixel)
            h, w = rgba.shape[:2]
            u0, v0 = art.origin_uv
            self.corner[i] = np.asarray(frame["origin"], dtype=float) + u0 * u + (v0 + h * step) * v
            self.step_u[i], self.step_v[i] = step * u, -step * v
            self.normal[i] = np.asarray(frame["normal"], dtype=float)
            self.back[i] = bool(art.back_side)
            self.has[i] = True
            self.offset[i], self.width[i], self.height[i] = at, w, h
            pixels.append(rgba.reshape(-1, 4))
            at += w * h
        self.atlas = np.vstack(pixels) if pixels else np.zeros((0, 4), dtype=np.uint8)


def pixels_per_mm(view_scale):
    """The artwork's resolution for a panel drawn at `view_scale` pixels per mm."""
    return float(np.clip(OVERSAMPLE * view_scale, MIN_PIXELS_PER_MM, MAX_PIXELS_PER_MM))


def render_card_artwork(scaffold, printed, resolution):
    """CardArtwork of `scaffold` (design state) for `printed`, popupcore.printed_parts as
    design_from_motion.printed_character gives them (the body first, then the limbs): each limb
    on its mechanism's parts at any depth (print_artwork.LIMB_BEHIND_MM), the body on every
    other patch, each from its normal side, `resolution` pixels per mm."""
    from popupwb.core import popupcore

    patches = list(scaffold.patches)
    index = {p.id: i for i, p in enumerate(patches)}
    images, taken = {}, set()
    for limb in printed[1:]:
        names = {f"{limb.mechanism}.{part}" for part in limb.parts}
        chosen = [p for p in patches if p.name in names and p.id not in taken]
        taken.update(p.id for p in chosen)
        if chosen and len(limb.mesh.triangles):
            arts = popupcore.render_artworks(
                limb.mesh,
                chosen,
                pixels_per_mm=resolution,
                depth=math.inf,
                behind=LIMB_BEHIND_MM,
            )
            images.update((index[a.patch], a) for a in arts)
    body = [p for p in patches if p.id not in taken]
    if printed and body and len(printed[0].mesh.triangles):
        for art in popupcore.render_artworks(printed[0].mesh, body, pixels_per_mm=resolution):
            images[index[art.patch]] = art
    return CardArtwork(len(patches), images)


def _image_maps(artwork, affine, rotations, translations, eye):
    """(n, 2, 3): per patch, the affine map from a panel pixel (x, y) to its artwork's continuous
    (column, row); NaN where the patch shows no artwork this frame (none, seen from behind or
    edge-on). `affine` = (A 2x3, b): the camera, panel pixel = A X + b."""
    a, b = affine
    maps = np.full((len(artwork.has), 2, 3), np.nan)
    for i in np.nonzero(artwork.has)[0]:
        rotation = rotations[i]
        facing = float((rotation @ artwork.normal[i]) @ eye)
        if (facing <= 0) != bool(artwork.back[i]) or facing == 0:
            continue  # its printed side faces away: blank paper seen
        start = a @ (rotation @ artwork.corner[i] + translations[i]) + b
        jacobian = np.c_[a @ (rotation @ artwork.step_u[i]), a @ (rotation @ artwork.step_v[i])]
        if abs(np.linalg.det(jacobian)) < 1e-9:
            continue
        inverse = np.linalg.inv(jacobian)
        maps[i] = np.c_[inverse, -inverse @ start]
    return maps


def _artwork_pixels(artwork, maps, ids, covered):
    """(rows, cols, rgba float) of the covered panel pixels whose patch shows artwork there."""
    rows, cols = np.nonzero(covered & artwork.has[np.maximum(ids, 0)])
    which = ids[rows, cols]
    m = maps[which]
    x, y = cols + 0.5, rows + 0.5
    column = np.floor(m[:, 0, 0] * x + m[:, 0, 1] * y + m[:, 0, 2])
    row = np.floor(m[:, 1, 0] * x + m[:, 1, 1] * y + m[:, 1, 2])
    with np.errstate(invalid="ignore"):
        inside = (column >= 0) & (column < artwork.width[which])
        inside &= (row >= 0) & (row < artwork.height[which])
    rows, cols, which = rows[inside], cols[inside], which[inside]
    at = artwork.offset[which] + row[inside].astype(np.int64) * artwork.width[which]
    at += column[inside].astype(np.int64)
    return rows, cols, artwork.atlas[at].astype(float)


def _zbuffer(view, polygons, height, width):
    """(ids, edge-on indices): per panel pixel the index of the polygon nearest the camera there
    (-1 none), each polygon's depth taken from its plane; polygons seen edge-on are left out."""
    from PIL import Image, ImageDraw

    zbuffer = np.full((height, width), -np.inf)
    ids = np.full((height, width), -1, dtype=np.int64)
    edge_on = []
    for i, polygon in enumerate(polygons):
        if len(polygon) < 3:
            continue
        pixels = view.pixels(polygon, 0)
        x0, y0 = np.floor(pixels.min(axis=0)).astype(int)
        x1, y1 = np.ceil(pixels.max(axis=0)).astype(int) + 1
        x0, y0, x1, y1 = max(x0, 0), max(y0, 0), min(x1, width), min(y1, height)
        doubled = np.sum(
            pixels[:, 0] * np.roll(pixels[:, 1], -1) - np.roll(pixels[:, 0], -1) * pixels[:, 1]
        )
        if abs(doubled) < EDGE_ON_PX2 or x1 <= x0 or y1 <= y0:  # under a pixel of area
            edge_on.append(i)
            continue
        mask = Image.new("1", (x1 - x0, y1 - y0), 0)
        ImageDraw.Draw(mask).polygon([(float(a - x0), float(b - y0)) for a, b in pixels], fill=1)
        inside = np.asarray(mask, dtype=bool)
        # The polygon is planar: its depth is affine in the pixel coordinates.
        system = np.c_[pixels, np.ones(len(pixels))]
        (a, b, c), *_ = np.linalg.lstsq(system, view.depth(polygon), rcond=None)
        z = a * (np.arange(x0, x1) + 0.5)[None, :] + b * (np.arange(y0, y1) + 0.5)[:, None] + c
        window = zbuffer[y0:y1, x0:x1]
        nearer = inside & (z > window)
        window[nearer] = z[nearer]
        ids[y0:y1, x0:x1][nearer] = i
    return ids, edge_on


def paint_card(view, polygons, colours, height, width, outline, printed=None):
    """The card panel as (RGB uint8 height x width x 3, covered mask, edge-on polygon indices):
    each pixel shows the polygon nearest the camera there, in its colour (an RGB triple: the
    paper shaded) or, where the artwork prints on it, the image's pixel over that paper, shaded
    alike; region borders are outlined with `outline` (None: not). `printed` = (CardArtwork,
    shades, rotations n x 3 x 3, translations n x 3): the artwork, each polygon's shading factor
    and rigid motion from the design state; None: the paper alone."""
    ids, edge_on = _zbuffer(view, polygons, height, width)
    palette = np.array([(255, 255, 255)] + [tuple(c) for c in colours], dtype=np.uint8)
    picture = palette[ids + 1]
    covered = ids >= 0
    if printed is not None and printed[0].has.any():
        artwork, shades, rotations, translations = printed
        maps = _image_maps(artwork, view.affine(), rotations, translations, view.towards_eye())
        rows, cols, rgba = _artwork_pixels(artwork, maps, ids, covered)
        if len(rows):
            which = ids[rows, cols]
            paper = palette[which + 1].astype(float)
            alpha = rgba[:, 3:] / 255.0
            shade = np.asarray(shades, dtype=float)[which][:, None]
            ink = rgba[:, :3] * shade * alpha + paper * (1.0 - alpha)
            picture[rows, cols] = np.clip(np.rint(ink), 0, 255).astype(np.uint8)
    if outline is not None:
        border = np.zeros_like(covered)
        border[:, 1:] |= ids[:, 1:] != ids[:, :-1]
        border[1:, :] |= ids[1:, :] != ids[:-1, :]
        picture[border] = outline
        covered |= border
    return picture, covered, edge_on
