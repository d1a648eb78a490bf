"""tools/make_corpus.py: every corpus model is written, popupcore.load_model (assimp) reads it,
and what it measures matches the recipe (make_corpus.CORPUS): bounding box in the file's unit and
up axis, separate parts kept apart, border edges on open shells, duplicated faces and
non-manifold corners where the recipe put them, the texture file written and named."""

import os
import subprocess
import sys

import numpy as np
import pytest

import popupcore
from cli_runner import load_tool

make_corpus = load_tool("make_corpus")
CORPUS = make_corpus.CORPUS

# What issue 25 asks the corpus to carry, as CORPUS's defect tags.
REQUIRED_DEFECTS = {
    "separate-solids",
    "overlapping-solids",
    "inner-parts",
    "many-border-edges",
    "non-manifold",
    "duplicated-faces",
    "open-shell",
    "single-sided",
    "ground-plate",
    "gable-roof",
    "hip-roof",
    "shed-roof",
    "overhang",
    "chimney",
    "porch",
    "window-holes",
    "several-blocks",
    "separate-wheels",
    "thin-protrusions",
    "organic",
    "off-centre",
    "huge-scale",
    "tiny-scale",
    "x-up",
    "texture-tga",
    "texture-bmp",
    "texture-embedded",
    "vertex-colours",
    "no-texture",
}


# Answers whose two corners are vertices of the model (a ridge's ends, a wall box's corners).
CORNERS_ON_THE_MODEL = (
    "ridge",
    "roof_high_edge",
    "walls",
    "front_wall",
    "back_wall",
    "terrain",
    "chimney",
    "bed",
    "deck",
)


@pytest.fixture(scope="module")
def corpus(tmp_path_factory):
    """Every model written once into a tmp folder, loaded and cleaned: name -> (path, mesh,
    repairs)."""
    folder = tmp_path_factory.mktemp("corpus")
    models = {}
    for name, entry in CORPUS.items():
        path = make_corpus.write_corpus_model(name, str(folder / f"{name}.{entry['file']}"))
        mesh = popupcore.load_model(path)
        _, repairs = popupcore.clean_model(mesh)
        models[name] = (path, mesh, repairs)
    return models


