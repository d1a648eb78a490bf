"""popupcore, the pybind11 module: verdicts on the test designs, types and shapes crossing the
boundary, design-file errors that name the item, and exception translation.

Runs under /usr/bin/python3 with build/python on PYTHONPATH (ctest sets it).
"""

import copy
import json
import math
import os
import threading
import time

import numpy as np
import pytest

import popupcore

SOURCE_DIR = os.environ.get(
    "POPUP_SOURCE_DIR", os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
)
DATA_DIR = os.path.join(SOURCE_DIR, "tests", "data")
VERDICTS = ("foldable", "stable", "intersection_free", "enclosed")


def data_path(name):
    # A missing file fails the test (no skipping): the designs are part of the suite.
    path = os.path.join(DATA_DIR, name)
    assert os.path.isfile(path), f"test design {path} is missing"
    return path


def design_dict(name):
    with open(data_path(name), encoding="utf-8") as f:
        return json.load(f)


def load(name):
    return popupcore.load_scaffold(data_path(name))


def design_error(text):
    """The DesignError raised for a design given as JSON text (or dict)."""
    if not isinstance(text, str):
        text = json.dumps(text)
    with pytest.raises(popupcore.DesignError) as info:
        popupcore.scaffold_from_json(text)
    return str(info.value)


@pytest.fixture(scope="module")
def tent():
    return load("tent_fold.json")


class _Reports(dict):
    def __missing__(self, name):
        self[name] = popupcore.check_validity(load(name))
        return self[name]


@pytest.fixture(scope="module")
def reports():
    """check_validity of a test design by file name, computed once per design."""
    return _Reports()


# --- verdicts on the test designs -------------------------------------------------------------

# Expected verdicts; None where the design's failure makes the verdict meaningless.
EXPECTED = {
    "tent_fold.json": dict(foldable=True, stable=True, intersection_free=True, enclosed=True),
    "broken_tent.json": dict(foldable=False),
    "unstable_five_bar.json": dict(stable=False),
    # Walls passing through each other cannot close flat either: not foldable as well.
    "colliding_walls.json": dict(foldable=False, stable=True, intersection_free=False),
    "sticking_out_tent.json": dict(
        foldable=True, stable=True, intersection_free=True, enclosed=False
    ),
}


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_verdicts_of_test_designs(reports, name):
    report = reports[name]
    for verdict, expected in EXPECTED[name].items():
        assert getattr(report, verdict) is expected, f"{name}: {verdict}"
    assert report.valid is all(getattr(report, v) for v in VERDICTS)
    assert report.valid is (name == "tent_fold.json")


def test_valid_tent_numbers(reports, tent):
    report = reports["tent_fold.json"]
    assert report.model_size == pytest.approx(tent.size(), rel=1e-12)
    assert report.model_size > 0
    assert 0.0 <= report.max_hinge_residual <= 1e-9 * report.model_size
    assert 0.0 <= report.max_edge_strain <= 1e-9
    assert 0.0 <= report.flatness_at_zero <= 1e-6 * report.model_size
    assert report.locked_at == -1.0
    assert [d.code for d in report.diagnostics if d.code.startswith("not_")] == []


def test_broken_tent_locks_before_closing(reports):
    report = reports["broken_tent.json"]
    assert 0.0 < report.locked_at < math.pi


@pytest.mark.parametrize("name", [n for n in sorted(EXPECTED) if n != "tent_fold.json"])
def test_failing_designs_explain_themselves(reports, name):
    report = reports[name]
    assert report.diagnostics, f"{name}: invalid without a diagnostic"
    for d in report.diagnostics:
        assert isinstance(d.code, str) and d.code
        assert isinstance(d.message, str) and d.message
        assert d.code in popupcore.diagnostic_codes()
        assert d.severity in ("error", "warning", "info")
        assert all(isinstance(i, int) for i in d.patches)
    # At least one finding points at patches a person can go and fix, all of them in the design.
    ids = {p.id for p in load(name).patches}
    assert any(d.patches for d in report.diagnostics), name
    assert all(set(d.patches) <= ids for d in report.diagnostics), name


def test_report_to_dict_mirrors_attributes(reports):
    for name in EXPECTED:
        report = reports[name]
        d = report.to_dict()
        json.dumps(d)  # plain JSON types only
        for key in ("valid", *VERDICTS):
            assert d[key] is getattr(report, key), (name, key)
        for key in ("max_hinge_residual", "max_edge_strain", "flatness_at_zero", "model_size"):
            assert d[key] == getattr(report, key), (name, key)
        if report.locked_at < 0:
            assert d["locked_at_deg"] is None
        else:
            assert d["locked_at_deg"] == pytest.approx(math.degrees(report.locked_at), abs=1e-12)
        assert d["diagnostics"] == [
            {
                "code": x.code,
                "severity": x.severity,
                "message": x.message,
                "patches": list(x.patches),
                "parameter": x.parameter,
                "angle_deg": x.angle_deg,
            }
            for x in report.diagnostics
        ]
        assert d["diagnostics"] == [x.to_dict() for x in report.diagnostics]


