"""An animated character is printed as the card shows it (thesis §6.4, Fig 6.9): each limb a
mechanism carries is printed on that mechanism's moving parts alone, and the body on the pages
without it. On the skinned figure made by tools/blender_rig.py, through `popup animate` (the
document and the sheets it writes), checked against the posed mesh (popupcore.posed_mesh, placed
by the card's AnimationToCard) and by re-reading the written SVG."""

import base64
import io
import os

import numpy as np
import pytest

from cli_runner import popup
from test_cli_sheet_artwork import print_layer

FIGURE = os.path.join(os.environ["POPUP_SOURCE_DIR"], "tests", "data", "animations", "figure.glb")


@pytest.fixture(scope="module")
def animated(tmp_path_factory):
    """The folder `popup animate` wrote for the figure (design.FCStd, sheets/)."""
    out = tmp_path_factory.mktemp("figure") / "out"
    proc = popup("animate", FIGURE, "--out", str(out))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return out


@pytest.fixture
def card_doc(animated, freecad):
    doc = freecad.openDocument(str(animated / "design.FCStd"))
    yield doc
    freecad.closeDocument(doc.Name)


def _mesh_points(obj, card):
    to_card = card.Placement.inverse().toMatrix()
    return np.array([tuple(to_card.multVec(p)) for p in obj.Mesh.Topology[0]], dtype=float)


def _posed_in_card(card):
    """The figure's mesh at the card's last frame, in the card's frame: what the split splits."""
    import popupcore

    animation = popupcore.load_animation(FIGURE)
    posed = popupcore.posed_mesh(animation, float(card.LastFrame))
    matrix = np.array(card.AnimationToCard.A, dtype=float).reshape(4, 4)
    return np.asarray(posed.vertices) @ matrix[:3, :3].T + matrix[:3, 3], len(posed.triangles)


def _limbed(doc):
    return [o for o in doc.Objects if getattr(o, "LimbModel", None) is not None]


def test_every_triangle_is_printed_once_and_each_limb_is_its_chains(card_doc):
    card = card_doc.getObject("Card")
    vertices, triangles = _posed_in_card(card)
    mechanisms = _limbed(card_doc)
    # The figure's design moves a hand and a foot and lifts the other hand on a layer.
    assert len(mechanisms) >= 2
    body = card.SourceModel
    counts = [body.Mesh.CountFacets] + [m.LimbModel.Mesh.CountFacets for m in mechanisms]
    assert sum(counts) == triangles
    assert min(counts) > 0
    for m in mechanisms:
        # The limb is the posed mesh's own vertices, unmoved (FreeCAD keeps a mesh in single
        # precision: 1e-3 mm), and its mechanism says whose.
        points = _mesh_points(m.LimbModel, card)
        assert _distances(points, vertices).max() < 1e-3, m.Name
        assert m.Chain and m.Chain in m.LimbModel.Label
        assert set(m.LimbParts) <= {"wing_arm", "TG", "TB", "M", "tread"}
    # The body keeps only the vertices its own triangles use: most of a limb's are not among
    # them (the limbs meet the torso only where they join it).
    body_points = _mesh_points(body, card)
    for m in mechanisms:
        shared = _distances(_mesh_points(m.LimbModel, card), body_points) < 1e-3
        assert shared.mean() < 0.25, m.Name


def _distances(points, others):
    """Each of `points`' distance to the nearest of `others`."""
    return np.sqrt(((points[:, None, :] - others[None, :, :]) ** 2).sum(axis=2)).min(axis=1)


def _images_by_patch(svg_path):
    images, _ = print_layer(svg_path)
    return {int(i.get("id").rsplit("-", 1)[1]): i for i in images}


def _alpha_pixels(image):
    from PIL import Image

    href = image.get("{http://www.w3.org/1999/xlink}href")
    data = base64.b64decode(href.split(",", 1)[1])
    return int(np.count_nonzero(np.asarray(Image.open(io.BytesIO(data)))[..., 3]))


def _design(animated):
    """The card as `popup sheet` reads it (it opens and closes the document itself)."""
    from popupwb.cli import designs

    _, (design,) = designs.load_designs(str(animated / "design.FCStd"), one=True, with_model=True)
    return design


