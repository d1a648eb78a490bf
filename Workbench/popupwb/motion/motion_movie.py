"""motion.gif of `popup animate`: the card opening from closed (0°) to open flat (180°), side by
side with the character's animation over the chosen frames, frame k of the movie at the fold
angle θ = 180°·s and the animation frame first + s·(last − first), s = k / (FRAMES − 1) (the
pairing the design is made for, docs/MATH.md "Motion targets").

Left, the card: the simulated scaffold (popupcore.simulate_fold from the design state) posed at θ,
each patch filled through a z-buffer (numpy, Pillow's polygon masks) and shaded by its normal,
seen by a camera above the open card (card x to the right, y up: the view the target paths are
measured in) leaning TILT_DEGREES toward its front edge, so what stands up shows.
Right, the character: its bones (popupcore.forward_kinematics, fractional frames interpolated) and,
when it has one, its skinned mesh (popupcore.posed_mesh), mapped to the card by animation_to_card
and projected the same way. Both halves share one scale and the faint target paths, so the
mechanisms' points (left) and the end effectors (right) can be followed together.

Deterministic: fixed frame count, sizes, colours and Pillow's built-in font; no timestamps.
"""

import math

import numpy as np

FRAMES = 37  # every 5° of the fold
PANEL_PX = 480
HEADER_PX = 28
MARGIN_PX = 16
FRAME_MS = 90
HOLD_MS = 1200  # the open card stays a while before the loop starts again
MAX_MESH_TRIANGLES = 6000
BACKGROUND = (255, 255, 255)
PAPER = np.array([245.0, 225.0, 178.0])
CARD = np.array([214.0, 214.0, 214.0])
MESH = np.array([140.0, 165.0, 215.0])
EDGE = (70, 70, 70)
BONE = (40, 40, 40)
PATH = (200, 200, 200)
POINT_COLOURS = (
    (31, 119, 180),
    (214, 39, 40),
    (44, 160, 44),
    (148, 103, 189),
    (255, 127, 14),
    (23, 190, 207),
    (140, 86, 75),
    (227, 119, 194),
)
LIGHT = np.array([0.3, -0.4, 0.87])
TILT_DEGREES = 30.0  # the camera above the open card, leaning toward its front edge (y = 0)


class MovieError(ValueError):
    """The fold could not be simulated over the whole range."""


def _shade(colour, normal):
    light = LIGHT / np.linalg.norm(LIGHT)
    length = float(np.linalg.norm(normal))
    shade = abs(float(normal @ light)) / length if length > 0 else 0.5
    return tuple(int(round(c)) for c in np.clip(colour * (0.55 + 0.45 * shade), 0, 255))


def _normal(polygon):
    normal = np.zeros(3)
    for i in range(len(polygon)):  # Newell's normal
        normal += np.cross(polygon[i], polygon[(i + 1) % len(polygon)])
    return normal


def card_frames(scaffold, count=FRAMES):
    """[(θ degrees, [patch outline Kx3], card patch indices)] from closed to open, by simulating
    the scaffold from its design state (180°) to 0 at `count` angles; MovieError when the
    simulation stops early (a design that locks)."""
    from popupwb.core import popupcore

    angles = list(np.linspace(math.pi, 0.0, int(count)))
    sweep = popupcore.simulate_fold(scaffold, angles)
    states = list(sweep.states)
    if len(states) != len(angles):
        raise MovieError(
            f"the card's fold stops at {math.degrees(angles[len(states) - 1]):.0f}° of "
            f"{len(angles)} angles: no movie of a design that does not close"
            if states
            else "the card's fold cannot be simulated"
        )
    ids = [patch.id for patch in scaffold.patches]
    card = {ids.index(i) for i in (scaffold.ground, scaffold.backdrop) if i in ids}
    frames = []
    for angle, state in zip(angles, states):
        outlines = [
            np.asarray(o, dtype=float).reshape(-1, 3)
            for o in popupcore.posed_outlines(scaffold, state)
        ]
        frames.append((math.degrees(angle), outlines, card))
    return frames[::-1]


