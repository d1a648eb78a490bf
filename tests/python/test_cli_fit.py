"""`popup fit MODEL --out DIR`, run as a maker would, on models made by tools/make_models.py at test
time: exit 0 with design.FCStd, report.json, preview.png and sheets for a model that fits, 1 when no
valid design is found, 2 with one named error line for input it cannot use.

Known answers come from how the models were made (make_models.BOXES), never from the fitter: the
cuboid's bounding box put through report.json's model_to_card must stand on the card, and its one
box fold must have the cuboid's dimensions in card millimetres."""

import os
import struct
import zipfile

import numpy as np
import pytest

from cli_runner import assert_input_refused, assert_named_error, load_tool, read_report, run_design

UPRIGHT = ("--up", "0,0,1", "--facing", "0,-1,0")  # make_models: z up, the front faces -y
REPORT_KEYS = {
    "valid": bool,
    "mechanisms": list,
    "metrics": dict,
    "model_to_card": list,
    "timings_s": dict,
    "repairs": list,
    "model_repairs": dict,
    "number_of_mechanisms": int,
    "number_of_patches": int,
}
STATS = ("mean", "rms", "max")


make_models = load_tool("make_models")


@pytest.fixture(scope="module")
def models(tmp_path_factory):
    folder = tmp_path_factory.mktemp("models")
    paths = {}
    for name, extension in (
        ("cuboid", "stl"),
        ("house", "obj"),
        ("tent", "ply"),
        ("defective", "obj"),
        ("plate", "off"),
    ):
        paths[name] = make_models.write_model(name, str(folder / f"{name}.{extension}"))
    return paths


def fit(model, out, *extra, home=None):
    return run_design("fit", model, out, *extra, home=home)


@pytest.fixture(scope="module")
def cuboid_fit(models, tmp_path_factory, user_home):
    out = tmp_path_factory.mktemp("cuboid")
    proc = fit(models["cuboid"], out, *UPRIGHT, "--seed", "3", home=user_home)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return out, proc, read_report(out)


def test_a_cuboid_writes_every_file(cuboid_fit):
    out, proc, _ = cuboid_fit
    for name in ("design.FCStd", "report.json", "preview.png", "sheets/sheets.dxf"):
        assert os.path.isfile(os.path.join(out, name)), name
    with open(os.path.join(out, "preview.png"), "rb") as f:
        header = f.read(24)
    assert header[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = struct.unpack(">II", header[16:24])
    assert (width, height) == (1600, 800)  # model and pop-up side by side
    assert "popup fit: reading" in proc.stderr  # progress goes to stderr
    assert "valid design" in proc.stdout.splitlines()
    # The sheets are those `popup sheet` writes: its own report sits beside them.
    assert read_report(out, "sheets")["round_trip"]["ok"] is True


def test_the_report_has_every_key_with_its_type(cuboid_fit):
    report = cuboid_fit[2]
    for key, kind in REPORT_KEYS.items():
        assert isinstance(report[key], kind), key
    assert report["valid"] is True
    metrics = report["metrics"]
    assert metrics["diagonal_mm"] > 0
    for direction in ("model_to_popup", "popup_to_model"):
        values = metrics["hausdorff"][direction]
        assert set(values) >= set(STATS)
        assert 0 <= values["mean"] <= values["rms"] <= values["max"]
        # The normalised figures are the millimetre ones over the diagonal.
        for stat in STATS:
            assert values[stat] == pytest.approx(
                metrics["hausdorff_mm"][direction][stat] / metrics["diagonal_mm"]
            )
    assert isinstance(metrics["volume_difference"], float)
    assert 0 <= metrics["coverage"] <= 1
    timings = report["timings_s"]
    assert "total" in timings and len(timings) >= 3
    assert all(seconds >= 0 for seconds in timings.values())
    # The metrics are measured on a thread beside the preview and the sheets: the other stages
    # run one after the other.
    sequential = [v for k, v in timings.items() if k not in ("total", "metrics")]
    assert sum(sequential) <= timings["total"] + 1e-6
    assert 0 < timings["metrics"] <= timings["total"]
    for mechanism in report["mechanisms"]:
        assert set(mechanism) >= {"type", "host", "parameters"}
        assert all(isinstance(v, float) for v in mechanism["parameters"].values())
    assert report["number_of_mechanisms"] == len(report["mechanisms"])


def _card_corners(report, lo, hi):
    matrix = np.array(report["model_to_card"], dtype=float)
    assert matrix.shape == (4, 4)
    corners = np.array(
        [[x, y, z, 1.0] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])]
    )
    return (corners @ matrix.T)[:, :3]