def test_the_sheets_print_each_limb_on_its_moving_part(animated):
    design = _design(animated)
    images = {}
    for svg in sorted((animated / "sheets").glob("sheets*.svg")):
        images.update(_images_by_patch(str(svg)))
    assert len(design.limbs) >= 2
    for limb in design.limbs:
        # Printed on a moving part of its mechanism (of a floating layer's TG and TB, the one
        # that lies over it), and only there.
        ids = [p.id for p in design.scaffold.patches if p.name in limb.patches]
        assert any(i in images and _alpha_pixels(images[i]) > 0 for i in ids), limb.patches


def test_the_pages_print_the_body_without_the_limbs(animated):
    """Rendering the pages with the limbs kept apart covers fewer pixels than with the whole
    posed figure, by about the limbs' own projected area."""
    from popupwb.core import popupcore
    from popupwb.sheets.print_artwork import render_sheet_artwork
    from popupwb.sheets.export import layout

    design = _design(animated)
    assert design.limbs
    sheet_set = layout(design.scaffold)
    whole = popupcore.ModelMesh(
        np.vstack([np.asarray(design.model.vertices)] + [l.mesh.vertices for l in design.limbs]),
        np.vstack(
            [np.asarray(design.model.triangles)]
            + [
                np.asarray(l.mesh.triangles) + offset
                for l, offset in zip(design.limbs, _offsets(design))
            ]
        ),
    )
    split = render_sheet_artwork(design.model, design.scaffold, sheet_set, design.limbs)
    together = render_sheet_artwork(whole, design.scaffold, sheet_set)
    pages = [p.id for p in design.scaffold.patches if p.name in ("Card.ground", "Card.backdrop")]
    split_pixels = sum(split[p].covered_pixels for p in pages)
    together_pixels = sum(together[p].covered_pixels for p in pages)
    assert split_pixels < 0.9 * together_pixels


def _offsets(design):
    offset = len(design.model.vertices)
    out = []
    for limb in design.limbs:
        out.append(offset)
        offset += len(limb.mesh.vertices)
    return out


def test_a_thick_characters_body_prints_on_the_pages_at_any_depth(tmp_path):
    """The Blender walk (tools/blender_capture.py) lies across the open card's plane from 29 mm
    behind the page to 15 mm in front. Wherever a body vertex lies more than 3 mm behind the
    page and is on a page that nothing stands on, the page's artwork has ink: a fitted model's
    window (1 mm behind, 10 mm in front) printed none of the rear leg."""
    from popupwb.sheets.export import layout
    from popupwb.sheets.print_artwork import render_sheet_artwork

    walk = os.path.join(os.path.dirname(FIGURE), "capture_walk.glb")
    out = tmp_path / "walk"
    proc = popup("animate", walk, "--out", str(out), "--view=-1,0,0")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    design = _design(out)
    artwork = render_sheet_artwork(
        design.model, design.scaffold, layout(design.scaffold), design.limbs, pixels_per_mm=2.0
    )
    body = np.asarray(design.model.vertices)
    behind = body[body[:, 2] < -3.0]
    assert len(behind) > 100
    inked = checked = 0
    for page in (p for p in design.scaffold.patches if str(p.role) in ("ground", "backdrop")):
        art = artwork[page.id]
        frame = art.frame
        origin, u, v = (np.asarray(frame[k], dtype=float) for k in ("origin", "u", "v"))
        alpha = np.asarray(art.rgba)[..., 3]
        u0, v0 = art.origin_uv
        step = float(art.mm_per_pixel)
        cols = (((behind - origin) @ u - u0) / step).astype(int)
        rows = len(alpha) - 1 - (((behind - origin) @ v - v0) / step).astype(int)
        inside = (cols >= 0) & (cols < alpha.shape[1]) & (rows >= 0) & (rows < alpha.shape[0])
        checked += int(inside.sum())
        inked += int((alpha[rows[inside], cols[inside]] > 0).sum())
    assert checked > 100 and inked >= 0.9 * checked, (inked, checked)
