"""popupcore.design_motion as bound: a trajectory file (an arm swinging about a fixed shoulder, a
still body) designed into a card, the report's numbers re-derived here from its own arrays, the
seed, progress, cancel and bad options."""

import json
import math
import threading

import numpy as np
import pytest

import popupcore


def write_trajectories(path, frames=25):
    arm, body = [], []
    for k in range(frames):
        a = math.radians(90 * k / (frames - 1))  # a quarter turn about the shoulder
        arm.append([-40 * math.sin(a), 40 * math.cos(a), 0])
        body.append([30, -20, 0])
    doc = {
        "format": "popup-trajectories",
        "version": 1,
        "frame_rate": 25,
        "effectors": [
            {"name": "arm", "root": [0, 0, 0], "points": arm},
            {"name": "body", "root": [30, 10, 0], "points": body},
        ],
    }
    path.write_text(json.dumps(doc))
    return str(path)


def quick(seed=1, iterations=600):
    o = popupcore.MotionOptions()
    o.iterations = iterations
    o.seed = seed
    return o


@pytest.fixture(scope="module")
def animation(tmp_path_factory):
    return popupcore.load_trajectories(write_trajectories(tmp_path_factory.mktemp("m") / "t.json"))


def test_design_motion_report_is_consistent_with_its_own_paths(animation):
    r = popupcore.design_motion(animation, quick())
    assert isinstance(r.valid, bool)
    assert r.iterations == 2 * 600
    names = [c.name for c in r.chains]
    assert len(names) == len(r.targets.chains)
    total = 0.0
    diagonal = r.targets.diagonal_mm
    for c in r.chains:
        target, achieved = np.asarray(c.target), np.asarray(c.achieved)
        assert target.shape == achieved.shape == (len(c.s), 2)
        # Eq 6.6 from the arrays: the RMS distance of the two paths.
        rms = math.sqrt(np.mean(np.sum((target - achieved) ** 2, axis=1)))
        assert c.error_mm == pytest.approx(rms, abs=1e-9)
        assert c.error == pytest.approx(rms / diagonal, abs=1e-12)
        assert c.status in ("animated", "merged", "stationary")
        assert c.mapping in ("vertical", "diagonal", "horizontal", "rotation", "stationary")
        if c.status != "animated":
            assert c.reason
        total += c.weight * c.error
    assert r.weighted_error == pytest.approx(total, abs=1e-12)
    stages = [s for s, _ in r.timings]
    assert stages[0] == "targets" and stages[-1] == "total"
    assert all(t >= 0 for _, t in r.timings)
    # A v-fold's wings carry the diagonal's step; a floating layer's side pairs carry a rotation
    # off the central fold.
    hosts = {"central fold"} | {
        m.name + part for m in r.mechanisms for part in (".wings", ".side_ground", ".side_backdrop")
    }
    for m in r.mechanisms:
        assert m.host in hosts
        assert m.type in (
            "rotation_arm",
            "vertical_translation",
            "horizontal_translation",
            "v_fold",
            "step_fold",
            "floating_layer",
        )
    if r.valid:
        assert popupcore.check_validity(r.scaffold).valid


def test_same_seed_same_design(animation):
    a = popupcore.design_motion(animation, quick(5))
    b = popupcore.design_motion(animation, quick(5))
    assert [(m.name, m.parameters) for m in a.mechanisms] == [
        (m.name, m.parameters) for m in b.mechanisms
    ]
    assert a.cost == b.cost


def test_progress_reaches_one_and_cancel_raises(animation):
    progress = popupcore.MotionProgress()
    popupcore.design_motion(animation, quick(), progress=progress)
    assert progress.value == pytest.approx(1.0)
    flag = popupcore.CancelFlag()
    flag.cancel()
    with pytest.raises(popupcore.Cancelled):
        popupcore.design_motion(animation, quick(), cancel=flag)


def test_cancel_from_another_thread_stops_a_long_search(animation):
    flag = popupcore.CancelFlag()
    timer = threading.Timer(0.2, flag.cancel)
    timer.start()
    with pytest.raises(popupcore.Cancelled):
        popupcore.design_motion(animation, quick(iterations=10_000_000), cancel=flag)
    timer.cancel()


def test_bad_options_name_the_option(animation):
    o = quick()
    o.search_chains = 0
    with pytest.raises(popupcore.DesignError, match="search_chains"):
        popupcore.design_motion(animation, o)
    o = quick()
    o.iterations = -3
    with pytest.raises(popupcore.DesignError, match="iterations"):
        popupcore.design_motion(animation, o)
