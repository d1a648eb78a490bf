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

from popupwb.sheets.print_artwork import LIMB_BEHIND_MM, body_windows

# Artwork pixels per panel pixel: a little finer than the panel, so nearest sampling is sharp.
OVERSAMPLE = 1.5
MIN_PIXELS_PER_MM = 1.0
MAX_PIXELS_PER_MM = 8.0
EDGE_ON_PX2 = 2.0  # a patch seen under this doubled area (pixels²) is drawn as a line
# Patches lying on one plane (a mechanism's parts flat on the page at 180°): the later one, glued
# over the earlier (the pages come first), shows, and a limb's part over all.
TIE_MM = 1e-4


class CardArtwork:
    """The printed artwork of a scaffold's patches at its design state, cropped to what is
    printed, in one flat atlas: patch index i's image is rows offset[i] to offset[i] +
    width[i] * height[i] of `ink` (RGB premultiplied by alpha) and `alpha` (row-major, row 0 at
    the top), its pixel (column c, row r) spanning the design-state points corner[i] +
    [c, c + 1] step_u[i] + [r, r + 1] step_v[i]; has[i] False where nothing is printed."""

    def __init__(self, count, images, limbs=()):
        self.has = np.zeros(count, dtype=bool)
        # The limbs' parts: on a plane shared with others they show (the moving part lies over
        # the wing or page it folds from; a later part would otherwise hide the limb).
        self.limb = np.zeros(count, dtype=bool)
        self.limb[list(limbs)] = True
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
            rgba = np.asarray(art.rgba)  # a copy out of the core: read once
            rows, cols = np.nonzero(rgba[..., 3])
            if not len(rows):
                continue  # nothing of the character on it: plain paper
            frame = art.frame
            u, v = (np.asarray(frame[k], dtype=float) for k in ("u", "v"))
            step = float(art.mm_per_pixel)
            u0, v0 = art.origin_uv
            top = np.asarray(frame["origin"], dtype=float) + u0 * u + (v0 + len(rgba) * step) * v
            r0, c0 = rows.min(), cols.min()
            rgba = rgba[r0 : rows.max() + 1, c0 : cols.max() + 1]
            self.step_u[i], self.step_v[i] = step * u, -step * v
            self.corner[i] = top + c0 * self.step_u[i] + r0 * self.step_v[i]
            self.normal[i] = np.asarray(frame["normal"], dtype=float)
            self.back[i] = bool(art.back_side)
            self.has[i] = True
            self.height[i], self.width[i] = rgba.shape[:2]
            self.offset[i] = at
            pixels.append(rgba.reshape(-1, 4))
            at += len(pixels[-1])
        atlas = np.vstack(pixels) if pixels else np.zeros((0, 4), dtype=np.uint8)
        self.alpha = atlas[:, 3].astype(np.float32) / 255.0
        self.ink = atlas[:, :3].astype(np.float32) * self.alpha[:, None]


def pixels_per_mm(view_scale):
    """The artwork's resolution for a panel drawn at `view_scale` pixels per mm."""
    return float(np.clip(OVERSAMPLE * view_scale, MIN_PIXELS_PER_MM, MAX_PIXELS_PER_MM))


def render_card_artwork(scaffold, printed, resolution):
    """CardArtwork of `scaffold` (design state) for `printed`, popupcore.printed_parts as
    design_from_motion.printed_character gives them (the body first, then the limbs): each limb
    on its mechanism's parts at any depth (print_artwork.LIMB_BEHIND_MM), the body on every
    other patch (the pages at any depth: print_artwork.body_windows), each from its normal side,
    `resolution` pixels per mm."""
    from popupwb.core import popupcore

    patches = list(scaffold.patches)
    index = {p.id: i for i, p in enumerate(patches)}
    images, taken = {}, set()
    for limb in printed[1:]:
        names = {f"{limb.mechanism}.{part}" for part in limb.parts}
        chosen = [p for p in patches if p.name in names]
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
        for chosen, window in body_windows(body, {"pixels_per_mm": resolution}):
            if chosen:
                for art in popupcore.render_artworks(printed[0].mesh, chosen, **window):
                    images[index[art.patch]] = art
    return CardArtwork(len(patches), images, [index[i] for i in taken])