def test_model_to_card_puts_the_model_on_the_card(cuboid_fit):
    report = cuboid_fit[2]
    ((_, lo, hi),) = make_models.BOXES["cuboid"]
    card = _card_corners(report, lo, hi)
    width, depth = report["card"]["width_mm"], report["card"]["depth_mm"]
    tolerance = 1e-6 * max(width, depth)
    # The bounding box's base lies on the pages (z = 0 at the design state), the model above it,
    # within the card: y along the fold from 0 to Width, x across both pages.
    assert card[:, 2].min() == pytest.approx(0.0, abs=1e-6 * width)
    assert card[:, 2].max() > 0
    assert card[:, 1].min() >= -tolerance and card[:, 1].max() <= width + tolerance
    assert card[:, 0].min() >= -depth - tolerance and card[:, 0].max() <= depth + tolerance


def test_the_cuboid_is_one_box_fold_of_its_dimensions(cuboid_fit):
    report = cuboid_fit[2]
    assert [m["type"] for m in report["mechanisms"]] == ["box_fold"]
    (box,) = report["mechanisms"]
    ((_, lo, hi),) = make_models.BOXES["cuboid"]
    card = _card_corners(report, lo, hi)
    extent = card.max(axis=0) - card.min(axis=0)  # along x (across the fold), y (along), z
    p = box["parameters"]
    assert p["width"] == pytest.approx(extent[1], rel=0.02)
    assert p["depth_ground"] + p["depth_backdrop"] == pytest.approx(extent[0], rel=0.02)
    assert p["height"] == pytest.approx(extent[2], rel=0.02)
    assert report["metrics"]["hausdorff"]["model_to_popup"]["mean"] <= 0.005


def test_the_document_reopens_with_the_reported_mechanisms_and_recomputes(cuboid_fit, freecad):
    out, _, report = cuboid_fit
    from popupwb.mechanism_registry import by_core_kind

    doc = freecad.openDocument(os.path.join(str(out), "design.FCStd"))
    try:
        mechanisms = [o for o in doc.Objects if hasattr(o, "HostPair")]
        assert all(o.Proxy is not None for o in mechanisms)
        assert [(o.Label, o.Proxy.TYPE) for o in mechanisms] == [
            (m["name"], by_core_kind(m["type"]).type_name) for m in report["mechanisms"]
        ]
        card = doc.getObject("Card")
        assert card.SourceModel is not None and card.SourceModel.TypeId == "Mesh::Feature"
        for o in mechanisms:
            o.touch()
        doc.recompute()
        assert not [o.Label for o in doc.Objects if "Invalid" in o.State]
        # Its parameters are the reported ones (lengths in mm).
        box = mechanisms[0]
        assert box.Height.Value == pytest.approx(report["mechanisms"][0]["parameters"]["height"])
    finally:
        freecad.closeDocument(doc.Name)


def test_the_same_seed_gives_the_same_design(models, cuboid_fit, tmp_path, user_home):
    proc = fit(models["cuboid"], tmp_path, *UPRIGHT, "--seed", "3", home=user_home)
    assert proc.returncode == 0, proc.stderr
    again, first = read_report(tmp_path), cuboid_fit[2]
    assert again["mechanisms"] == first["mechanisms"]
    assert again["model_to_card"] == first["model_to_card"]


