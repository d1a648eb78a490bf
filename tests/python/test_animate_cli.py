"""`popup animate ANIMATION --out DIR`, run as a maker would, on hand-written BVH files
(bvh_samples.py): exit 0 with design.FCStd, report.json, paths.png, motion.gif and sheets that
`popup verify` accepts; 2 with one named error line for files it cannot use.

Known answers come from how the BVH was written, never from the pipeline: the waving hand's
target path, put back through report.json's animation_to_card, is the arc the BVH's channels
draw; the GIF has the movie's frame count and size; the report's totals are re-added from its
own rows and its mechanisms are the document's features."""

import math
import os

import numpy as np
import pytest

import bvh_samples
from cli_runner import assert_input_refused, assert_named_error, popup, read_report, run_design

REPORT_KEYS = {
    "valid": bool,
    "chains": list,
    "weighted_error": float,
    "iterations": int,
    "timings_s": dict,
    "mechanisms": list,
    "number_of_mechanisms": int,
    "targets": dict,
    "animation": dict,
}
CHAIN_KEYS = {"name", "mechanism", "error", "weight", "status", "reason"}
ITERATIONS = "1500"
SEED = "2"

MAPPINGS = ("vertical", "diagonal", "horizontal", "rotation", "stationary")


def animate(path, out, *extra, home=None):
    return run_design("animate", path, out, *extra, home=home)


@pytest.fixture(scope="module")
def wave(tmp_path_factory):
    return bvh_samples.write_bvh(tmp_path_factory.mktemp("bvh") / "wave.bvh")


@pytest.fixture(scope="module")
def waved(wave, tmp_path_factory, user_home):
    out = tmp_path_factory.mktemp("wave")
    proc = animate(wave, out, "--seed", SEED, "--iterations", ITERATIONS, home=user_home)
    return out, proc, read_report(out)


def test_a_waving_figure_writes_its_files(waved):
    out, proc, report = waved
    assert proc.returncode in (0, 1), proc.stdout + proc.stderr
    for name in ("design.FCStd", "report.json", "paths.png", "motion.gif"):
        assert os.path.isfile(os.path.join(out, name)), name
    assert "popup animate: reading" in proc.stderr and "designing" in proc.stderr
    assert report["core_valid"] is True and report["validity"]["valid"] is True


def test_a_waving_figure_exits_0_with_sheets(waved):
    out, proc, report = waved
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert os.path.isfile(os.path.join(out, "sheets", "sheets.dxf"))
    assert "valid design" in proc.stdout.splitlines()
    assert report["valid"] is True and report["sheets_ok"] is True


def test_the_report_has_every_key_with_its_type(waved):
    report = waved[2]
    for key, kind in REPORT_KEYS.items():
        assert isinstance(report[key], kind), key
    for chain in report["chains"]:
        assert set(chain) >= CHAIN_KEYS
        assert chain["status"] in ("animated", "merged", "stationary")
        assert (chain["reason"] == "") == (chain["status"] == "animated") or chain["reason"]
    # The weighted total is the chains' errors weighted by their vertex (here bone-length)
    # shares, which sum to one.
    weights = [c["weight"] for c in report["chains"]]
    assert sum(weights) == pytest.approx(1.0, abs=1e-9)
    assert report["weighted_error"] == pytest.approx(
        sum(c["weight"] * c["error"] for c in report["chains"]), rel=1e-9, abs=1e-12
    )
    # E_m / diagonal: the millimetre errors over the character's diagonal on the card.
    diagonal = report["targets"]["diagonal_mm"]
    for chain in report["chains"]:
        assert chain["error"] == pytest.approx(chain["error_mm"] / diagonal, rel=1e-9, abs=1e-12)
    # The reach floor, recomputed from the path and the card: the RMS of how far each target lies
    # beyond depth·sin(θ/2) across the fold (θ = 180°·s); no chain's error is below it.
    depth = report["card"]["depth_mm"]
    for chain in report["chains"]:
        short = [
            max(0.0, abs(x) - depth * math.sin(math.pi * s / 2))
            for s, (x, _) in zip(chain["s"], chain["target"])
        ]
        floor = math.sqrt(sum(d * d for d in short) / len(short))
        assert chain["floor_mm"] == pytest.approx(floor, rel=1e-9, abs=1e-9)
        assert chain["floor"] == pytest.approx(floor / diagonal, rel=1e-9, abs=1e-12)
        assert chain["floor_mm"] <= chain["error_mm"] + 1e-9
        # The best one mechanism alone is a mechanism on this card: the floor holds for it too.
        assert chain["floor_mm"] <= chain["bound_mm"] + 1e-9
        assert chain["bound"] == pytest.approx(chain["bound_mm"] / diagonal, rel=1e-9, abs=1e-12)
        assert chain["bound_mechanism"] in MAPPINGS + ("printed",)
    assert max(c["floor_mm"] for c in report["chains"]) > 5.0  # the hands start far off the fold
    assert report["weighted_floor"] == pytest.approx(
        sum(c["weight"] * c["floor"] for c in report["chains"]), rel=1e-9, abs=1e-12
    )
    assert report["weighted_bound"] == pytest.approx(
        sum(c["weight"] * c["bound"] for c in report["chains"]), rel=1e-9, abs=1e-12
    )
    timings = report["timings_s"]
    assert "total" in timings and {"load", "design_other", "document", "movie"} <= set(timings)
    assert sum(v for k, v in timings.items() if k != "total") <= timings["total"] + 1e-6
    assert report["iterations"] >= int(ITERATIONS)
    assert report["animation"]["frames"] == bvh_samples.FRAMES