def character_frames(
    animation, animation_to_card, first_frame, last_frame, count=FRAMES, in_place_up=None
):
    """[(frame, bone segments [(a, b)] in card mm, mesh triangles Mx3x3 or None)] over the frame
    range, `count` evenly spaced (fractional) frames. `in_place_up`: the view's up when the
    targets keep the character in place (targets.in_place), so it stands where they are."""
    from popupwb.core import popupcore
    from popupwb.model.model_source import transformed

    matrix = np.asarray(animation_to_card, dtype=float)
    parents = [int(parent) for _, parent in animation.bones]
    mesh = animation.mesh
    has_mesh = mesh is not None and len(mesh.triangles) > 0
    out = []
    for s in np.linspace(0.0, 1.0, int(count)):
        frame = first_frame + s * (last_frame - first_frame)
        globals_ = [
            np.asarray(m, dtype=float) for m in popupcore.forward_kinematics(animation, frame)
        ]
        back = np.zeros(3)
        if in_place_up is not None:
            back = np.asarray(
                popupcore.ground_travel(animation, in_place_up, int(last_frame), float(frame))
            )
        points = np.array([g[:3, 3] for g in globals_]).reshape(-1, 3) - back
        joints = transformed(points, matrix)
        segments = [(joints[p], joints[b]) for b, p in enumerate(parents) if p >= 0]
        triangles = None
        if has_mesh:
            posed = popupcore.posed_mesh(animation, float(frame))
            vertices = transformed(np.asarray(posed.vertices) - back, matrix)
            faces = np.asarray(posed.triangles, dtype=np.int64).reshape(-1, 3)
            if len(faces) > MAX_MESH_TRIANGLES:
                faces = faces[:: int(math.ceil(len(faces) / MAX_MESH_TRIANGLES))]
            triangles = vertices[faces]
        out.append((float(frame), segments, triangles))
    return out


class _View:
    """Card mm to panel pixels through the camera: screen x is card x, screen up is
    y cos t + z sin t (the open card seen from in front, TILT above its plane's normal), one
    scale for both panels; depth toward the camera is z cos t - y sin t."""

    def __init__(self, points):
        screen = self.screen(points)
        lo, hi = screen.min(axis=0), screen.max(axis=0)
        span = max(float(hi[0] - lo[0]), float(hi[1] - lo[1]), 1e-9)
        self.scale = (PANEL_PX - 2 * MARGIN_PX) / span
        self.centre = 0.5 * (lo + hi)

    @staticmethod
    def screen(points):
        p = np.asarray(points, dtype=float)
        p = p.reshape(-1, p.shape[-1])
        if p.shape[1] == 2:  # a point of the card's plane
            p = np.c_[p, np.zeros(len(p))]
        tilt = math.radians(TILT_DEGREES)
        return np.c_[p[:, 0], p[:, 1] * math.cos(tilt) + p[:, 2] * math.sin(tilt)]

    @staticmethod
    def depth(points):
        p = np.asarray(points, dtype=float).reshape(-1, 3)
        tilt = math.radians(TILT_DEGREES)
        return p[:, 2] * math.cos(tilt) - p[:, 1] * math.sin(tilt)

    def pixels(self, points, left=0):
        """(N, 2) float pixel coordinates."""
        q = self.screen(points)
        x = left + PANEL_PX / 2 + (q[:, 0] - self.centre[0]) * self.scale
        y = HEADER_PX + PANEL_PX / 2 - (q[:, 1] - self.centre[1]) * self.scale
        return np.c_[x, y]

    def __call__(self, points, left=0):
        return [(float(a), float(b)) for a, b in self.pixels(points, left)]


def _render(image, view, polygons, colours, left, outline):
    """Draws planar `polygons` (each Kx3, card mm) into the panel at `left` with a z-buffer:
    each pixel shows the polygon nearest the camera there, its depth from the polygon's plane,
    so folded patches hide what is behind them whatever their order. Region borders are
    outlined with `outline` (None: not); polygons seen edge-on are drawn as lines."""
    from PIL import Image, ImageDraw

    width, height = image.size
    zbuffer = np.full((height, PANEL_PX), -np.inf)
    ids = np.full((height, PANEL_PX), -1, dtype=np.int64)
    edge_on = []
    for i, polygon in enumerate(polygons):
        if len(polygon) < 3:
            continue
        pixels = view.pixels(polygon, 0)
        depth = view.depth(polygon)
        x0, y0 = np.floor(pixels.min(axis=0)).astype(int)
        x1, y1 = np.ceil(pixels.max(axis=0)).astype(int) + 1
        x0, y0, x1, y1 = max(x0, 0), max(y0, 0), min(x1, PANEL_PX), min(y1, height)
        doubled = np.sum(
            pixels[:, 0] * np.roll(pixels[:, 1], -1) - np.roll(pixels[:, 0], -1) * pixels[:, 1]
        )
        if abs(doubled) < 2.0 or x1 <= x0 or y1 <= y0:  # under a pixel of area: edge-on
            edge_on.append(i)
            continue
        mask = Image.new("1", (x1 - x0, y1 - y0), 0)
        ImageDraw.Draw(mask).polygon([(float(a - x0), float(b - y0)) for a, b in pixels], fill=1)
        inside = np.asarray(mask, dtype=bool)
        # The polygon is planar: its depth is affine in the pixel coordinates.
        system = np.c_[pixels, np.ones(len(pixels))]
        (a, b, c), *_ = np.linalg.lstsq(system, depth, rcond=None)
        rows, cols = np.nonzero(inside)
        z = a * (cols + x0 + 0.5) + b * (rows + y0 + 0.5) + c
        current = zbuffer[rows + y0, cols + x0]
        nearer = z > current
        zbuffer[rows[nearer] + y0, cols[nearer] + x0] = z[nearer]
        ids[rows[nearer] + y0, cols[nearer] + x0] = i
    palette = np.array([BACKGROUND] + [tuple(c) for c in colours], dtype=np.uint8)
    picture = palette[ids + 1]
    if outline is not None:
        border = np.zeros_like(ids, dtype=bool)
        border[:, 1:] |= ids[:, 1:] != ids[:, :-1]
        border[1:, :] |= ids[1:, :] != ids[:-1, :]
        picture[border] = outline
    drawn = np.asarray(image).copy()
    region = drawn[:, left : left + PANEL_PX]
    covered = ids >= 0
    if outline is not None:
        covered |= border
    region[covered] = picture[covered]
    image.paste(Image.fromarray(drawn))
    draw = ImageDraw.Draw(image)
    for i in edge_on:
        draw.line(view(np.vstack([polygons[i], polygons[i][:1]]), left), fill=outline or BONE)