def test_check_validity_takes_options(tent):
    assert popupcore.check_validity(tent, samples=19, clearance=0.0).valid
    report = popupcore.check_validity(tent, samples=1)
    assert not report.valid
    assert [d.code for d in report.diagnostics] == ["bad_option"]


# --- scaffold objects and the JSON round trip -------------------------------------------------


def test_scaffold_attributes(tent):
    raw = design_dict("tent_fold.json")
    assert len(tent.patches) == len(raw["patches"])
    assert len(tent.hinges) == len(raw.get("hinges", []))
    assert tent.ground == raw["ground"] and tent.backdrop == raw["backdrop"]
    assert tent.design_angle == pytest.approx(math.radians(raw.get("design_angle_deg", 180.0)))
    for patch, patch_raw in zip(tent.patches, raw["patches"]):
        assert patch.id == patch_raw["id"]
        outer = patch.outer
        assert isinstance(outer, np.ndarray) and outer.dtype == np.float64
        assert outer.shape == (len(patch_raw["outline"]), 3)
        np.testing.assert_array_equal(outer, np.array(patch_raw["outline"], dtype=float))
        assert patch.normal.shape == (3,)
        assert np.linalg.norm(patch.normal) == pytest.approx(1.0, abs=1e-12)
        # The outline lies in the plane of its normal.
        assert np.ptp(outer @ patch.normal) <= 1e-9 * tent.size()
        assert patch.area() > 0
        assert patch.role in {
            "ground",
            "backdrop",
            "support",
            "top",
            "front",
            "back",
            "tab",
            "other",
        }
    for hinge in tent.hinges:
        assert hinge.from_point.shape == (3,) and hinge.to_point.shape == (3,)
        assert hinge.direction in {"valley", "mountain", "unspecified"}
        assert {hinge.patch_a, hinge.patch_b} <= {p.id for p in tent.patches}


def assert_same_scaffold(a, b):
    assert a.name == b.name
    assert (a.ground, a.backdrop) == (b.ground, b.backdrop)
    assert a.design_angle == b.design_angle
    assert a.paper_thickness == b.paper_thickness
    assert [(p.id, p.name, p.role) for p in a.patches] == [
        (p.id, p.name, p.role) for p in b.patches
    ]
    for p, q in zip(a.patches, b.patches):
        np.testing.assert_array_equal(p.outer, q.outer)
        assert len(p.holes) == len(q.holes)
        for h, k in zip(p.holes, q.holes):
            np.testing.assert_array_equal(h, k)
    assert len(a.hinges) == len(b.hinges)
    for h, k in zip(a.hinges, b.hinges):
        assert (h.id, h.patch_a, h.patch_b, h.direction) == (
            k.id,
            k.patch_a,
            k.patch_b,
            k.direction,
        )
        np.testing.assert_array_equal(h.from_point, k.from_point)
        np.testing.assert_array_equal(h.to_point, k.to_point)
    assert list(a.glue) == list(b.glue)


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_json_round_trip_is_exact(name):
    original = load(name)
    again = popupcore.scaffold_from_json(popupcore.scaffold_to_json(original))
    assert_same_scaffold(original, again)


def test_save_and_load_round_trip(tent, tmp_path):
    path = str(tmp_path / "tent copy.json")
    popupcore.save_scaffold(tent, path)
    assert_same_scaffold(tent, popupcore.load_scaffold(path))


# --- simulation results as numpy arrays -------------------------------------------------------


@pytest.fixture(scope="module")
def sweep(tent):
    return popupcore.simulate_fold(tent, [math.pi, math.radians(120), math.radians(45), 0.0])


def test_simulate_fold_array_shapes(tent, sweep):
    n = len(tent.patches)
    assert sweep.ok and sweep.complete and sweep.locked_at == -1.0
    assert [s.angle for s in sweep.states] == pytest.approx(
        [math.pi, math.radians(120), math.radians(45), 0.0], abs=1e-12
    )
    for state in sweep.states:
        assert isinstance(state.rotations, np.ndarray) and state.rotations.dtype == np.float64
        assert isinstance(state.translations, np.ndarray) and state.translations.dtype == np.float64
        assert state.rotations.shape == (n, 3, 3)
        assert state.translations.shape == (n, 3)