def _print_patch(picture, ids, box, artwork, i, shade, pose, camera):
    """Draws patch i's artwork on the pixels of `picture` (the box `box` of the panel) it wins
    in `ids`, over the paper colour they have, shaded by `shade`: the image carried by the
    patch's rigid motion `pose` = (R, t) and the `camera` = (A, b, eye), panel pixel = A X + b.
    Nothing where its printed side faces away (blank paper seen) or it is seen edge-on."""
    (rotation, translation), (a, b, eye) = pose, camera
    facing = float((rotation @ artwork.normal[i]) @ eye)
    if facing == 0 or (facing < 0) != bool(artwork.back[i]):
        return
    start = a @ (rotation @ artwork.corner[i] + translation) + b
    jacobian = np.c_[a @ (rotation @ artwork.step_u[i]), a @ (rotation @ artwork.step_v[i])]
    if abs(np.linalg.det(jacobian)) < 1e-9:
        return
    width, height = artwork.width[i], artwork.height[i]
    # Only the pixels under the image can show it.
    corners = start + np.array([[0, 0], [width, 0], [0, height], [width, height]]) @ jacobian.T
    x0, y0 = np.maximum(np.floor(corners.min(axis=0)).astype(int) - box[:2], 0)
    x1, y1 = np.maximum(np.ceil(corners.max(axis=0)).astype(int) + 1 - box[:2], 0)
    rows, cols = np.nonzero(ids[y0:y1, x0:x1] == i)
    if not len(rows):
        return
    rows, cols = rows + y0, cols + x0
    inverse = np.linalg.inv(jacobian)
    offset = np.c_[cols + (box[0] + 0.5), rows + (box[1] + 0.5)] - start
    column, row = np.floor(offset @ inverse.T).astype(np.int64).T
    inside = (column >= 0) & (column < width) & (row >= 0) & (row < height)
    rows, cols = rows[inside], cols[inside]
    at = artwork.offset[i] + row[inside] * width + column[inside]
    paper = picture[rows, cols].astype(np.float32)
    ink = artwork.ink[at] * shade + paper * (1.0 - artwork.alpha[at])[:, None]
    picture[rows, cols] = np.rint(ink).astype(np.uint8)  # within 0..255: a blend


def newell_normals(polygons):
    """(n, 3) Newell normals of the polygons (each Kx3; zero for fewer than 3 corners), their
    length twice the area, all in one pass."""
    normals = np.zeros((len(polygons), 3))
    used = [i for i, p in enumerate(polygons) if len(p) >= 3]
    if not used:
        return normals
    points = np.vstack([np.asarray(polygons[i], dtype=float).reshape(-1, 3) for i in used])
    counts = np.array([len(polygons[i]) for i in used], dtype=np.int64)
    starts = np.concatenate([[0], np.cumsum(counts)[:-1]])
    following = np.arange(1, len(points) + 1)
    following[starts + counts - 1] = starts  # each polygon's last corner closes it
    normals[used] = np.add.reduceat(np.cross(points, points[following]), starts, axis=0)
    return normals


def _depth_planes(polygons, normals, affine, eye):
    """(n, 3): per polygon (a, b, c), its depth toward the camera at pixel (x, y) being
    a x + b y + c (the polygon is planar, the camera orthographic: pixel = A X + b, depth =
    eye . X); NaN seen edge-on."""
    a, b = affine
    inverse = np.linalg.inv(np.vstack([a, eye]))
    m = normals @ inverse  # the plane n . X = n . X0 in (pixel - b, depth)
    centres = np.array([np.asarray(p, dtype=float).reshape(-1, 3).mean(axis=0) for p in polygons])
    level = np.einsum("ij,ij->i", normals, centres)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.c_[
            -m[:, 0] / m[:, 2],
            -m[:, 1] / m[:, 2],
            (level + m[:, 0] * b[0] + m[:, 1] * b[1]) / m[:, 2],
        ]


