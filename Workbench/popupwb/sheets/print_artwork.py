"""Artwork on the print layer, for print-then-cut: the model's appearance rendered onto each patch
(popupcore.render_artwork) and placed on that patch's flat outline on its sheet.

The writers take `artwork` = {patch id: image}, where an image is any object with
    rgba          height x width x 4 uint8 array, row 0 at the top (largest v), straight alpha;
    origin_uv     (u, v) of the image's lower-left corner in the patch's own frame, mm;
    mm_per_pixel  the side of a pixel, mm;
    back_side     True when rendered from the side opposite the patch's normal (default False).
popupcore.PatchArtwork is one. Each flat patch's `to_sheet` (docs/SHEET_FORMAT.md) takes the patch
frame onto the sheet; where it is a reflection (the patch's back side faces up) the image is
mirrored with it, and only an image of that side belongs there. `render_sheet_artwork` renders
every laid-out patch from its printed side:

    sheet_set = layout(scaffold, paper="A3")
    artwork = render_sheet_artwork(mesh, scaffold, sheet_set, pixels_per_mm=300 / 25.4)
    export_sheets(sheet_set, "out/sheets", artwork=artwork)

No FreeCAD needed.
"""

import base64
import io
import math
from dataclasses import dataclass
from typing import Tuple

import numpy

from .sheet_set import pieces_by_sheet

Affine = Tuple[Tuple[float, float, float], Tuple[float, float, float]]


@dataclass(frozen=True)
class PlacedArtwork:
    """One patch's image where it goes on its sheet."""

    piece: str
    patch: object  # popupcore.FlatPatch
    rgba: numpy.ndarray  # height x width x 4 uint8
    size_mm: Tuple[float, float]  # width, height
    # Image mm (x right, y up, origin at its lower-left corner) onto the sheet:
    # ((a, c, e), (b, d, f)) with sheet = (a x + c y + e, b x + d y + f).
    image_to_sheet: Affine


def _side(back):
    return "back" if back else "normal"


def _checked_rgba(patch_id, image):
    # PatchArtwork.rgba copies the image out of the core on every read; the SVG and the PDF both
    # place it, so the copy is kept on the image (a few MB each at 300 dpi).
    rgba = getattr(image, "_rgba_array", None)
    if rgba is None:
        rgba = numpy.asarray(image.rgba)
        try:
            image._rgba_array = rgba
        except AttributeError:  # an image without a __dict__: read again next time
            pass
    if rgba.dtype != numpy.uint8 or rgba.ndim != 3 or rgba.shape[2] != 4 or 0 in rgba.shape:
        raise ValueError(
            f"artwork for patch {patch_id}: rgba is {rgba.dtype} of shape {rgba.shape}, must be "
            "uint8 of shape (height, width, 4) with height, width >= 1"
        )
    return rgba


def _checked_number(patch_id, name, value, positive=False):
    value = float(value)
    if not math.isfinite(value) or (positive and value <= 0):
        raise ValueError(
            f"artwork for patch {patch_id}: {name} = {value!r}, must be a finite number"
            + (" > 0" if positive else "")
        )
    return value


def place(piece_id, patch, image):
    """The PlacedArtwork of `image` on the flat `patch` of piece `piece_id`; ValueError naming the
    patch when the image is malformed, the sheet set has no frame for the patch, or the image
    shows the side that faces down on the sheet."""
    rgba = _checked_rgba(patch.id, image)
    step = _checked_number(patch.id, "mm_per_pixel", image.mm_per_pixel, positive=True)
    u0, v0 = (_checked_number(patch.id, "origin_uv", value) for value in image.origin_uv)
    if patch.to_sheet is None:
        raise ValueError(
            f"artwork for patch {patch.id} ({patch.name}): the sheet set gives no to_sheet for "
            "it (written by an older PopUp); lay the sheets out again"
        )
    back = bool(getattr(image, "back_side", False))
    if back == patch.normal_side_up():
        raise ValueError(
            f"artwork for patch {patch.id} ({patch.name}) shows its {_side(back)} side, but "
            f"{piece_id} has its {_side(not back)} side up on the sheet: render it with "
            f"back_side={not back}"
        )
    (a, c, tx), (b, d, ty) = patch.to_sheet.tolist()
    image_to_sheet = (
        (a, c, a * u0 + c * v0 + tx),
        (b, d, b * u0 + d * v0 + ty),
    )
    height, width = rgba.shape[:2]
    return PlacedArtwork(piece_id, patch, rgba, (width * step, height * step), image_to_sheet)


def place_artwork(sheet_set, artwork):
    """{sheet index: [PlacedArtwork, ...]} for `artwork` {patch id: image} on the
    popupcore.SheetSet `sheet_set`, in the order of the pieces and their patches, leaving out
    images that are transparent all over; ValueError for a patch id the sheets do not have, or
    as `place`."""
    if not artwork:
        return {}
    remaining = {int(patch_id): image for patch_id, image in artwork.items()}
    placed = {}
    for index, pieces in enumerate(pieces_by_sheet(sheet_set)):
        for piece in pieces:
            for patch in piece.patches:
                if patch.id in remaining:
                    item = place(piece.id, patch, remaining.pop(patch.id))
                    if item.rgba[..., 3].any():  # an image with nothing on it is left out
                        placed.setdefault(index, []).append(item)
    if remaining:
        known = sorted(patch.id for piece in sheet_set.pieces for patch in piece.patches)
        raise ValueError(
            f"artwork for patch {min(remaining)}: the sheets have no such patch (they have "
            f"{', '.join(map(str, known)) or 'none'})"
        )
    return placed


