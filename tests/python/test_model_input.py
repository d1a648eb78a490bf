"""popupcore.load_model, clean_model and fit_metrics: files written here, answers known by
construction (areas, counts, a model equal to the pop-up's own surface)."""

import math
import os
import random
import struct
import sys

import numpy as np
import pytest

import popupcore

CUBOID_AREA = 2 * (20 * 30 + 30 * 40 + 20 * 40)  # 5200 mm² for 20 x 30 x 40


def cuboid_soup():
    """The 20 x 30 x 40 cuboid as 12 outward triangles, each with its own three corners."""
    c = [(x, y, z) for z in (0, 40) for y in (0, 30) for x in (0, 20)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    tris = [t for q in quads for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]
    return [[c[i] for i in t] for t in tris]


def write_binary_stl(path, triangles):
    with open(path, "wb") as f:
        f.write(b"\0" * 80 + struct.pack("<I", len(triangles)))
        for t in triangles:
            f.write(struct.pack("<3f", 0, 0, 0))
            for p in t:
                f.write(struct.pack("<3f", *p))
            f.write(b"\0\0")


def codes(error):
    return [d["code"] for d in error.value.diagnostics]


def test_load_model_reads_a_binary_stl_and_joins_its_corners(tmp_path):
    path = tmp_path / "cuboid.stl"
    write_binary_stl(path, cuboid_soup())
    mesh = popupcore.load_model(str(path))
    assert mesh.vertices.shape == (8, 3)
    assert mesh.triangles.shape == (12, 3)
    assert mesh.area() == pytest.approx(CUBOID_AREA)
    assert mesh.vertices.min(axis=0) == pytest.approx([0, 0, 0])
    assert mesh.vertices.max(axis=0) == pytest.approx([20, 30, 40])
    assert mesh.source == str(path)
    assert mesh.texture_bytes == b""


def test_load_model_reads_obj_vertex_colours(tmp_path):
    path = tmp_path / "tetra.obj"
    path.write_text(
        "v 0 0 0 1 0 0\nv 10 0 0 0 1 0\nv 0 10 0 0 0 1\nv 0 0 10 1 1 1\n"
        "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
    )
    mesh = popupcore.load_model(str(path))
    expected = {(0, 0, 0): (1, 0, 0), (10, 0, 0): (0, 1, 0), (0, 10, 0): (0, 0, 1)}
    expected[(0, 0, 10)] = (1, 1, 1)
    assert mesh.colours.shape == (4, 3)
    for v, c in zip(mesh.vertices, mesh.colours):
        assert c == pytest.approx(expected[tuple(int(round(x)) for x in v)])


def test_a_missing_file_is_a_named_design_error(tmp_path):
    path = str(tmp_path / "nowhere.glb")
    with pytest.raises(popupcore.DesignError) as error:
        popupcore.load_model(path)
    assert codes(error) == ["unreadable_model"]
    assert path in str(error.value) and "no such file" in str(error.value)


def test_random_bytes_are_a_design_error_naming_the_file(tmp_path):
    rng = random.Random(3)
    for extension in ("stl", "obj", "glb", "ply", "fbx", "dae", "3mf", "off"):
        path = tmp_path / f"noise.{extension}"
        path.write_bytes(bytes(rng.randrange(256) for _ in range(4096)))
        with pytest.raises(popupcore.DesignError) as error:
            popupcore.load_model(str(path))
        assert str(path) in str(error.value)
        assert codes(error)[0] in ("unreadable_model", "empty_model")


def test_nan_coordinates_and_no_faces_are_design_errors(tmp_path):
    soup = cuboid_soup()
    soup[3][1] = (20.0, float("nan"), 40.0)
    path = tmp_path / "nan.stl"
    write_binary_stl(path, soup)
    with pytest.raises(popupcore.DesignError) as error:
        popupcore.load_model(str(path))
    assert codes(error) == ["non_finite_model"]

    points = tmp_path / "points.off"
    points.write_text("OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n")
    with pytest.raises(popupcore.DesignError) as error:
        popupcore.load_model(str(points))
    assert str(points) in str(error.value)

    no_faces = popupcore.ModelMesh(np.zeros((3, 3)), np.zeros((0, 3), dtype=np.int32), "empty")
    with pytest.raises(popupcore.DesignError) as error:
        popupcore.clean_model(no_faces)
    assert codes(error) == ["empty_model"]


def test_clean_model_counts_the_merged_corners_of_a_soup():
    soup = cuboid_soup()
    vertices = np.array([p for t in soup for p in t], dtype=float)
    triangles = np.arange(36, dtype=np.int32).reshape(12, 3)
    triangles[0] = triangles[0][[0, 2, 1]]  # one face flipped
    mesh, repairs = popupcore.clean_model(popupcore.ModelMesh(vertices, triangles, "soup"))
    assert repairs["duplicate_points_merged"] == 36 - 8
    assert repairs["faces_reoriented"] == 1
    assert repairs["closed"] is True
    assert repairs["holes"] == 0 and repairs["border_edges"] == 0
    assert set(repairs) == {
        "duplicate_points_merged",
        "degenerate_faces_removed",
        "duplicate_faces_removed",
        "faces_reoriented",
        "non_manifold_vertices_split",
        "isolated_vertices_removed",
        "border_edges",
        "holes",
        "closed",
    }
    assert mesh.vertices.shape == (8, 3) and mesh.area() == pytest.approx(CUBOID_AREA)


def test_a_freecad_mesh_of_a_part_solid_reads_back_with_its_area(tmp_path):
    sys.path.append("/usr/lib/freecad-python3/lib")
    import FreeCAD  # noqa: F401
    import Mesh
    import Part

    solid = Part.makeCylinder(10, 25).fuse(Part.makeBox(30, 20, 5))
    mesh = Mesh.Mesh(solid.tessellate(0.01))
    for name in ("solid.stl", "solid.obj", "solid.ply", "solid.off"):
        path = str(tmp_path / name)
        mesh.write(path)
        read = popupcore.load_model(path)
        assert read.triangles.shape[0] == mesh.CountFacets, name
        assert read.area() == pytest.approx(mesh.Area, rel=1e-5), name
        cleaned, repairs = popupcore.clean_model(read)
        assert repairs["closed"], name
        assert cleaned.area() == pytest.approx(mesh.Area, rel=1e-5), name


def box_fold_design():
    card = popupcore.make_card(popupcore.CardParams())
    params = popupcore.BoxFoldParams()
    popupcore.add_box_fold(card, popupcore.central_fold(card), params, "B1")
    return card


def test_fit_metrics_of_a_model_equal_to_the_popup_is_zero():
    design = box_fold_design()
    vertices, triangles = [], []
    for patch in design.patches:
        if patch.id in (design.ground, design.backdrop):
            continue
        assert not patch.holes
        start = len(vertices)
        vertices.extend(patch.outer)
        for k in range(1, len(patch.outer) - 1):  # box fold patches are convex
            triangles.append((start, start + k, start + k + 1))
    model = popupcore.ModelMesh(np.array(vertices), np.array(triangles, dtype=np.int32), "own")
    prisms = [np.array(vertices)]
    metrics = popupcore.fit_metrics(model, np.eye(4), design, prisms, threshold_mm=0.01)
    assert set(metrics) == {
        "diagonal_mm",
        "hausdorff",
        "hausdorff_mm",
        "volume_difference",
        "model_volume_mm3",
        "popup_volume_mm3",
        "coverage",
        "model_closed",
    }
    diagonal = np.linalg.norm(np.ptp(np.array(vertices), axis=0))
    assert metrics["diagonal_mm"] == pytest.approx(diagonal)
    for way in ("model_to_popup", "popup_to_model"):
        assert set(metrics["hausdorff"][way]) == {"mean", "rms", "max"}
        assert metrics["hausdorff_mm"][way]["mean"] == pytest.approx(0, abs=1e-6)
        assert metrics["hausdorff_mm"][way]["max"] <= 1e-3 * diagonal
    assert metrics["coverage"] == 1.0
    assert metrics["model_closed"] is False
    assert metrics["volume_difference"] is None and metrics["model_volume_mm3"] is None


def test_fit_metrics_names_a_bad_prism_and_a_bad_matrix():
    design = box_fold_design()
    model = popupcore.ModelMesh(
        np.array([[0, 0, 0], [10, 0, 0], [0, 10, 0.0]]), np.array([[0, 1, 2]], dtype=np.int32)
    )
    with pytest.raises(popupcore.DesignError, match=r"prisms\[0\]"):
        popupcore.fit_metrics(model, np.eye(4), design, [np.zeros((3, 3))], 1.0)
    matrix = np.eye(4)
    matrix[0, 0] = math.nan
    with pytest.raises(popupcore.DesignError, match="model_to_card"):
        popupcore.fit_metrics(model, matrix, design, [], 1.0)