def _zbuffer(pixels, planes, box, order):
    """(ids, edge-on indices): per pixel of `box` (x0, y0, x1, y1) the index of the polygon
    nearest the camera there (-1 none; of polygons as near, within TIE_MM, the last in
    `order`); `pixels` each polygon's corners in panel pixels, `planes` its depth plane.
    Polygons seen edge-on (under a pixel of area) are left out."""
    from PIL import Image, ImageDraw

    bx0, by0, bx1, by1 = box
    zbuffer = np.full((by1 - by0, bx1 - bx0), -np.inf)
    ids = np.full((by1 - by0, bx1 - bx0), -1, dtype=np.int32)
    edge_on = []
    for i in order:
        corners = pixels[i]
        if len(corners) < 3:
            continue
        x0, y0 = np.floor(corners.min(axis=0)).astype(int)
        x1, y1 = np.ceil(corners.max(axis=0)).astype(int) + 1
        x0, y0, x1, y1 = max(x0, bx0), max(y0, by0), min(x1, bx1), min(y1, by1)
        following = np.roll(corners, -1, axis=0)
        doubled = np.sum(corners[:, 0] * following[:, 1] - following[:, 0] * corners[:, 1])
        if abs(doubled) < EDGE_ON_PX2 or x1 <= x0 or y1 <= y0 or not np.isfinite(planes[i]).all():
            edge_on.append(i)
            continue
        mask = Image.new("L", (x1 - x0, y1 - y0), 0)  # "L": 1 read as bool without unpacking
        ImageDraw.Draw(mask).polygon((corners - (x0, y0)).ravel().tolist(), fill=1)
        a, b, c = planes[i]
        z = (a * (np.arange(x0, x1) + 0.5))[None, :] + (b * (np.arange(y0, y1) + 0.5) + c)[:, None]
        window = zbuffer[y0 - by0 : y1 - by0, x0 - bx0 : x1 - bx0]
        nearer = np.asarray(mask).view(bool) & (z > window - TIE_MM)
        window[nearer] = z[nearer]
        ids[y0 - by0 : y1 - by0, x0 - bx0 : x1 - bx0][nearer] = i
    return ids, sorted(edge_on)


def paint_card(view, polygons, normals, colours, size, outline, printed=None):
    """The card panel's drawn box as (RGB uint8 array, covered mask, (x0, y0) its top-left
    pixel, edge-on polygon indices) for a panel of `size` (width, height): each pixel shows the
    polygon nearest the camera there, in its colour (an RGB triple: the paper shaded) or, where
    the artwork prints on it, the image's pixel over that paper, shaded alike; region borders
    are outlined with `outline` (None: not). `normals`: newell_normals(polygons); `printed` =
    (CardArtwork, shades, rotations n x 3 x 3, translations n x 3): the artwork, each polygon's
    shading factor and rigid motion from the design state; None: the paper alone."""
    affine, eye = view.affine(), view.towards_eye()
    counts = [len(p) for p in polygons]
    points = np.vstack([np.asarray(p, dtype=float).reshape(-1, 3) for p in polygons])
    flat = points @ affine[0].T + affine[1]
    pixels = np.split(flat, np.cumsum(counts)[:-1])
    lo = np.floor(flat.min(axis=0)).astype(int) - 2
    hi = np.ceil(flat.max(axis=0)).astype(int) + 3
    box = (max(lo[0], 0), max(lo[1], 0), min(hi[0], size[0]), min(hi[1], size[1]))
    if box[2] <= box[0] or box[3] <= box[1]:  # nothing in the panel
        return np.zeros((0, 0, 3), np.uint8), np.zeros((0, 0), bool), box[:2], []
    planes = _depth_planes(polygons, normals, affine, eye)
    # Ties: the later patch, and a limb's part over everything (CardArtwork.limb).
    limb = printed[0].limb if printed is not None else np.zeros(len(polygons), dtype=bool)
    order = np.argsort(limb, kind="stable")
    ids, edge_on = _zbuffer(pixels, planes, box, order)
    palette = np.array([(255, 255, 255)] + [tuple(c) for c in colours], dtype=np.uint8)
    picture = palette[ids + 1]
    covered = ids >= 0
    if printed is not None:
        artwork, shades, rotations, translations = printed
        camera = (*affine, eye)
        for i in np.nonzero(artwork.has)[0]:
            pose = (rotations[i], translations[i])
            _print_patch(picture, ids, box, artwork, i, shades[i], pose, camera)
    if outline is not None:
        border = np.zeros_like(covered)
        border[:, 1:] |= ids[:, 1:] != ids[:, :-1]
        border[1:, :] |= ids[1:, :] != ids[:-1, :]
        picture[border] = outline
        covered |= border
    return picture, covered, box[:2], edge_on