# A limb is all that prints on its patches: it counts at any depth in front of them and this far
# behind (the raised platform of a floating layer stands above the limb it shows), in mm.
LIMB_BEHIND_MM = 1000.0
# The pages of an animated card print the body as seen from the front at any depth, in front of
# them or behind: the character lies across the open card's plane, as thick as it is (a Blender
# walker spans 29 mm behind the page to 15 mm in front; a fitted model's page looks 1 mm behind
# and 10 mm in front).
PAGE_ROLES = ("ground", "backdrop")


def body_windows(patches, options):
    """[(patches, options)]: how the body of an animated character prints on `patches` (those
    that carry no limb): the pages at any depth, the others as a fitted model's."""
    pages = [p for p in patches if str(p.role) in PAGE_ROLES]
    others = [p for p in patches if str(p.role) not in PAGE_ROLES]
    pages_window = dict(options, depth=float("inf"), behind=LIMB_BEHIND_MM)
    return [(pages, pages_window), (others, dict(options))]


def _patch_sides(sheet_set):
    """{patch id: whether its sheet prints its back side} of every laid-out patch."""
    sides = {}
    for piece in sheet_set.pieces:
        for flat in piece.patches:
            if flat.to_sheet is None:
                raise ValueError(
                    f"patch {flat.id} ({flat.name}): the sheet set gives no to_sheet for it "
                    "(written by an older PopUp); lay the sheets out again"
                )
            sides[flat.id] = not flat.normal_side_up()
    return sides


def _render_on(artwork, mesh, patches, sides, options):
    """Renders `mesh` on those `patches` the sheets lay out, each from its printed side."""
    from popupwb.core import popupcore

    for back in (False, True):
        chosen = [p for p in patches if sides.get(p.id) is back]
        if chosen:
            for art in popupcore.render_artworks(mesh, chosen, back_side=back, **options):
                artwork[art.patch] = art


def render_sheet_artwork(mesh, scaffold, sheet_set, limbs=None, **options):
    """{patch id: popupcore.PatchArtwork} for every patch the sheet set lays out, each rendered
    from the side its sheet prints (back_side where the flat patch's back faces up), the
    texture read once per side. `mesh`: a popupcore.ModelMesh in card mm; `scaffold`: the
    design at its design state; `sheet_set`: the popupcore.SheetSet export.layout gives;
    `limbs`: model_source.PrintedLimb of an animated character, each printed alone on its
    patches (at any depth: LIMB_BEHIND_MM), `mesh` (the body) on all the others (the pages at
    any depth, body_windows); None for a card not animated; `options`: the
    keywords of popupcore.render_artworks (pixels_per_mm, depth, behind, light, ambient,
    max_pixels). popupcore.DesignError names a bad option or model."""
    if "back_side" in options:
        raise ValueError("render_sheet_artwork chooses back_side per patch from the sheet set")
    sides = _patch_sides(sheet_set)
    artwork = {}
    limb_patches = set()
    for limb in limbs or ():
        patches = [p for p in scaffold.patches if p.name in limb.patches]
        limb_patches.update(p.id for p in patches)
        window = dict(options, depth=float("inf"), behind=LIMB_BEHIND_MM)
        _render_on(artwork, limb.mesh, patches, sides, window)
    body = [p for p in scaffold.patches if p.id not in limb_patches]
    for patches, window in body_windows(body, options) if limbs is not None else [(body, options)]:
        _render_on(artwork, mesh, patches, sides, window)
    return artwork


def source_model_artwork(mesh, scaffold, sheet_set, owner, run=None, limbs=None):
    """render_sheet_artwork of a card's source model (and its limbs), as the GUI export and
    `popup sheet` both print it; `run(function, *args)` runs the rendering (progress.run in the
    GUI: progress and cancel), else it runs here. ValueError "<owner>: artwork of the source
    model: <why>" when the model cannot be rendered."""
    run = run or (lambda function, *args: function(*args))
    try:
        return run(render_sheet_artwork, mesh, scaffold, sheet_set, limbs)
    except ValueError as error:  # DesignError: the model cannot be rendered
        why = " ".join(str(error).split())
        raise ValueError(f"{owner}: artwork of the source model: {why}") from None


def artwork_warnings(artwork):
    """The distinct warnings of rendered images {patch id: PatchArtwork} (each image carries its
    model's: a texture that cannot be read, so the model prints shaded), in order."""
    distinct = {}
    for art in (artwork or {}).values():
        for d in getattr(art, "warnings", None) or []:
            distinct.setdefault(d["message"], d)
    return list(distinct.values())


def pil_image(rgba):
    """The image as a PIL RGBA image (reportlab draws it, keeping the alpha as a soft mask)."""
    from PIL import Image

    return Image.fromarray(numpy.ascontiguousarray(rgba), "RGBA")


def png_data_uri(rgba):
    """The image as a data: URI of a PNG, for an SVG <image>."""
    buffer = io.BytesIO()
    # zlib level 4 rather than PIL's 6: the same pixels, 0-9 % larger, 2.4-3.5 times faster
    # (the SVG's images were a third of `popup fit`'s sheets stage on a scanned model); levels
    # below 4 use zlib's fast matcher and quadruple flat-coloured artwork.
    pil_image(rgba).save(buffer, format="PNG", compress_level=4)
    return "data:image/png;base64," + base64.b64encode(buffer.getvalue()).decode("ascii")