def connected_parts(triangles, count):
    """Connected components of the triangles through shared vertex indices (union-find)."""
    parent = list(range(count))

    def root(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    for a, b, c in triangles.tolist():
        ra = root(a)
        parent[root(b)] = ra
        parent[root(c)] = ra
    return len({root(v) for v in np.unique(triangles).tolist()})


def test_the_corpus_has_twenty_models_and_every_defect_the_issue_lists():
    assert len(CORPUS) >= 20
    tags = set().union(*(entry["defects"] for entry in CORPUS.values()))
    assert REQUIRED_DEFECTS <= tags, sorted(REQUIRED_DEFECTS - tags)
    assert {e["unit"] for e in CORPUS.values()} >= {"m", "cm", "mm", "in"}
    assert {e["up"] for e in CORPUS.values()} >= {"+x", "+y", "+z"}
    assert {e["file"] for e in CORPUS.values()} >= {"stl", "obj", "ply", "off", "glb", "dae", "3mf"}


@pytest.mark.parametrize("name", list(CORPUS))
def test_each_model_loads_with_the_recipes_box_and_parts(corpus, name):
    entry = CORPUS[name]
    _, mesh, _ = corpus[name]
    assert len(mesh.vertices) > 0 and len(mesh.triangles) > 0
    low, high = mesh.vertices.min(axis=0), mesh.vertices.max(axis=0)
    tolerance = 0.01 * np.linalg.norm(high - low)
    for measured, stated in ((low, entry["bbox"][0]), (high, entry["bbox"][1])):
        stated = np.array(stated, dtype=float) * entry["scale"]
        known = ~np.isnan(stated)
        assert np.all(np.abs(measured[known] - stated[known]) <= tolerance), (measured, stated)
    assert connected_parts(mesh.triangles, len(mesh.vertices)) >= entry["min_components"]


@pytest.mark.parametrize("name", list(CORPUS))
def test_known_answers_lie_on_the_model(corpus, name):
    """Ridges are lines between two roof corners, boxes lie within the model's box."""
    entry = CORPUS[name]
    _, mesh, _ = corpus[name]
    vertices = mesh.vertices / entry["scale"]
    low, high = vertices.min(axis=0), vertices.max(axis=0)
    tolerance = 1e-3 * np.linalg.norm(high - low)
    for key, (lo, hi) in entry["answers"].items():
        assert np.all(np.array(lo) >= low - tolerance) and np.all(np.array(hi) <= high + tolerance)
        if key in CORNERS_ON_THE_MODEL:
            for corner in (lo, hi):
                nearest = np.min(np.linalg.norm(vertices - np.array(corner), axis=1))
                assert nearest <= tolerance, (key, corner)


@pytest.mark.parametrize("name", [n for n, e in CORPUS.items() if e["open"]])
def test_open_shells_have_border_edges(corpus, name):
    _, _, repairs = corpus[name]
    assert repairs["border_edges"] > 0 and not repairs["closed"]


def test_the_tree_has_thousands_of_border_edges(corpus):
    _, _, repairs = corpus["tree_cards"]
    assert repairs["border_edges"] >= 2400


@pytest.mark.parametrize(
    "tag, key",
    [
        ("duplicated-faces", "duplicate_faces_removed"),
        ("non-manifold", "non_manifold_vertices_split"),
    ],
)
def test_duplicated_faces_and_non_manifold_corners_are_there(corpus, tag, key):
    names = [n for n, e in CORPUS.items() if tag in e["defects"]]
    assert names
    for name in names:
        assert corpus[name][2][key] > 0, name


@pytest.mark.parametrize("name", [n for n, e in CORPUS.items() if e["texture"]])
def test_texture_files_are_written_and_referenced(corpus, name):
    path, mesh, _ = corpus[name]
    texture = CORPUS[name]["texture"]
    image = os.path.join(os.path.dirname(path), texture)
    assert os.path.getsize(image) > 0
    with open(os.path.splitext(path)[0] + ".mtl") as mtl:
        assert f"map_Kd {texture}" in mtl.read()
    assert os.path.basename(mesh.texture) == texture
    assert len(mesh.uvs) == len(mesh.vertices)


def test_the_tga_is_an_uncompressed_truecolour_image(corpus):
    path, _, _ = corpus["cottage_tga"]
    with open(os.path.join(os.path.dirname(path), "cottage.tga"), "rb") as f:
        header = f.read(18)
    assert header[2] == 2 and header[16] == 24  # uncompressed true-colour, 24 bits
    assert int.from_bytes(header[12:14], "little") == 64


def test_embedded_texture_and_vertex_colours(corpus):
    _, lighthouse, _ = corpus["lighthouse"]
    assert lighthouse.texture_bytes[:8] == b"\x89PNG\r\n\x1a\n"
    assert len(lighthouse.uvs) == len(lighthouse.vertices)
    for name in (n for n, e in CORPUS.items() if "vertex-colours" in e["defects"]):
        _, mesh, _ = corpus[name]
        assert mesh.colours.shape == mesh.vertices.shape, name


def test_the_cli_writes_named_models_and_refuses_unknown_ones(tmp_path):
    tool = os.path.join(os.environ["POPUP_SOURCE_DIR"], "tools", "make_corpus.py")
    run = subprocess.run(
        [sys.executable, tool, "--out", str(tmp_path), "chair_x_up", "bookshelf"],
        capture_output=True,
        text=True,
    )
    assert run.returncode == 0, run.stderr
    assert sorted(os.listdir(tmp_path)) == ["bookshelf.mtl", "bookshelf.obj", "chair_x_up.stl"]
    run = subprocess.run(
        [sys.executable, tool, "--out", str(tmp_path), "teapot"], capture_output=True, text=True
    )
    assert run.returncode == 2 and "'teapot'" in run.stderr and "house_gable" in run.stderr
    with pytest.raises(ValueError, match=r"\.stl, not \.obj"):
        make_corpus.write_corpus_model("chair_x_up", str(tmp_path / "chair.obj"))


@pytest.mark.parametrize("name", ["engine", "tree_cards", "cottage_tga"])
def test_the_corpus_is_the_same_bytes_on_every_run(corpus, tmp_path, name):
    """Seeded randomness and fixed zip dates: a model written again is the same file."""
    first, _, _ = corpus[name]
    again = make_corpus.write_corpus_model(name, str(tmp_path / os.path.basename(first)))
    with open(first, "rb") as a, open(again, "rb") as b:
        assert a.read() == b.read()
