"""The matplotlib preview `popup fit` drew before the core's rasteriser (popupcore.render_view,
Workbench/popupwb/fitting/preview.py), kept unchanged as the baseline bench/fit_e2e_bench.py
times the new preview against, on the same model in the same run. Not used by the workbench."""

import numpy as np

IMAGE_SIZE_PX = (1600, 800)
DPI = 100
MAX_MODEL_TRIANGLES = 40000  # beyond this every k-th triangle is drawn: a preview, not a render
LIGHT = np.array([0.6, -0.3, 0.75])
MODEL_COLOUR = np.array([0.55, 0.65, 0.85])
PAPER_COLOUR = np.array([0.95, 0.88, 0.70])
CARD_COLOUR = np.array([0.85, 0.85, 0.85])
CAMERA = {"elev": 28.0, "azim": 25.0}  # degrees: from the +x side, a little to the right


def _shaded(polygons, colour):
    """One RGB per polygon: `colour` lit by LIGHT through the polygon's normal (both sides)."""
    light = LIGHT / np.linalg.norm(LIGHT)
    colours = []
    for polygon in polygons:
        p = np.asarray(polygon, dtype=float)
        normal = np.zeros(3)
        for i in range(len(p)):  # Newell's normal: fine for any planar polygon
            a, b = p[i], p[(i + 1) % len(p)]
            normal += np.cross(a, b)
        length = np.linalg.norm(normal)
        shade = abs(normal @ light) / length if length > 0 else 0.5
        colours.append(np.clip(colour * (0.45 + 0.55 * shade), 0.0, 1.0))
    return colours


def _set_box(axes, lo, hi):
    centre, half = 0.5 * (lo + hi), 0.5 * float(np.max(hi - lo))
    axes.set_xlim(centre[0] - half, centre[0] + half)
    axes.set_ylim(centre[1] - half, centre[1] + half)
    axes.set_zlim(centre[2] - half, centre[2] + half)
    axes.set_box_aspect((1, 1, 1))
    axes.view_init(**CAMERA)
    axes.set_xlabel("x (mm)")
    axes.set_ylabel("y (mm)")
    axes.set_zlabel("z (mm)")


def write_preview(path, model_vertices, model_triangles, patches, card_patches=(), title=""):
    """Writes the side-by-side PNG to `path`.

    `model_vertices` (Nx3) and `model_triangles` (Mx3) are the model in the card's frame (mm);
    `patches` the pop-up's patch outlines (each Kx3) at the design state, `card_patches` the
    indices of the card's own pages among them (drawn grey)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    vertices = np.asarray(model_vertices, dtype=float).reshape(-1, 3)
    triangles = np.asarray(model_triangles, dtype=np.int64).reshape(-1, 3)
    if len(triangles) > MAX_MODEL_TRIANGLES:
        triangles = triangles[:: int(np.ceil(len(triangles) / MAX_MODEL_TRIANGLES))]
    model_polygons = vertices[triangles]
    patch_polygons = [np.asarray(p, dtype=float).reshape(-1, 3) for p in patches]

    everything = np.vstack([vertices] + patch_polygons)
    lo, hi = everything.min(axis=0), everything.max(axis=0)

    figure = Figure(figsize=(IMAGE_SIZE_PX[0] / DPI, IMAGE_SIZE_PX[1] / DPI), dpi=DPI)
    FigureCanvasAgg(figure)
    if title:
        figure.suptitle(title)

    # Collections are depth-sorted as wholes: the card's centre is nearer the camera than the
    # model's, so sorted it would hide the model standing on it. Drawn in order instead: the card
    # first, the model over it (seen from above, nothing of the card is in front of the model).
    left = figure.add_subplot(1, 2, 1, projection="3d", computed_zorder=False)
    left.set_title("model (in the card's frame, on the open card)")
    pages = [patch_polygons[i] for i in card_patches]
    if pages:  # the card under the model, as on the right: the two halves compare at a glance
        left.add_collection3d(
            Poly3DCollection(
                pages, facecolors=[CARD_COLOUR] * len(pages), edgecolors=(0.2, 0.2, 0.2)
            )
        )
    left.add_collection3d(
        Poly3DCollection(
            list(model_polygons),
            facecolors=_shaded(model_polygons, MODEL_COLOUR),
            edgecolors="none",
        )
    )
    _set_box(left, lo, hi)

    right = figure.add_subplot(1, 2, 2, projection="3d")
    right.set_title("pop-up at the design state (open flat, 180°)")
    card = set(card_patches)
    colours = _shaded(patch_polygons, PAPER_COLOUR)
    for i in card:
        colours[i] = CARD_COLOUR
    right.add_collection3d(
        Poly3DCollection(
            patch_polygons, facecolors=colours, edgecolors=(0.2, 0.2, 0.2), linewidths=0.6
        )
    )
    _set_box(right, lo, hi)

    figure.tight_layout()
    figure.savefig(path)
    return path


def scaffold_outlines(scaffold):
    """Outer loops of every patch of a popupcore.Scaffold at its design state, and the indices of
    the card's pages among them."""
    outlines = [np.asarray(patch.outer, dtype=float).reshape(-1, 3) for patch in scaffold.patches]
    ids = [patch.id for patch in scaffold.patches]
    card = [ids.index(i) for i in (scaffold.ground, scaffold.backdrop) if i in ids]
    return outlines, card
