"""`popup fit` on the models that missed (issue 12): the round blob under NPCA found no design, the
truck on wheels with its given axes was one tent far from it. Models from tools/make_models.py;
bounds from their construction and the issue, never from the fitter's output."""

import json
import os

import numpy as np
import pytest

from cli_runner import load_tool, popup
from test_cli_fit import UPRIGHT

THESIS_BEST_MEAN = 0.0128  # issue 12's goal for blocky models, with at most 8 mechanisms


make_models = load_tool("make_models")


@pytest.fixture(scope="module")
def models(tmp_path_factory):
    folder = tmp_path_factory.mktemp("models")
    return {
        name: make_models.write_model(name, str(folder / f"{name}.stl"))
        for name in ("blob", "figure", "truck_with_wheels")
    }


def fitted(model, out, *flags):
    proc = popup("fit", model, "--out", str(out), "--seed", "1", *flags)
    assert "Traceback" not in proc.stdout + proc.stderr, proc.stderr
    with open(os.path.join(out, "report.json")) as f:
        return proc, json.load(f)


def stl_triangles(path):
    """Triangles (n, 3, 3) of a binary STL, read here."""
    data = open(path, "rb").read()
    count = int(np.frombuffer(data[80:84], dtype="<u4")[0])
    records = np.frombuffer(
        data[84 : 84 + 50 * count], dtype=np.dtype([("r", "<f4", 12), ("a", "<u2")])
    )
    return records["r"][:, 3:].reshape(count, 3, 3).astype(float)


def test_the_blob_under_npca_gets_a_valid_design_closer_than_the_bare_card(models, tmp_path):
    proc, report = fitted(models["blob"], tmp_path / "blob")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert report["valid"] is True and 1 <= report["number_of_mechanisms"] <= 8
    # The bare card is the page z = 0: the model's surface lies, area-weighted, at its mean
    # height on the card from it. The design must explain the model better than nothing does.
    m = np.array(report["model_to_card"], dtype=float)
    tri = stl_triangles(models["blob"])
    area = 0.5 * np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1)
    centroids = tri.mean(axis=1) @ m[:3, :3].T + m[:3, 3]
    page_mean = float((area * np.abs(centroids[:, 2])).sum() / area.sum())
    metrics = report["metrics"]
    assert metrics["hausdorff_mm"]["model_to_popup"]["mean"] < 0.5 * page_mean
    # The box it fell back on says so.
    assert any(r["action"] == "replaced" for r in report["repairs"])


def test_the_truck_on_wheels_with_its_axes_is_under_the_thesis_best_mean(models, tmp_path):
    proc, report = fitted(models["truck_with_wheels"], tmp_path / "truck", *UPRIGHT)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert report["valid"] is True and report["number_of_mechanisms"] <= 8
    assert report["metrics"]["hausdorff"]["model_to_popup"]["mean"] < THESIS_BEST_MEAN
    # Its cargo box (make_models.BOXES["truck"], lifted 8 mm onto the axles) is a box fold
    # standing on the page through the wheels: some box reaches the cargo box's top.
    lo, hi = next((lo, hi) for _, lo, hi in make_models.BOXES["truck"] if hi[2] == 48)
    scale = np.linalg.norm(np.array(report["model_to_card"])[:3, 0])
    tops = [
        max(c[2] for c in p["corners"]) for p in report["primitives"] if p["kind"] == "rectangular"
    ]
    assert min(abs(t - (hi[2] + 8) * scale) for t in tops) < 0.02 * (hi[2] + 8) * scale


@pytest.mark.parametrize("name", ["figure", "truck_with_wheels", "blob"])
@pytest.mark.parametrize("alignment", ["given axes", "NPCA"])
def test_organic_and_wheeled_models_stay_valid_with_usable_sheets(
    models, tmp_path, name, alignment
):
    flags = UPRIGHT if alignment == "given axes" else ()
    proc, report = fitted(models[name], tmp_path / "out", *flags)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert report["valid"] is True and report["sheets_ok"] is True