def test_simulated_rotations_are_orthonormal(sweep):
    for state in sweep.states:
        for r in state.rotations:
            np.testing.assert_allclose(r.T @ r, np.eye(3), rtol=0, atol=1e-12)
            assert np.linalg.det(r) == pytest.approx(1.0, abs=1e-12)


def test_design_state_is_identity(tent, sweep):
    open_state = sweep.states[0]
    np.testing.assert_allclose(
        open_state.rotations, np.broadcast_to(np.eye(3), open_state.rotations.shape), atol=1e-12
    )
    np.testing.assert_allclose(open_state.translations, 0.0, atol=1e-9 * tent.size())


def test_hinges_stay_closed_through_the_poses(tent, sweep):
    index = {p.id: i for i, p in enumerate(tent.patches)}
    for state in sweep.states:
        assert state.hinge_residual <= 1e-9 * tent.size()
        for h in tent.hinges:
            for x in (h.from_point, h.to_point):
                a, b = index[h.patch_a], index[h.patch_b]
                xa = state.rotations[a] @ x + state.translations[a]
                xb = state.rotations[b] @ x + state.translations[b]
                assert np.linalg.norm(xa - xb) <= 1e-9 * tent.size()


def test_posed_outlines_follow_the_poses(tent, sweep):
    for state in sweep.states:
        outlines = popupcore.posed_outlines(tent, state)
        assert len(outlines) == len(tent.patches)
        for i, (patch, outline) in enumerate(zip(tent.patches, outlines)):
            assert outline.shape == patch.outer.shape
            expected = patch.outer @ state.rotations[i].T + state.translations[i]
            np.testing.assert_allclose(outline, expected, rtol=0, atol=1e-9 * tent.size())


def test_tent_closes_flat(tent, sweep):
    closed = popupcore.posed_outlines(tent, sweep.states[-1])
    # Closed card: everything in the page plane x = 0 (thesis frame).
    assert max(np.abs(o[:, 0]).max() for o in closed) <= 1e-6 * tent.size()


def test_brep_text(tent, sweep):
    for text in (
        popupcore.design_to_brep(tent),
        popupcore.patches_to_brep(tent, sweep.states[1]),
        popupcore.patches_to_brep(tent, sweep.states[1], thickness=0.3),
    ):
        assert isinstance(text, str) and "CASCADE Topology" in text


# --- bad design files: DesignError naming the item --------------------------------------------


def test_design_error_is_a_value_error():
    assert issubclass(popupcore.DesignError, ValueError)


def test_malformed_json():
    message = design_error('{"format": "popup-design", "patches": [')
    assert "JSON" in message


def test_not_a_design():
    message = design_error("[1, 2, 3]")
    assert "(root)" in message


def test_missing_field():
    raw = design_dict("tent_fold.json")
    del raw["patches"][0]["outline"]
    message = design_error(raw)
    assert "patches[0].outline" in message and "missing" in message


def test_null_coordinate():
    # JSON has no NaN: writers emit null for it.
    raw = design_dict("tent_fold.json")
    raw["patches"][0]["outline"][1][2] = None
    message = design_error(raw)
    assert "patches[0].outline[1][2]" in message


def test_nan_literal_is_rejected():
    text = json.dumps(design_dict("tent_fold.json"))
    raw = design_dict("tent_fold.json")
    raw["patches"][1]["outline"][0][0] = float("nan")
    text = json.dumps(raw)  # Python writes the non-standard literal NaN
    assert "NaN" in text
    design_error(text)


def test_infinite_coordinate():
    raw = design_dict("tent_fold.json")
    raw["patches"][1]["outline"][0][0] = 123456.0
    text = json.dumps(raw).replace("123456.0", "1e999", 1)
    message = design_error(text)
    # Overflow is caught by the JSON parser, before any field is read: the value is named.
    assert "1e999" in message


def test_hinge_off_its_patches(tent):
    raw = design_dict("tent_fold.json")
    hinge = raw["hinges"][0]
    normal = next(p.normal for p in tent.patches if p.id == hinge["patches"][0])
    shift = 5.0 * normal
    hinge["from"] = list(np.array(hinge["from"]) + shift)
    hinge["to"] = list(np.array(hinge["to"]) + shift)
    message = design_error(raw)
    assert f"hinge {hinge.get('id', 0)}" in message


def test_non_planar_patch(tent):
    raw = design_dict("tent_fold.json")
    i = next(k for k, p in enumerate(raw["patches"]) if len(p["outline"]) >= 4)
    patch = tent.patches[i]
    raw["patches"][i]["outline"][2] = list(
        np.array(raw["patches"][i]["outline"][2]) + 3.0 * patch.normal
    )
    message = design_error(raw)
    assert f"patch {patch.id}" in message
    assert "planar" in message


