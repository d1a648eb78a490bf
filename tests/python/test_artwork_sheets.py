"""Artwork on the cutting sheets (print-then-cut): a coloured model rendered onto the patches of a
box-fold card (popupcore.render_artwork), written into the SVG and PDF print layer, and read
back: each image where its patch lies on the sheet, clipped to the patch's outline, mirrored
with a patch whose back side is printed, with registration marks. No FreeCAD needed."""

import base64
import io
import json
import math
import os
import re
import xml.etree.ElementTree as ElementTree

import ezdxf
import numpy
import pytest
from PIL import Image
from pypdf import PdfReader
from pypdf.generic import ContentStream

import popupcore
from popupwb.sheets.export import export_sheets, layout
from popupwb.sheets.pdf_writer import write_pdf
from popupwb.sheets.print_artwork import render_sheet_artwork
from popupwb.sheets.svg_writer import write_svg

SOURCE_DIR = os.environ["POPUP_SOURCE_DIR"]
SVG = "{http://www.w3.org/2000/svg}"
XLINK = "{http://www.w3.org/1999/xlink}"
PT_PER_MM = 72.0 / 25.4
PIXELS_PER_MM = 2.0

RED, BLUE, GREEN, MAGENTA = (1, 0, 0), (0, 0, 1), (0, 1, 0), (1, 0, 1)
GREY, YELLOW = (0.5, 0.5, 0.5), (1, 1, 0)
# Markers: (centre, colour) on the card's inside (facing +z) and outside (facing -z), and one on
# the box's top. box.json: ground x in [0, 140], y in [0, 200]; the box x in [-30, 30],
# y in [60, 140], 30 mm high (patch 5 is its top on the ground side).
INSIDE = [((100, 30, 0.2), RED), ((100, 170, 0.2), BLUE)]
OUTSIDE = [((100, 30, -0.2), GREEN), ((100, 170, -0.2), MAGENTA)]
ON_TOP = [((8, 75, 30.2), RED)]


def byte_colour(rgb):
    return tuple(round(255 * c) for c in rgb)


def square(centre, half, facing_up):
    """A square around `centre` in a plane z = const, counter-clockwise seen from +z or -z."""
    x, y, z = centre
    corners = [(x - half, y - half, z), (x + half, y - half, z), (x + half, y + half, z)]
    corners.append((x - half, y + half, z))
    return corners if facing_up else corners[::-1]


