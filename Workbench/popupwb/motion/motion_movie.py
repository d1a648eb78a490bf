"""motion.gif of `popup animate`: the card opening from closed (0°) to open flat (180°), side by
side with the character's animation over the chosen frames, frame k of the movie at the fold
angle θ = 180°·s and the animation frame first + s·(last − first), s = k / (FRAMES − 1) (the
pairing the design is made for, docs/MATH.md "Motion targets").

Left, the card: the simulated scaffold (popupcore.simulate_fold from the design state) posed at θ,
seen by a camera above the open card (card x to the right, y up: the view the target paths are
measured in) leaning TILT_DEGREES toward its front edge, so what stands up shows; each patch
filled through a z-buffer with the artwork its sheet prints (movie_card: the body on the pages,
each limb on its mechanism's moving parts) over the paper, shaded by its normal.
Right, the character: its bones (popupcore.forward_kinematics, fractional frames interpolated) and,
when it has one, its skinned mesh (popupcore.posed_mesh, drawn by popupcore.render_view), mapped
to the card by animation_to_card and projected the same way. Both halves share one scale and the
faint target paths, so the mechanisms' points (left) and the end effectors (right) can be
followed together.

Deterministic: fixed frame count, sizes, colours and Pillow's built-in font, one palette for all
frames; no timestamps.
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
PALETTE_COLOURS = 128
PALETTE_SAMPLES = 7  # frames, evenly spaced, the shared palette is chosen from
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
AMBIENT = 0.55
TILT_DEGREES = 30.0  # the camera above the open card, leaning toward its front edge (y = 0)


class MovieError(ValueError):
    """The fold could not be simulated over the whole range."""


def card_frames(scaffold, count=FRAMES):
    """[(θ degrees, [patch outline Kx3], card patch indices, (rotations n x 3 x 3,
    translations n x 3) of the patches from the design state)] from closed to open, by
    simulating the scaffold from its design state (180°) to 0 at `count` angles; MovieError when
    the simulation stops early (a design that locks)."""
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
        poses = (np.asarray(state.rotations), np.asarray(state.translations).reshape(-1, 3))
        frames.append((math.degrees(angle), outlines, card, poses))
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
    # The still nodes above the character (a glTF or FBX armature node at the file's origin) are
    # not drawn: a bone from the hips to the origin is no part of the character.
    above = set()
    parent = parents[popupcore.character_root(animation)] if parents else -1
    while parent >= 0:
        above.add(parent)
        parent = parents[parent]
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
        segments = [
            (joints[p], joints[b]) for b, p in enumerate(parents) if p >= 0 and p not in above
        ]
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
        return np.stack([p[:, 0], p[:, 1] * math.cos(tilt) + p[:, 2] * math.sin(tilt)], axis=1)

    @staticmethod
    def towards_eye():
        """The depth of a card point X toward the camera is towards_eye() . X."""
        tilt = math.radians(TILT_DEGREES)
        return np.array([0.0, -math.sin(tilt), math.cos(tilt)])

    def affine(self, left=0):
        """(A 2x3, b): the pixel of a card point X is A X + b."""
        tilt = math.radians(TILT_DEGREES)
        a = self.scale * np.array([[1.0, 0.0, 0.0], [0.0, -math.cos(tilt), -math.sin(tilt)]])
        b = np.array(
            [
                left + PANEL_PX / 2 - self.centre[0] * self.scale,
                HEADER_PX + PANEL_PX / 2 + self.centre[1] * self.scale,
            ]
        )
        return a, b

    def pixels(self, points, left=0):
        """(N, 2) float pixel coordinates."""
        q = self.screen(points)
        x = left + PANEL_PX / 2 + (q[:, 0] - self.centre[0]) * self.scale
        y = HEADER_PX + PANEL_PX / 2 - (q[:, 1] - self.centre[1]) * self.scale
        return np.stack([x, y], axis=1)

    def __call__(self, points, left=0):
        return [(float(a), float(b)) for a, b in self.pixels(points, left)]


def _draw_card(canvas, view, outlines, card, poses, artwork):
    """The card at one fold angle into the left panel of `canvas` (an RGB array); the patches
    seen edge-on, to be drawn as lines."""
    from popupwb.motion.movie_card import newell_normals, paint_card

    normals = newell_normals(outlines)
    light = LIGHT / np.linalg.norm(LIGHT)
    lengths = np.linalg.norm(normals, axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        lit = np.where(lengths > 0, np.abs(normals @ light) / lengths, 0.5)
    shades = AMBIENT + (1.0 - AMBIENT) * lit
    base = np.array([CARD if i in card else PAPER for i in range(len(outlines))]).reshape(-1, 3)
    colours = np.clip(np.rint(base * shades[:, None]), 0, 255).astype(np.uint8)
    printed = (artwork, shades, *poses) if artwork is not None else None
    picture, covered, (x0, y0), edge_on = paint_card(
        view, outlines, normals, colours, (PANEL_PX, canvas.shape[0]), EDGE, printed
    )
    region = canvas[y0 : y0 + picture.shape[0], x0 : x0 + picture.shape[1]]
    region[covered] = picture[covered]
    return edge_on


def _draw_mesh(canvas, view, triangles):
    """The character's mesh projected on the card's plane (as its paths are) into the right
    panel of `canvas`, nearest the camera on top (popupcore.render_view's z-buffer)."""
    from popupwb.core import popupcore

    tilt = math.radians(TILT_DEGREES)
    points = np.asarray(triangles, dtype=float).reshape(-1, 3)
    # On the card's plane seen by the camera: (x, y cos t); z orders what lies over what.
    flat = np.stack([points[:, 0], points[:, 1] * math.cos(tilt), points[:, 2]], axis=1)
    faces = np.arange(len(flat), dtype=np.int32).reshape(-1, 3)
    rgba = popupcore.render_view(
        [(flat, faces, MESH / 255.0)],
        [],
        towards_eye=(0.0, 0.0, 1.0),
        up=(0.0, 1.0, 0.0),
        centre=(float(view.centre[0]), float(view.centre[1]), 0.0),
        mm_per_pixel=1.0 / view.scale,
        width=PANEL_PX,
        height=PANEL_PX,
        light=tuple(LIGHT),
        ambient=AMBIENT,
        edge_px=0.0,
    )
    region = canvas[HEADER_PX : HEADER_PX + PANEL_PX, PANEL_PX : 2 * PANEL_PX]
    drawn = rgba[..., 3] > 0
    region[drawn] = rgba[..., :3][drawn]


def _printed_artwork(scaffold, printed, view):
    """movie_card.CardArtwork of the printed parts, None without any or when they cannot be
    rendered (the sheets, which print them, say why)."""
    from popupwb.motion.movie_card import pixels_per_mm, render_card_artwork

    if not printed:
        return None
    try:
        return render_card_artwork(scaffold, printed, pixels_per_mm(view.scale))
    except ValueError:  # popupcore.DesignError: a mesh the core cannot render
        return None


def _one_palette(frames):
    """The frames as "P" images sharing one palette, chosen from PALETTE_SAMPLES of them: the
    GIF's frames compare and compress cheaply and the colours do not flicker."""
    from PIL import Image

    picks = np.unique(np.linspace(0, len(frames) - 1, PALETTE_SAMPLES).round().astype(int))
    sample = Image.fromarray(np.concatenate([np.asarray(frames[k]) for k in picks], axis=0))
    palette = sample.quantize(PALETTE_COLOURS, method=Image.Quantize.FASTOCTREE)
    return [frame.quantize(palette=palette, dither=Image.Dither.NONE) for frame in frames]


def write_movie(path, scaffold, character, chains=(), title="", count=FRAMES, printed=()):
    """Writes the GIF to `path` and returns (path, frames, (width, height)). `character` is
    character_frames(...) of the same `count` (the right half), `chains` the ChainReports whose
    target and achieved paths are drawn faintly, with the moving points on them, `printed` the
    character as the card prints it (design_from_motion.printed_character: the body, then the
    limbs), drawn on the card's patches; () draws the paper alone."""
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
    everything = [o for _, outlines, _, _ in cards for o in outlines]
    everything += [np.array(seg) for _, segments, _ in people for seg in segments]
    everything += [np.c_[p, np.zeros(len(p))] for t, a, _ in paths for p in (t, a) if len(p)]
    view = _View(np.vstack(everything))
    artwork = _printed_artwork(scaffold, printed, view)
    font = ImageFont.load_default()
    size = (2 * PANEL_PX, PANEL_PX + HEADER_PX)
    background = Image.new("RGB", size, BACKGROUND)
    draw = ImageDraw.Draw(background)
    for left in (0, PANEL_PX):  # the same in every frame
        for target, achieved, _ in paths:
            if len(target) > 1:
                draw.line(view(target, left), fill=PATH, width=1)
    background = np.asarray(background)
    images = []
    for k, ((angle, outlines, card, poses), (frame, segments, triangles)) in enumerate(
        zip(cards, people)
    ):
        s = k / max(count - 1, 1)
        canvas = background.copy()
        edge_on = _draw_card(canvas, view, outlines, card, poses, artwork)
        if triangles is not None and len(triangles):
            _draw_mesh(canvas, view, triangles)
        image = Image.fromarray(canvas)
        draw = ImageDraw.Draw(image)
        for i in edge_on:
            draw.line(view(np.vstack([outlines[i], outlines[i][:1]]), 0), fill=EDGE)
        if segments:  # on the card's plane, where its paths are measured
            ends = view.pixels(np.array(segments)[:, :, :2].reshape(-1, 2), PANEL_PX)
            for a, b in ends.reshape(-1, 2, 2).tolist():
                draw.line([tuple(a), tuple(b)], fill=BONE, width=3)
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
        images.append(image)
    images = _one_palette(images)
    durations = [FRAME_MS] * (len(images) - 1) + [HOLD_MS]
    images[0].save(
        path, save_all=True, append_images=images[1:], duration=durations, loop=0, optimize=False
    )
    return path, len(images), size


def write_result_movie(path, result, animation, up, title=""):
    """write_movie of a popupcore.MotionResult designed from `animation`: the card as it is
    printed (design_from_motion.printed_character) beside the character over the frames shown,
    standing where the targets are when its walk was taken out (`up`: the view's up). As
    `popup animate` writes motion.gif and the From-animation panel plays it."""
    from popupwb.motion.design_from_motion import printed_character

    targets = result.targets
    character = character_frames(
        animation,
        targets.animation_to_card,
        targets.first_frame,
        targets.last_frame,
        in_place_up=tuple(up) if targets.in_place else None,
    )
    return write_movie(
        path,
        result.scaffold,
        character,
        result.chains,
        title=title,
        printed=printed_character(animation, result),
    )
