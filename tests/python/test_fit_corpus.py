"""`popup fit` on corpus models with the defects of real files (tools/make_corpus.py), with the
automatic axes a maker gets: the house of nine touching solids on a terrain slab gets a box and a
roof at the card's scale, the slab becomes the page; the dog, with no flat bottom, stands on its
legs. Expected figures come from the recipes (make_corpus.CORPUS, corpus_buildings.GABLE), not
from the fitter."""

import numpy as np
import pytest

from cli_runner import load_tool, read_report, run_design

make_corpus = load_tool("make_corpus")
corpus_buildings = make_corpus.buildings  # the recipes make_corpus imported


@pytest.fixture(scope="module")
def house(tmp_path_factory):
    folder = tmp_path_factory.mktemp("house_gable")
    model = make_corpus.write_corpus_model("house_gable", str(folder / "house_gable.obj"))
    out = folder / "fit"
    proc = run_design("fit", model, out)
    return proc, read_report(out)


def test_the_terrain_slab_is_the_page(house):
    proc, report = house
    assert proc.returncode == 0, proc.stderr
    plate = report["plate"]
    # The OBJ is y up (x, y, z) -> (x, z, -y): the slab's top is the file's y = 0, its top face
    # the terrain's 24 x 20 m.
    (x0, y0, z0), (x1, y1, z1) = corpus_buildings.GABLE["terrain"]
    assert np.allclose(plate["up"], [0, 1, 0], atol=1e-9)
    assert plate["top"] == pytest.approx(z1, abs=1e-9)
    assert plate["thickness"] == pytest.approx(z1 - z0, abs=1e-9)
    assert plate["top_area"] == pytest.approx((x1 - x0) * (y1 - y0), rel=1e-9)
    # The card's z = 0 is the slab's top: the file's y = top lands there.
    m = np.asarray(report["model_to_card"])
    assert (m @ [0.0, plate["top"], 0.0, 1.0])[2] == pytest.approx(0.0, abs=1e-6)


def test_the_house_gets_a_box_and_its_roof(house):
    _, report = house
    assert report["valid"] is True and report["sheets_ok"] is True
    kinds = [(m["type"], m["host"]) for m in report["mechanisms"]]
    assert ("box_fold", "central fold") in kinds
    assert any(t == "tent_fold" and h.endswith(".top") for t, h in kinds)
    assert not any(r["action"] == "replaced" for r in report["repairs"])
    # Issue 25's goal for a gable house, measured on the house above its slab.
    assert report["metrics"]["hausdorff"]["model_to_popup"]["mean"] <= 0.0128
    # Nine touching solids: the faces between them (the walls' tops under the roof, the floor
    # slab's) lie inside the volume.
    assert report["fit"]["inner_samples"] > 0
    # The 20000 samples are spread over the model above the slab; the few that land on the
    # slab's level itself (a wall's foot) are the page's.
    assert 19900 <= report["fit"]["outer_samples"] + report["fit"]["inner_samples"] <= 20000


def test_a_dog_stands_on_its_legs(tmp_path):
    model = make_corpus.write_corpus_model("dog", str(tmp_path / "dog.off"))
    out = tmp_path / "fit"
    proc = run_design("fit", model, out)
    report = read_report(out)
    assert report["valid"] is True, proc.stderr
    # The OFF file is y up (make_corpus.CORPUS): the card's z is the file's +y.
    assert make_corpus.CORPUS["dog"]["up"] == "+y"
    m = np.asarray(report["model_to_card"])[:3, :3]
    up = m[2] / np.linalg.norm(m[2])
    assert up == pytest.approx([0, 1, 0], abs=1e-6)


def test_three_blocks_get_a_mechanism_each(tmp_path):
    """Three touching blocks of 9, 15 and 6 m (an L, corpus_buildings.APARTMENT), storey slabs
    inside: no mirror plane, so the fold may stand through a block's middle; the tower and the
    long block become a box, the wing a step in front of it and the top block a box on it."""
    model = make_corpus.write_corpus_model("apartment_blocks", str(tmp_path / "blocks.stl"))
    out = tmp_path / "fit"
    proc = run_design("fit", model, out)
    report = read_report(out)
    assert proc.returncode == 0, proc.stderr
    assert report["valid"] is True and report["sheets_ok"] is True
    assert not any(r["action"] == "replaced" for r in report["repairs"])
    assert len(report["mechanisms"]) >= 3
    # The bulk box measured 0.0316 of the diagonal (docs/SHAPE_RESULTS.md, before).
    assert report["metrics"]["hausdorff"]["model_to_popup"]["mean"] <= 0.016


def _fitted(folder, name, extension):
    """`popup fit` of the corpus model `name`: its report, after exit 0 with verified sheets."""
    model = make_corpus.write_corpus_model(name, str(folder / f"{name}.{extension}"))
    out = folder / "fit"
    proc = run_design("fit", model, out)
    report = read_report(out)
    assert proc.returncode == 0, proc.stderr
    assert report["sheets_ok"] is True
    return report


def _kinds(report):
    return [(m["type"], m["host"]) for m in report["mechanisms"]]


def test_a_bust_is_shoulders_and_a_head(tmp_path):
    """A scanned bust (corpus_objects, no flat face a prism rests on) falls back on its bulk: two
    boxes, the head's on the shoulders' top, closer to the model than the one box of its bulk
    (0.0257 of the diagonal, docs/SHAPE_RESULTS.md before)."""
    report = _fitted(tmp_path, "bust_scan", "ply")
    assert _kinds(report) == [("box_fold", "central fold"), ("box_fold", "B1.top")]
    assert any("two box folds" in r["reason"] for r in report["repairs"])
    assert report["metrics"]["hausdorff"]["model_to_popup"]["mean"] <= 0.0235


def test_a_game_house_of_open_sheets_gets_its_roof(tmp_path):
    """The game cottage (corpus_buildings.open_roof_game): single-sided wall quads and a roof of
    one sheet overhanging the walls, no solid anywhere. Its roof's planes meet the walls' top
    beyond the walls, so no fitted tent stands on the box; its bulk is the walls' box and a tent
    roof on its top, as the issue asks of a gable house (mean <= 0.0128)."""
    report = _fitted(tmp_path, "open_roof_game", "obj")
    assert _kinds(report) == [("box_fold", "central fold"), ("tent_fold", "B1.top")]
    assert report["metrics"]["hausdorff"]["model_to_popup"]["mean"] <= 0.0128