def box_faces(lo, hi):
    """(corners, colour) of the box's faces, counter-clockwise seen from outside."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    return [
        ([(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)], GREY),  # +z
        ([(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)], YELLOW),  # -y, the front
    ]


@pytest.fixture(scope="module")
def model():
    quads = box_faces((-30, 60, 0), (30, 140, 30))
    quads += [(square(c, 5, True), colour) for c, colour in INSIDE + ON_TOP]
    quads += [(square(c, 5, False), colour) for c, colour in OUTSIDE]
    vertices, triangles, colours = [], [], []
    for corners, colour in quads:
        k = len(vertices)
        vertices += corners
        colours += [colour] * 4
        triangles += [(k, k + 1, k + 2), (k, k + 2, k + 3)]
    mesh = popupcore.ModelMesh(numpy.array(vertices, float), numpy.array(triangles), "markers")
    mesh.colours = numpy.array(colours, float)
    return mesh


@pytest.fixture(scope="module")
def scaffold():
    return popupcore.load_scaffold(
        os.path.join(SOURCE_DIR, "tests", "data", "mechanisms", "box.json")
    )


def flat_patches(sheet_set):
    """{patch id: (piece dict, flat patch dict)}."""
    return {p["id"]: (piece, p) for piece in sheet_set["pieces"] for p in piece["patches"]}


def normal_side_up(flat):
    (a, b, _), (c, d, _) = flat["to_sheet"]
    return a * d - b * c > 0


def render_all(model, scaffold, sheet_set):
    """Artwork for every patch, each rendered from the side its sheet prints."""
    artwork = render_sheet_artwork(model, scaffold, sheet_set, pixels_per_mm=PIXELS_PER_MM)
    flats = flat_patches(json.loads(sheet_set.to_json()))
    assert sorted(artwork) == sorted(flats)
    for patch_id, art in artwork.items():
        assert art.back_side == (not normal_side_up(flats[patch_id][1]))
    return artwork


def on_sheet(flat, art, point):
    """Where the design-state `point` of the patch lands on the sheet: its coordinates in the
    artwork's patch frame, through the flat patch's to_sheet."""
    d = numpy.asarray(point, float) - art.frame["origin"]
    u, v = d @ art.frame["u"], d @ art.frame["v"]
    (a, b, tx), (c, e, ty) = flat["to_sheet"]
    return (a * u + b * v + tx, c * u + e * v + ty)


def inside(loop, point):
    x, y = point
    crossings = 0
    for (x0, y0), (x1, y1) in zip(loop, loop[1:] + loop[:1]):
        if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            crossings += 1
    return crossings % 2 == 1


def path_points(d):
    return [(float(x), float(y)) for x, y in re.findall(r"([-0-9.]+),([-0-9.]+)", d)]


@pytest.fixture(scope="module", params=["front", "back"], ids=["card-inside", "card-outside"])
def written(request, model, scaffold, tmp_path_factory):
    """The box card laid out on A3 with P1 printed on the given side (as sheets.json spells it),
    its artwork, and the files."""
    sheet_set = layout(scaffold, paper="A3", printed_sides={"P1": request.param})
    artwork = render_all(model, scaffold, sheet_set)
    out = tmp_path_factory.mktemp("artwork_" + request.param)
    paths = export_sheets(sheet_set, str(out), artwork=artwork)
    pdf = write_pdf(sheet_set, str(out / "plain.pdf"), artwork=artwork, compress=False)
    with open(paths["sheet_set"]) as f:
        return request.param, json.load(f), artwork, paths, pdf


def visible(artwork):
    return {i: art for i, art in artwork.items() if art.rgba[..., 3].any()}


def svg_images(path):
    """{patch id: (image element, clip path points in sheet mm)} of the SVG's PRINT layer."""
    root = ElementTree.parse(path).getroot()
    height = float(root.get("viewBox").split()[3])
    clips = {c.get("id"): c for c in root.iter(SVG + "clipPath")}
    layer = next(g for g in root.iter(SVG + "g") if g.get("id") == "PRINT")
    found = {}
    for group in layer.findall(SVG + "g"):
        clip = clips[group.get("clip-path")[len("url(#") : -1]]
        points = [(x, height - y) for x, y in path_points(clip.find(SVG + "path").get("d"))]
        image = group.find(SVG + "image")
        found[int(image.get("id").split("-")[-1])] = (image, points)
    return root, height, layer, found