def _chain_of_bone(report, bone):
    names = [b["name"] for b in report["animation"]["bones"]]
    for target, chain in zip(report["targets"]["chains"], report["chains"]):
        if names.index(bone) in target["bones"]:
            return chain
    raise AssertionError(f"no chain holds {bone}")


def test_the_hand_target_is_the_arc_the_bvh_draws(waved):
    report = waved[2]
    matrix = np.array(report["targets"]["animation_to_card"])
    first, last = report["targets"]["first_frame"], report["targets"]["last_frame"]
    assert (first, last) == (0, bvh_samples.FRAMES - 1)
    hand = _chain_of_bone(report, "RightHand")
    s = np.array(hand["s"])
    assert s[0] == 0.0 and s[-1] == 1.0 and np.all(np.diff(s) > 0)
    expected = np.array([bvh_samples.hand(first + t * (last - first)) for t in s])
    expected = expected @ matrix[:3, :3].T + matrix[:3, 3]
    scale = abs(np.linalg.det(matrix[:3, :3])) ** (1 / 3)
    assert np.array(hand["target"]) == pytest.approx(expected[:, :2], abs=1e-6 * scale * 100)
    # The adaptive samples (τangle = 2°, core/include/popup/motion/adaptive_samples.hpp): an
    # interval is split while its quarter-point polyline turns by more than 2°; on a circle the
    # turn is a quarter of the interval's arc, so no interval of the 120° arc spans over 8°.
    assert np.max(np.diff(s)) * (bvh_samples.ARM_TO - bvh_samples.ARM_FROM) <= 8.0 + 1e-9


def test_the_waving_hand_is_a_rotation(waved):
    # A circle arc: the mapping Table 6.1 gives it is a rotation, animated. It turns about the
    # shoulder, off the fold: the arm stands on a floating layer's side pair (docs/MATH.md, A
    # rotation arm on a floating layer's side), which misses it by less than the translations.
    report = waved[2]
    hand = _chain_of_bone(report, "RightHand")
    assert (hand["mechanism"], hand["status"]) == ("rotation", "animated")
    carried = {m["name"]: m for m in report["mechanisms"] if m["name"] in hand["mechanisms"]}
    assert sorted(m["type"] for m in carried.values()) == ["floating_layer", "rotation_arm"]
    (arm,) = [m for m in carried.values() if m["type"] == "rotation_arm"]
    layer, side = arm["host"].rsplit(".", 1)
    assert layer in carried and side in ("side_ground", "side_backdrop")


def test_the_gif_is_the_movie(waved):
    from PIL import Image

    from popupwb.motion import motion_movie

    with Image.open(os.path.join(waved[0], "motion.gif")) as gif:
        assert gif.n_frames == motion_movie.FRAMES == 37
        assert gif.size == (2 * motion_movie.PANEL_PX, motion_movie.PANEL_PX + 28)
    with Image.open(os.path.join(waved[0], "paths.png")) as png:
        assert png.size == (1200, 900)


def test_the_document_holds_the_reported_mechanisms(waved, freecad):
    from popupwb.mechanism_registry import by_core_kind

    out, _, report = waved
    doc = freecad.openDocument(os.path.join(str(out), "design.FCStd"))
    try:
        mechanisms = [o for o in doc.Objects if hasattr(o, "HostPair")]
        assert [(o.Label, o.Proxy.TYPE) for o in mechanisms] == [
            (m["name"], by_core_kind(m["type"]).type_name) for m in report["mechanisms"]
        ]
        card = doc.getObject("Card")
        assert card.SourceAnimation.endswith("wave.bvh")
        assert (card.FirstFrame, card.LastFrame) == (0, bvh_samples.FRAMES - 1)
        # Each chain's mechanisms say, in their Chain property, that they move it.
        by_label = {o.Label: o for o in mechanisms}
        for chain in report["chains"]:
            for name in chain["mechanisms"]:
                assert chain["name"] in by_label[name].Chain.split(", "), (name, chain["name"])
        for o in mechanisms:
            o.touch()
        doc.recompute()
        assert not [o.Label for o in doc.Objects if "Invalid" in o.State]
    finally:
        freecad.closeDocument(doc.Name)