def test_a_defective_mesh_is_repaired_and_still_fits(models, tmp_path, user_home):
    proc = fit(models["defective"], tmp_path, *UPRIGHT, home=user_home)
    report = read_report(tmp_path)
    # What make_models.DEFECTIVE_OBJ was written with: a zero-area and a needle triangle, a
    # duplicated face, two flipped triangles and the top left out (its duplicated vertex is
    # joined by load_model already: assimp joins identical vertices).
    repairs = report["model_repairs"]
    assert repairs["degenerate_faces_removed"] == 2, repairs
    assert repairs["duplicate_faces_removed"] == 1, repairs
    assert repairs["faces_reoriented"] >= 1, repairs
    assert repairs["holes"] == 1 and repairs["closed"] is False, repairs
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert report["valid"] is True and report["number_of_mechanisms"] >= 1


def test_a_freecad_document_with_a_part_solid_is_a_model(tmp_path, user_home, freecad):
    import Part

    doc = freecad.newDocument("BoxModel")
    box = doc.addObject("Part::Feature", "Block")
    box.Shape = Part.makeBox(60, 40, 30)
    doc.recompute()
    path = str(tmp_path / "block.FCStd")
    doc.saveAs(path)
    freecad.closeDocument(doc.Name)
    proc = fit(path, tmp_path / "out", *UPRIGHT, home=user_home)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "Block of block.FCStd" in proc.stderr
    assert read_report(tmp_path / "out")["number_of_mechanisms"] >= 1


def test_a_model_with_nothing_to_pop_up_exits_1_with_a_report(models, tmp_path, user_home):
    proc = fit(models["plate"], tmp_path, *UPRIGHT, home=user_home)
    assert proc.returncode == 1, proc.stdout + proc.stderr
    report = read_report(tmp_path)
    assert report["valid"] is False
    assert not os.path.exists(tmp_path / "sheets")
    assert "no valid design" in proc.stdout.lower() + proc.stderr.lower()


def _bad_model(folder, kind):
    if kind == "empty":
        path = folder / "empty.stl"
        path.write_bytes(b"")
    elif kind == "random":
        path = folder / "noise.stl"
        path.write_bytes(np.random.default_rng(7).bytes(3000))
    elif kind == "nan":
        path = folder / "nan.obj"
        path.write_text(
            "v 0 0 0\nv 1 0 0\nv nan 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n"
        )
    elif kind == "damaged":
        good = folder / "good.FCStd"
        with zipfile.ZipFile(good, "w") as z:
            z.writestr("Document.xml", "<Document>" * 50)
        path = folder / "damaged.FCStd"
        path.write_bytes(good.read_bytes()[: len(good.read_bytes()) // 2])
    else:
        path = folder / "missing.stl"
    return str(path)


@pytest.mark.parametrize("kind", ["empty", "random", "nan", "damaged", "missing"])
def test_unusable_models_exit_2_naming_the_file(kind, tmp_path, user_home):
    path = _bad_model(tmp_path, kind)
    proc = fit(path, tmp_path / "out", home=user_home)
    assert_input_refused(proc, path, tmp_path / "out")


@pytest.mark.parametrize(
    "flags, fragment",
    [
        (("--up", "0,0,0"), "--up 0,0,0"),
        (("--facing", "1,x,0"), "--facing 1,x,0"),
        (("--max-mechanisms", "0"), "--max-mechanisms 0"),
        (("--seed", "-1"), "--seed -1"),
        (("--detail", "nan"), "--detail nan"),
        (("--paper", "B9"), "--paper B9"),
    ],
)
def test_bad_options_exit_2_naming_the_flag(models, flags, fragment, tmp_path, user_home):
    proc = fit(models["cuboid"], tmp_path / "out", *flags, home=user_home)
    assert_named_error(proc, fragment)


def test_an_out_that_is_a_file_is_named(models, tmp_path, user_home):
    taken = tmp_path / "taken"
    taken.write_text("")
    assert_named_error(fit(models["cuboid"], taken, home=user_home), f"--out {taken}")