def svg_colour_at(image, height, sheet_point):
    """The colour of the SVG <image>'s pixel under a sheet point (sheet y up)."""
    a, b, c, d, e, f = map(float, re.findall(r"[-0-9.e]+", image.get("transform")))
    x, y = sheet_point[0], height - sheet_point[1]
    det = a * d - b * c
    ix = (d * (x - e) - c * (y - f)) / det  # the transform's inverse
    iy = (-b * (x - e) + a * (y - f)) / det
    href = image.get("href") or image.get(XLINK + "href")
    assert href.startswith("data:image/png;base64,")
    picture = Image.open(io.BytesIO(base64.b64decode(href.split(",", 1)[1]))).convert("RGBA")
    step = float(image.get("width")) / picture.width
    assert float(image.get("height")) == pytest.approx(picture.height * step, abs=1e-6)
    return picture.getpixel((int(ix // step), int(iy // step)))


def test_every_patch_gets_its_image_clipped_to_its_outline(written):
    side, sheet_set, artwork, paths, _ = written
    flats = flat_patches(sheet_set)
    root, height, _, found = svg_images(paths["svg"][0])
    assert len(sheet_set["sheets"]) == 1
    # Every image with something on it; those transparent all over are left out.
    assert sorted(found) == sorted(visible(artwork))
    assert 0 < len(found) < len(artwork)
    for patch_id, (image, clip) in found.items():
        piece, flat = flats[patch_id]
        # The clipPath is the patch's outline on the sheet, vertex for vertex.
        numpy.testing.assert_allclose(clip, flat["outer"], atol=2e-6)
        # The image covers the outline: its placed rectangle holds every outline vertex, and it
        # is the patch's bounding box in its own frame, rounded up to whole pixels.
        art = artwork[patch_id]
        rows, columns = art.rgba.shape[:2]
        a, b, c, d, e, f = map(float, re.findall(r"[-0-9.e]+", image.get("transform")))
        w, h = float(image.get("width")), float(image.get("height"))
        assert (w, h) == pytest.approx((columns / PIXELS_PER_MM, rows / PIXELS_PER_MM))
        corners = [
            (a * x + c * y + e, height - (b * x + d * y + f))
            for x, y in ((0, 0), (w, 0), (w, h), (0, h))
        ]
        for vertex in flat["outer"]:
            assert (
                inside(corners, vertex)
                or min(math.dist(vertex, corner) for corner in corners) < 1e-6
            )
        lo = numpy.min(flat["outer"], axis=0)
        hi = numpy.max(flat["outer"], axis=0)
        assert numpy.all(numpy.min(corners, axis=0) >= lo - 1.0 / PIXELS_PER_MM - 1e-9)
        assert numpy.all(numpy.max(corners, axis=0) <= hi + 1.0 / PIXELS_PER_MM + 1e-9)


def test_markers_land_where_their_patch_lies_on_the_sheet(written, scaffold):
    side, sheet_set, artwork, paths, _ = written
    flats = flat_patches(sheet_set)
    _, height, _, found = svg_images(paths["svg"][0])
    ground = scaffold.ground
    # Inside printed: the inside markers; outside printed: the outside ones, mirrored with it.
    expected = INSIDE if side == "front" else OUTSIDE
    assert normal_side_up(flats[ground][1]) == (side == "front")
    for point, colour in expected:
        at = on_sheet(flats[ground][1], artwork[ground], point)
        assert inside(flats[ground][1]["outer"], at)
        assert svg_colour_at(found[ground][0], height, at) == byte_colour(colour) + (255,)
        # 7 mm off the marker (its half width is 5 mm): bare card, transparent.
        beside = on_sheet(flats[ground][1], artwork[ground], (point[0] + 7, point[1], 0))
        assert svg_colour_at(found[ground][0], height, beside)[3] == 0
    # The box's top (patch 5, its own piece) shows the grey top face and the red marker on it.
    top = 5
    if normal_side_up(flats[top][1]):
        marker = on_sheet(flats[top][1], artwork[top], ON_TOP[0][0])
        assert svg_colour_at(found[top][0], height, marker) == byte_colour(RED) + (255,)
        plain = on_sheet(flats[top][1], artwork[top], (20, 120, 30))
        assert svg_colour_at(found[top][0], height, plain) == byte_colour(GREY) + (255,)


def test_svg_and_pdf_carry_registration_marks(written):
    _, sheet_set, _, paths, pdf = written
    root, height, layer, _ = svg_images(paths["svg"][0])
    marks = [r for r in layer.findall(SVG + "rect")]
    assert len(marks) == 3
    assert {(float(r.get("x")), height - float(r.get("y")) - 5) for r in marks} == {
        (2.5, 2.5),
        (2.5, 420 - 7.5),
        (297 - 7.5, 420 - 7.5),
    }
    with open(pdf, "rb") as file:
        data = file.read()
    assert len(re.findall(rb"([-0-9.]+) ([-0-9.]+) 5 5 re f", data)) == 3


def test_pdf_images_have_their_size_and_place(written):
    _, sheet_set, artwork, paths, _ = written
    flats = flat_patches(sheet_set)
    reader = PdfReader(paths["pdf"])
    (page,) = reader.pages
    xobjects = page["/Resources"]["/XObject"]
    images = {
        name: x.get_object()
        for name, x in xobjects.items()
        if x.get_object()["/Subtype"] == "/Image"
    }
    assert all("/SMask" in x for x in images.values())  # transparent where no surface counts
    artwork = visible(artwork)
    # Follow the current transformation matrix to each image: its unit square lands on the
    # patch's bounding box in the patch frame, through to_sheet (points = mm × 72 / 25.4).
    placed, drawn = [], []
    stack, ctm = [], numpy.identity(3)
    clips = 0
    for operands, operator in ContentStream(page.get_contents(), reader).operations:
        if operator == b"q":
            stack.append(ctm)
        elif operator == b"Q":
            ctm = stack.pop()
        elif operator == b"cm":
            a, b, c, d, e, f = map(float, operands)
            ctm = ctm @ numpy.array([[a, c, e], [b, d, f], [0, 0, 1]])  # user space inside
        elif operator == b"W*":
            clips += 1
        elif operator == b"Do" and operands[0] in images:
            placed.append(ctm)
            drawn.append(images[operands[0]])
    # One image per patch with artwork (reportlab shares the XObject of identical images).
    assert len(drawn) == len(artwork)
    sizes = sorted((x["/Width"], x["/Height"]) for x in drawn)
    assert sizes == sorted((a.rgba.shape[1], a.rgba.shape[0]) for a in artwork.values())
    assert clips >= len(artwork)
    for patch_id, art in artwork.items():
        flat = flats[patch_id][1]
        u0, v0 = art.origin_uv
        rows, columns = art.rgba.shape[:2]
        step = art.mm_per_pixel
        (a, b, tx), (c, d, ty) = flat["to_sheet"]
        to_sheet = numpy.array([[a, b, tx], [c, d, ty], [0, 0, 1]])
        expected = [
            to_sheet @ (u0 + du, v0 + dv, 1)
            for du, dv in ((0, 0), (columns * step, 0), (0, rows * step))
        ]
        assert any(
            all(
                numpy.allclose((m @ (x, y, 1))[:2] / PT_PER_MM, e[:2], atol=1e-3)
                for (x, y), e in zip(((0, 0), (1, 0), (0, 1)), expected)
            )
            for m in placed
        ), f"patch {patch_id}"


def test_dxf_stays_a_cut_file(written):
    _, _, _, paths, _ = written
    document = ezdxf.readfile(paths["dxf"])
    assert not list(document.modelspace().query("IMAGE"))
    assert {layer.dxf.name for layer in document.layers} >= {"CUT", "MOUNTAIN", "VALLEY"}


def test_artwork_for_a_missing_patch_or_the_hidden_side_is_refused(model, scaffold, tmp_path):
    sheet_set = layout(scaffold, paper="A3")
    ground = scaffold.patches[scaffold.ground]
    art = popupcore.render_artwork(model, ground, pixels_per_mm=1.0)
    with pytest.raises(ValueError, match="artwork for patch 99: the sheets have no such patch"):
        write_svg(sheet_set, str(tmp_path / "x.svg"), artwork={99: art})
    hidden = popupcore.render_artwork(model, ground, pixels_per_mm=1.0, back_side=True)
    with pytest.raises(ValueError, match="shows its back side, but P1 has its normal side up"):
        write_pdf(sheet_set, str(tmp_path / "x.pdf"), artwork={ground.id: hidden})


def test_a_layout_stored_before_patch_frames_existed_takes_no_artwork(model, scaffold, tmp_path):
    data = json.loads(layout(scaffold, paper="A3").to_json())
    for piece in data["pieces"]:
        for patch in piece["patches"]:
            del patch["to_sheet"]
    older = popupcore.sheet_set_from_json(json.dumps(data))
    with pytest.raises(ValueError, match=r"gives no to_sheet for it \(written by an older PopUp\)"):
        render_sheet_artwork(model, scaffold, older, pixels_per_mm=1.0)
    ground = scaffold.patches[scaffold.ground]
    art = popupcore.render_artwork(model, ground, pixels_per_mm=1.0)
    with pytest.raises(
        ValueError, match=rf"artwork for patch {ground.id} \({ground.name}\): the sheet"
    ):
        write_svg(older, str(tmp_path / "x.svg"), artwork={ground.id: art})


def test_render_artwork_binding(model, scaffold):
    ground = scaffold.patches[scaffold.ground]
    art = popupcore.render_artwork(model, ground, pixels_per_mm=PIXELS_PER_MM, depth=5.0)
    assert art.rgba.dtype == numpy.uint8 and art.rgba.shape == (280, 400, 4)  # 140 x 200 mm
    assert art.mm_per_pixel == pytest.approx(1 / PIXELS_PER_MM)
    assert art.origin_uv == pytest.approx((-100, -70))  # u along the 200 mm edge, centred
    assert art.warnings == []
    # Two 10 x 10 mm inside markers, one pixel border allowed around their 40 mm perimeters.
    assert art.covered_pixels == int((art.rgba[..., 3] == 255).sum())
    assert art.covered_pixels / PIXELS_PER_MM**2 == pytest.approx(200, abs=2 * 40 / PIXELS_PER_MM)
    both = popupcore.render_artworks(model, [ground, scaffold.patches[5]], pixels_per_mm=1.0)
    assert [a.patch for a in both] == [ground.id, 5]
    with pytest.raises(popupcore.DesignError, match="pixels_per_mm = 0, must be > 0") as error:
        popupcore.render_artwork(model, ground, pixels_per_mm=0)
    assert error.value.diagnostics[0]["parameter"] == "pixels_per_mm"
    with pytest.raises(popupcore.DesignError, match="depth = nan"):
        popupcore.render_artwork(model, ground, depth=float("nan"))


def test_flat_patch_frames_cross_the_binding(scaffold):
    from popupwb.sheets.sheet_options import core_options

    core = popupcore.layout_sheets(scaffold, core_options(paper="A3"))
    written = json.loads(core.to_json())
    for piece, piece_dict in zip(core.pieces, written["pieces"]):
        for flat, flat_dict in zip(piece.patches, piece_dict["patches"]):
            assert flat.to_sheet.shape == (2, 3)
            numpy.testing.assert_allclose(flat.to_sheet, flat_dict["to_sheet"], atol=0)
            assert flat.normal_side_up() == normal_side_up(flat_dict)


def test_a_png_texture_written_by_pil_is_mapped_by_its_uvs(scaffold, tmp_path):
    # 2 x 1 texture: left texel red, right texel blue, on a 40 x 20 mm quad over the ground with
    # u running along x; uv (0.25, 0.5) and (0.75, 0.5) are the texel centres.
    path = tmp_path / "two.png"
    Image.fromarray(numpy.array([[[255, 0, 0, 255], [0, 0, 255, 255]]], numpy.uint8)).save(path)
    corners = [(60, 20, 0.2), (100, 20, 0.2), (100, 40, 0.2), (60, 40, 0.2)]
    mesh = popupcore.ModelMesh(numpy.array(corners, float), numpy.array([[0, 1, 2], [0, 2, 3]]))
    mesh.uvs = numpy.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
    mesh.texture = str(path)
    ground = scaffold.patches[scaffold.ground]
    art = popupcore.render_artwork(mesh, ground, pixels_per_mm=1.0)
    assert art.warnings == []

    def colour_and_centre(point):
        """The pixel holding `point`, and the design-state centre of that pixel."""
        d = numpy.asarray(point, float) - art.frame["origin"]
        u, v = d @ art.frame["u"], d @ art.frame["v"]
        column = int((u - art.origin_uv[0]) // art.mm_per_pixel)
        row = art.rgba.shape[0] - 1 - int((v - art.origin_uv[1]) // art.mm_per_pixel)
        cu = art.origin_uv[0] + (column + 0.5) * art.mm_per_pixel
        cv = art.origin_uv[1] + (art.rgba.shape[0] - row - 0.5) * art.mm_per_pixel
        centre = art.frame["origin"] + cu * art.frame["u"] + cv * art.frame["v"]
        return tuple(art.rgba[row, column]), centre

    for point in ((70.5, 30.5, 0), (90.5, 30.5, 0), (79.6, 25, 0)):
        colour, centre = colour_and_centre(point)
        # Bilinear between texel centres (u = 0.25 red, 0.75 blue), the texture repeating.
        t = ((centre[0] - 60) / 40) * 2 - 0.5
        first = math.floor(t)
        blue = (t - first) if first % 2 == 0 else 1 - (t - first)
        assert colour == (round(255 * (1 - blue)), 0, round(255 * blue), 255), point
    mesh.texture = str(tmp_path / "missing.png")
    shaded = popupcore.render_artwork(mesh, ground, pixels_per_mm=1.0)
    assert [w["code"] for w in shaded.warnings] == ["unreadable_texture"]
    assert "missing.png" in shaded.warnings[0]["message"]