def _paint_flat(draw, view, triangles):
    """The character's mesh projected on the card's plane (as its paths are), far triangles
    first: small triangles, so the painter's order is enough."""
    depth = triangles[:, :, 2].mean(axis=1)
    for i in np.argsort(depth, kind="stable"):
        draw.polygon(view(triangles[i][:, :2], PANEL_PX), fill=_shade(MESH, _normal(triangles[i])))


def write_movie(path, scaffold, character, chains=(), title="", count=FRAMES):
    """Writes the GIF to `path` and returns (path, frames, (width, height)). `character` is
    character_frames(...) of the same `count` (the right half), `chains` the ChainReports whose
    target and achieved paths are drawn faintly, with the moving points on them."""
    from PIL import Image, ImageDraw, ImageFont

    cards = card_frames(scaffold, count)
    people = list(character)
    if len(people) != len(cards):
        raise ValueError(f"character: {len(people)} frames, must be {len(cards)} as the card's")
    paths = [
        (
            np.asarray(c.target, dtype=float).reshape(-1, 2),
            np.asarray(c.achieved, dtype=float).reshape(-1, 2),
            np.asarray(c.s, dtype=float),
        )
        for c in chains
    ]
    everything = [o for _, outlines, _ in cards for o in outlines]
    everything += [np.array(seg) for _, segments, _ in people for seg in segments]
    everything += [np.c_[p, np.zeros(len(p))] for t, a, _ in paths for p in (t, a) if len(p)]
    view = _View(np.vstack(everything))
    font = ImageFont.load_default()
    size = (2 * PANEL_PX, PANEL_PX + HEADER_PX)
    images = []
    for k, ((angle, outlines, card), (frame, segments, triangles)) in enumerate(zip(cards, people)):
        s = k / max(count - 1, 1)
        image = Image.new("RGB", size, BACKGROUND)
        draw = ImageDraw.Draw(image)
        for left in (0, PANEL_PX):
            for target, achieved, _ in paths:
                if len(target) > 1:
                    draw.line(view(target, left), fill=PATH, width=1)
        colours = [
            _shade(CARD if i in card else PAPER, _normal(outline))
            for i, outline in enumerate(outlines)
        ]
        _render(image, view, outlines, colours, 0, EDGE)
        draw = ImageDraw.Draw(image)
        if triangles is not None and len(triangles):
            _paint_flat(draw, view, triangles)
        for a, b in segments:  # on the card's plane, where its paths are measured
            draw.line(view(np.array([a, b])[:, :2], PANEL_PX), fill=BONE, width=3)
        for j, (target, achieved, samples) in enumerate(paths):
            colour = POINT_COLOURS[j % len(POINT_COLOURS)]
            for points, left in ((achieved, 0), (target, PANEL_PX)):
                if len(points) == len(samples) and len(points):
                    x = [np.interp(s, samples, points[:, d]) for d in (0, 1)]
                    ((px, py),) = view(np.array([x]), left)
                    draw.ellipse((px - 4, py - 4, px + 4, py + 4), fill=colour, outline=EDGE)
        draw.line([(PANEL_PX, HEADER_PX), (PANEL_PX, size[1])], fill=EDGE, width=1)
        header = f"{title}  fold {angle:5.1f} deg   animation frame {frame:6.2f}"
        draw.text((MARGIN_PX, 8), header.strip(), fill=(0, 0, 0), font=font)
        images.append(image.convert("P", palette=Image.ADAPTIVE, colors=128))
    durations = [FRAME_MS] * (len(images) - 1) + [HOLD_MS]
    images[0].save(
        path, save_all=True, append_images=images[1:], duration=durations, loop=0, optimize=False
    )
    return path, len(images), size
