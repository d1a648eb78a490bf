"""The workbench helpers of shape from a model, each against something known: Part solids and
meshes become ModelMeshes with their own boxes and areas, a document gives its top-level objects,
prism hulls have a box's 6 faces and a triangular prism's 5, report values become plain JSON, and
the preview draws the model left and the pop-up right."""

import json
import math
import random

import numpy as np
import pytest


@pytest.fixture
def core():
    from popupwb.core import popupcore

    return popupcore


def test_a_part_solid_becomes_its_mesh_with_placement(doc, core):
    import FreeCAD
    import Part

    from popupwb.model.model_source import model_of_object

    box = doc.addObject("Part::Feature", "Block")
    box.Shape = Part.makeBox(60, 40, 30)
    box.Placement = FreeCAD.Placement(FreeCAD.Vector(10, 0, 5), FreeCAD.Rotation())
    doc.recompute()
    model = model_of_object(box)
    vertices = np.asarray(model.vertices)
    assert vertices.min(axis=0) == pytest.approx([10, 0, 5])
    assert vertices.max(axis=0) == pytest.approx([70, 40, 35])
    assert model.area() == pytest.approx(2 * (60 * 40 + 60 * 30 + 40 * 30))
    assert model.source == "Block"


def test_a_mesh_feature_becomes_its_mesh(doc, core):
    import MeshPart
    import Part

    from popupwb.model.model_source import model_of_object

    obj = doc.addObject("Mesh::Feature", "Ball")
    obj.Mesh = MeshPart.meshFromShape(Shape=Part.makeSphere(10.0), LinearDeflection=0.2)
    doc.recompute()
    model = model_of_object(obj)
    assert len(model.triangles) == obj.Mesh.CountFacets
    assert model.diagonal() == pytest.approx(obj.Mesh.BoundBox.DiagonalLength)


def test_a_document_gives_its_top_level_models_and_skips_popup_objects(doc, core, tmp_path):
    import FreeCAD
    import Part

    from popupwb import make
    from popupwb.model.model_source import model_of_document, top_level_models

    a = doc.addObject("Part::Feature", "A")
    a.Shape = Part.makeBox(10, 10, 10)
    b = doc.addObject("Part::Feature", "B")
    b.Shape = Part.makeBox(10, 10, 10, FreeCAD.Vector(5, 0, 0))
    fusion = doc.addObject("Part::MultiFuse", "Fusion")
    fusion.Shapes = [a, b]
    make.make_card(doc)
    doc.recompute()
    assert [o.Name for o in top_level_models(doc)] == ["Fusion"]
    path = str(tmp_path / "parts.FCStd")
    doc.saveAs(path)
    model, labels = model_of_document(path)
    assert labels == ["Fusion"]
    assert np.ptp(np.asarray(model.vertices), axis=0) == pytest.approx([15, 10, 10])


def test_a_document_without_models_is_named(doc, tmp_path):
    from popupwb.model.model_source import model_of_document

    path = str(tmp_path / "empty.FCStd")
    doc.saveAs(path)
    with pytest.raises(ValueError, match="empty.FCStd: no Mesh or Part object"):
        model_of_document(path)


def test_prism_hulls_have_their_faces_whatever_the_corner_order():
    from popupwb.fitting.prism_hull import hull_faces

    random.seed(5)
    box = [(x, y, z) for x in (0, 2) for y in (0, 3) for z in (0, 1)]
    random.shuffle(box)
    faces = hull_faces(box)
    assert sorted(len(f) for f in faces) == [4] * 6
    tent = [(0, 0, 0), (0, 4, 0), (0, 2, 3), (5, 0, 0), (5, 4, 0), (5, 2, 3)]
    random.shuffle(tent)
    faces = hull_faces(tent)
    assert sorted(len(f) for f in faces) == [3, 3, 4, 4, 4]
    # Counter-clockwise from outside: each face's Newell normal points away from the centre.
    p = np.asarray(tent, dtype=float)
    centre = p.mean(axis=0)
    for face in faces:
        normal = sum(np.cross(p[face[i]], p[face[(i + 1) % len(face)]]) for i in range(len(face)))
        assert normal @ (p[face[0]] - centre) > 0


def test_report_values_become_plain_json():
    from popupwb.fitting.fit_report import plain, timings

    value = plain({"m": np.eye(2), "x": np.float64(math.nan), "n": np.int64(3), "b": np.bool_(1)})
    assert value == {"m": [[1.0, 0.0], [0.0, 1.0]], "x": None, "n": 3, "b": True}
    json.dumps(value, allow_nan=False)
    assert timings([("a", 1.0), ("b", 2.0), ("a", 0.5)], 4.0) == {"a": 1.5, "b": 2.0, "total": 4.0}


def test_the_preview_shows_model_left_and_pop_up_right(core, tmp_path):
    from matplotlib.image import imread

    from popupwb.fitting.preview import scaffold_outlines, write_preview

    params = core.CardParams()
    params.width, params.depth = 100.0, 80.0
    scaffold = core.make_card(params)
    outlines, card = scaffold_outlines(scaffold)
    assert len(outlines) == 2 and sorted(card) == [0, 1]
    # Standing across the fold in the middle of the card, as a fitted model does: depth-sorted as
    # a whole, the card (whose centre is nearer the camera) once hid it.
    vertices = np.array([[-20, 30, 0], [20, 30, 0], [0, 70, 0], [0, 50, 40]], dtype=float)
    triangles = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    path = write_preview(str(tmp_path / "p.png"), vertices, triangles, outlines, card, "test")
    image = imread(path)
    assert image.shape[:2] == (800, 1600)
    rgb = image[..., :3]
    # The model is blue-ish (more blue than red); the card grey; each drawn in its own half.
    left, right = rgb[:, :800], rgb[:, 800:]
    bluish = lambda part: np.sum((part[..., 2] - part[..., 0]) > 0.1)  # noqa: E731
    assert bluish(left) > 5000 and bluish(right) < 50
    grey = lambda part: np.sum((np.ptp(part, axis=-1) < 0.02) & (part[..., 0] < 0.9))  # noqa: E731
    assert grey(right) > 500