def test_empty_scaffold():
    raw = design_dict("tent_fold.json")
    raw["patches"] = []
    raw["hinges"] = []
    raw["glue"] = []
    message = design_error(raw)
    assert "no patches" in message


def test_missing_design_file(tmp_path):
    path = str(tmp_path / "nowhere.json")
    with pytest.raises(popupcore.DesignError) as info:
        popupcore.load_scaffold(path)
    assert path in str(info.value)


def test_design_error_lists_every_finding(tent):
    raw = design_dict("tent_fold.json")
    raw["patches"][0]["id"] = raw["patches"][1]["id"]  # duplicate id
    raw["paper_thickness"] = -1.0
    message = design_error(raw)
    assert "used twice" in message and "paper thickness" in message


# --- exception translation --------------------------------------------------------------------


@pytest.mark.parametrize(
    "kind, exception",
    [
        ("occt", popupcore.OcctError),
        ("cgal", popupcore.CgalError),
        ("std", RuntimeError),
        ("invalid_argument", ValueError),
    ],
)
def test_native_exceptions_are_translated(kind, exception):
    with pytest.raises(exception) as info:
        popupcore._raise_native(kind, "boom from " + kind)
    assert "boom from " + kind in str(info.value)


def test_native_error_classes():
    assert issubclass(popupcore.OcctError, RuntimeError)
    assert issubclass(popupcore.CgalError, RuntimeError)


# --- the GIL ----------------------------------------------------------------------------------


def test_simulate_fold_releases_the_gil(tent):
    """While a long simulation runs in a thread, the main thread keeps running Python.

    With the GIL held, the main thread would stall for the whole call; released, its longest
    pause stays far below the call's duration.
    """
    count = 181
    while True:  # enough angles for one call to take a quarter of a second
        angles = list(np.linspace(math.pi, 0.0, count))
        started = time.perf_counter()
        popupcore.simulate_fold(tent, angles)
        duration = time.perf_counter() - started
        if duration >= 0.25 or count >= 500_000:
            break
        count = int(count * min(10.0, max(2.0, 0.3 / max(duration, 1e-4))))

    call = {}

    def work():
        begin = time.perf_counter()
        call["sweep"] = popupcore.simulate_fold(tent, angles)
        call["duration"] = time.perf_counter() - begin

    worker = threading.Thread(target=work)
    longest_pause = 0.0
    worker.start()
    last = time.perf_counter()
    while worker.is_alive():
        now = time.perf_counter()
        longest_pause = max(longest_pause, now - last)
        last = now
    worker.join()
    assert call["sweep"].complete
    assert call["duration"] >= 0.1, "the call is too short for the check to mean anything"
    assert longest_pause < 0.5 * call["duration"]


def test_closed_forms_refuse_what_they_cannot_answer():
    nan = float("nan")
    cases = [
        (popupcore.box_fold_section, (popupcore.BoxFoldParams(), nan), "opening = nan"),
        (popupcore.tent_apex, (popupcore.TentFoldParams(), 100.0), "must be 0 to π"),
        (popupcore.v_fold_wings, (popupcore.VFoldParams(), -1.0, 1.0), "design_opening = -1"),
        (
            popupcore.horizontal_translation_tip,
            (popupcore.HorizontalTranslationParams(), -3.0),
            "opening = -3",
        ),
    ]
    for function, args, words in cases:
        with pytest.raises(ValueError, match=words):
            function(*args)
    broken = popupcore.TentFoldParams()
    broken.slope = nan
    with pytest.raises(ValueError, match="tent_apex: no closed form"):
        popupcore.tent_apex(broken, 1.0)
    # In range, the tent's apex stands on the mid-plane (x = 0) above the fold.
    apex = popupcore.tent_apex(popupcore.TentFoldParams(), 1.0)
    assert abs(apex[0]) < 1e-12 and apex[1] > 0


def test_unhelpful_failures_now_say_what_is_wrong():
    with pytest.raises(popupcore.DesignError, match="not valid Unicode") as caught:
        popupcore.scaffold_from_json('"\ud800"')
    assert caught.value.diagnostics[0]["code"] == "bad_json"
    box = load(os.path.join("mechanisms", "box.json"))
    state = popupcore.simulate_fold(box, [math.pi]).states[0]
    with pytest.raises(ValueError, match=r"thickness = 1e\+308 mm, must be 0 to 17\.2"):
        popupcore.patches_to_brep(box, state, 1e308)
