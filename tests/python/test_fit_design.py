"""popupcore.fit_design as bound: numbers of a fitted cuboid and a roofed house, checked against
their known boxes, and the errors of bad options."""

import math
import threading

import numpy as np
import pytest

import popupcore


def box_mesh(lo, hi):
    """A closed box [lo, hi], triangles counter-clockwise seen from outside."""
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    v = np.array(
        [
            [x0, y0, z0],
            [x1, y0, z0],
            [x1, y1, z0],
            [x0, y1, z0],
            [x0, y0, z1],
            [x1, y0, z1],
            [x1, y1, z1],
            [x0, y1, z1],
        ],
        dtype=float,
    )
    quads = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    t = []
    for a, b, c, d in quads:
        t += [(a, b, c), (a, c, d)]
    return v, np.array(t, dtype=np.int32)


def expected_scale(length, half_depth, height, o):
    # docs/MATH.md, Fitting: closed, the box reaches height + half depth on a page and its end
    # panels stand out of its ends by its half depth.
    return min(
        o.card_width * (1 - 2 * o.margin) / (length + 2 * half_depth),
        o.card_depth * (1 - 2 * o.margin) / (height + half_depth),
    )


def test_cuboid_gives_one_box_fold_of_its_size():
    v, t = box_mesh((-20, 0, 0), (20, 120, 30))
    o = popupcore.FitOptions()
    r = popupcore.fit_design(popupcore.ModelMesh(v, t, "cuboid"), o)
    assert r.valid
    assert [m.type for m in r.mechanisms] == ["box_fold"]
    box = r.mechanisms[0]
    assert box.name == "B1" and box.host == "central fold"
    s = expected_scale(120, 20, 30, o)
    p = box.parameters
    assert p["width"] == pytest.approx(120 * s, rel=0.02)
    assert p["height"] == pytest.approx(30 * s, rel=0.02)
    assert p["depth_ground"] == pytest.approx(20 * s, rel=0.02)
    assert p["depth_backdrop"] == pytest.approx(20 * s, rel=0.02)
    assert p["front"] == 1 and p["back"] == 1
    # model_to_card: a similarity of scale s taking the base to z = 0 and the length to the
    # card's middle.
    m = np.asarray(r.model_to_card)
    assert m.shape == (4, 4)
    linear = m[:3, :3]
    assert np.allclose(linear @ linear.T, s * s * np.eye(3), atol=1e-6 * s * s)
    card_vertices = (m @ np.c_[v, np.ones(len(v))].T).T[:, :3]
    assert card_vertices[:, 2].min() == pytest.approx(0, abs=1e-9)
    assert card_vertices[:, 2].max() == pytest.approx(30 * s, rel=1e-9)
    assert card_vertices[:, 1].mean() == pytest.approx(o.card_width / 2, rel=1e-9)
    assert card_vertices[:, 0].max() == pytest.approx(20 * s, rel=1e-6)
    # The primitive is the same box, 8 corners in card mm.
    prim = r.primitives[0]
    assert prim.kind == "rectangular" and prim.host == "central fold"
    corners = np.asarray(prim.corners)
    assert corners.shape == (8, 3)
    assert corners[:, 2].max() == pytest.approx(30 * s, rel=0.02)
    assert r.coverage >= 0.95
    assert [stage for stage, _ in r.timings][:5] == [
        "align",
        "sample",
        "fit_primitives",
        "map",
        "validate",
    ]
    assert all(seconds >= 0 for _, seconds in r.timings)
    assert popupcore.check_validity(r.scaffold).valid
    assert r.card.width == o.card_width and r.card.depth == o.card_depth


def test_house_gets_a_tent_on_its_box_and_same_seed_same_design():
    body_v, body_t = box_mesh((-30, 0, 0), (30, 100, 24))
    # The roof as a closed triangular prism on the body (touching it, like a part).
    rv = np.array(
        [[-30, 0, 24], [30, 0, 24], [0, 0, 42], [-30, 100, 24], [30, 100, 24], [0, 100, 42]],
        dtype=float,
    )
    rt = np.array(
        [
            [0, 2, 1],
            [3, 4, 5],
            [0, 1, 4],
            [0, 4, 3],
            [1, 2, 5],
            [1, 5, 4],
            [2, 0, 3],
            [2, 3, 5],
        ],
        dtype=np.int32,
    )
    rt = rt[:, ::-1]  # written clockwise above: turned to face out
    v = np.vstack([body_v, rv])
    t = np.vstack([body_t, rt + len(body_v)])
    mesh = popupcore.ModelMesh(v, t, "house")
    o = popupcore.FitOptions()
    o.seed = 5
    a = popupcore.fit_design(mesh, o)
    b = popupcore.fit_design(mesh, o)
    assert a.valid
    assert [(m.type, m.host) for m in a.mechanisms] == [
        ("box_fold", "central fold"),
        ("tent_fold", "B1.top"),
    ]
    s = expected_scale(100, 30, 42, o)
    roof = a.mechanisms[1].parameters
    assert roof["slope"] == pytest.approx(math.hypot(30, 18) * s, abs=0.02 * 42 * s)
    assert roof["foot"] == pytest.approx(30 * s, abs=0.02 * 60 * s)
    assert [m.parameters for m in a.mechanisms] == [m.parameters for m in b.mechanisms]
    assert np.array_equal(np.asarray(a.model_to_card), np.asarray(b.model_to_card))


def test_up_and_facing_are_none_or_three_numbers():
    o = popupcore.FitOptions()
    assert o.up is None and o.facing is None
    o.up = [0, 0, 2]
    assert o.up == (0.0, 0.0, 2.0)
    with pytest.raises(popupcore.DesignError, match="up"):
        o.up = [1, 2]
    o.up = None
    assert o.up is None


def test_bad_options_name_the_option_and_its_range():
    v, t = box_mesh((-20, 0, 0), (20, 120, 30))
    o = popupcore.FitOptions()
    o.probability = 2.0
    with pytest.raises(popupcore.DesignError) as e:
        popupcore.fit_design(popupcore.ModelMesh(v, t), o)
    assert "FitOptions.probability = 2" in str(e.value)
    assert "> 0 and < 1" in str(e.value)
    assert e.value.diagnostics[0]["code"] == "bad_option"
    assert e.value.diagnostics[0]["parameter"] == "probability"


def test_cancel_flag_stops_it():
    v, t = box_mesh((-20, 0, 0), (20, 120, 30))
    flag = popupcore.CancelFlag()
    flag.cancel()
    with pytest.raises(popupcore.Cancelled):
        popupcore.fit_design(popupcore.ModelMesh(v, t), popupcore.FitOptions(), cancel=flag)


def test_gil_is_released_while_fitting():
    v, t = box_mesh((-20, 0, 0), (20, 120, 30))
    mesh = popupcore.ModelMesh(v, t)
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(1)
            done.wait(0.005)

    thread = threading.Thread(target=tick)
    thread.start()
    popupcore.fit_design(mesh)
    done.set()
    thread.join()
    assert len(ticks) >= 3