def test_popup_verify_accepts_the_sheets(waved, user_home):
    out = waved[0]
    proc = popup(
        "verify", os.path.join(out, "design.FCStd"), os.path.join(out, "sheets"), home=user_home
    )
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_the_same_seed_gives_the_same_design(wave, waved, tmp_path, user_home):
    proc = animate(wave, tmp_path, "--seed", SEED, "--iterations", ITERATIONS, home=user_home)
    assert proc.returncode == waved[1].returncode, proc.stderr
    again, first = read_report(tmp_path), waved[2]
    assert again["mechanisms"] == first["mechanisms"]
    assert again["chains"] == first["chains"]
    with open(os.path.join(tmp_path, "motion.gif"), "rb") as a, open(
        os.path.join(waved[0], "motion.gif"), "rb"
    ) as b:
        assert a.read() == b.read()


def _bad_animation(folder, kind):
    if kind == "empty":
        path = folder / "empty.bvh"
        path.write_bytes(b"")
    elif kind == "garbage":
        path = folder / "noise.bvh"
        path.write_bytes(np.random.default_rng(7).bytes(3000))
    elif kind == "nan":
        path = folder / "nan.bvh"
        bvh_samples.write_bvh(path, value="nan")
    elif kind == "single":
        path = folder / "still.bvh"
        bvh_samples.write_bvh(path, frames=1)
    else:
        path = folder / "missing.bvh"
    return str(path)


@pytest.mark.parametrize("kind", ["empty", "garbage", "nan", "single", "missing"])
def test_unusable_animations_exit_2_naming_the_file(kind, tmp_path, user_home):
    path = _bad_animation(tmp_path, kind)
    proc = animate(path, tmp_path / "out", home=user_home)
    assert_input_refused(proc, path, tmp_path / "out")


def test_a_single_frame_says_so(tmp_path, user_home):
    path = _bad_animation(tmp_path, "single")
    proc = animate(path, tmp_path / "out", home=user_home)
    assert_named_error(proc, "still.bvh")
    assert "frame" in proc.stderr.strip().splitlines()[-1].lower()


@pytest.mark.parametrize(
    "flags, fragment",
    [
        (("--seed", "-1"), "--seed -1"),
        (("--iterations", "0"), "--iterations 0"),
        (("--first-frame", "-2"), "--first-frame -2"),
        (("--first-frame", "5", "--last-frame", "5"), "--last-frame 5"),
        (("--view", "0,0,0"), "--view 0,0,0"),
        (("--up", "1,x,0"), "--up 1,x,0"),
        (("--scale", "nan"), "--scale nan"),
        (("--scale", "-2"), "--scale -2"),
        (("--paper", "B9"), "--paper B9"),
    ],
)
def test_bad_options_exit_2_naming_the_flag(wave, flags, fragment, tmp_path, user_home):
    assert_named_error(animate(wave, tmp_path / "out", *flags, home=user_home), fragment)


def test_a_last_frame_past_the_end_is_named(wave, tmp_path, user_home):
    proc = animate(wave, tmp_path / "out", "--last-frame", "99", home=user_home)
    assert_named_error(proc, "99")


def test_sheets_that_cannot_be_laid_out_are_reported_not_a_crash(tmp_path, user_home):
    """A valid design whose piece is larger than the paper (here a card too big for A4): the
    sheets' step says why, the report keeps it as sheets_error and the run's code is 1, so
    report.json is still written (01_03.bvh once ended with exit 2 and no report)."""
    import types

    from popupwb import cli
    from popupwb.cli import design_steps as steps
    from popupwb.core import popupcore
    from popupwb.fitting.fit_run import Stages

    card = popupcore.CardParams()
    card.width, card.depth = 300.0, 200.0
    design = str(tmp_path / "big.json")
    popupcore.save_scaffold(popupcore.make_card(card), design)
    said, report = [], {"valid": True}
    files = {"design": design}
    args = types.SimpleNamespace(out=str(tmp_path / "out"))
    status = steps.write_sheets(args, "A4", report, files, Stages(), said.append)
    assert status == cli.EXIT_INVALID
    assert "does not fit the printable area 190.0 x 277.0 mm of A4" in report["sheets_error"]
    assert any("no cutting sheets" in line for line in said)
    assert "sheets" not in files


def test_the_demos_figure_exits_0_with_sheets_that_glue(tmp_path, user_home):
    """`make demo`'s animation (resources/samples/waving_figure.glb): its design is valid and its
    sheets lay out without error. An outline that leaves a glue tab no room is dropped, and the
    report says which (the floating layer under the still foot, on the A4 card)."""
    sample = os.path.join(os.environ["POPUP_SOURCE_DIR"], "resources", "samples")
    out = tmp_path / "demo"
    proc = animate(os.path.join(sample, "waving_figure.glb"), out, home=user_home)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    report = read_report(out)
    assert report["sheets_ok"] is True
    dropped = [d["message"] for d in report["diagnostics"] if "could not glue it" in d["message"]]
    assert dropped and all(m.startswith("FloatingLayer_") for m in dropped), dropped
