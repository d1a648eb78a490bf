"""motion_report: the report.json rows of `popup animate` from a motion result written by hand:
every required key with its type (docs/MOTION_REPORT.md), the chains' statuses gathered, paths
as nested lists, non-finite numbers as null, and the file re-read equal to what was built."""

import json
import math
import types

import numpy as np
import pytest


def _chain(name, mapping, status, reason="", error=0.01, weight=0.5):
    s = np.linspace(0.0, 1.0, 3)
    return types.SimpleNamespace(
        name=name,
        mapping=mapping,
        mechanisms=[f"{name}M"],
        error=error,
        error_mm=error * 200.0,
        floor=error / 2,
        floor_mm=error * 100.0,
        bound=error * 0.75,
        bound_mm=error * 150.0,
        bound_mechanism=mapping,
        weight=weight,
        status=status,
        reason=reason,
        s=s,
        target=np.c_[s, 2 * s],
        achieved=np.c_[s, 2 * s + 0.1],
    )


def _result(core):
    card = core.CardParams()
    card.width, card.depth = 186.0, 136.5
    chains = [
        _chain("LeftHand", "rotation", "animated", error=0.02, weight=0.6),
        _chain("RightHand", "rotation", "merged", "moves like LeftHand", weight=0.3),
        _chain("Tail", "stationary", "stationary", "collides with LeftHand", math.nan, 0.1),
    ]
    targets = types.SimpleNamespace(
        first_frame=0,
        last_frame=30,
        diagonal_mm=200.0,
        animation_to_card=np.eye(4),
        travel_removed_mm=0.0,
        window={"chosen": False, "score": 0.5, "whole_score": 0.5},
        chains=[
            types.SimpleNamespace(
                name=c.name,
                bones=[i, i + 1],
                parent_chain=-1,
                weight=c.weight,
                pruned=[],
                reach=40.0,
            )
            for i, c in enumerate(chains)
        ],
    )
    mechanism = types.SimpleNamespace(
        type="rotation_arm",
        name="LeftHandM",
        host="central fold",
        parameters={"offset": 10.0, "arm": 20.0},
    )
    return types.SimpleNamespace(
        card=card,
        chains=chains,
        targets=targets,
        mechanisms=[mechanism],
        valid=True,
        weighted_error=0.6 * 0.02 + 0.3 * 0.01,
        weighted_floor=0.6 * 0.01 + 0.3 * 0.005,
        weighted_bound=0.6 * 0.015 + 0.3 * 0.0075,
        iterations=3000,
        cost=12.5,
        diagnostics=[],
    )


def test_the_report_rows_and_their_types(tmp_path):
    from popupwb.core import popupcore
    from popupwb.motion.motion_report import build_report, write_report

    animation = types.SimpleNamespace(bones=[("Hips", -1), ("Arm", 0)], frames=31, mesh=None)
    report = build_report(
        animation_file="/x/wave.bvh",
        animation=animation,
        options={"seed": 1},
        result=_result(popupcore),
        validity={"valid": True, "diagnostics": []},
        stages=[("load", 0.5), ("design", 1.0), ("load", 0.25)],
        total_s=2.0,
        files={},
    )
    path = write_report(report, str(tmp_path / "report.json"))
    with open(path) as f:
        again = json.load(f)
    assert again == report
    assert again["valid"] is True and again["iterations"] == 3000
    assert again["weighted_error"] == pytest.approx(0.015)
    assert again["weighted_floor"] == pytest.approx(0.0075)
    assert again["chains"][0]["floor_mm"] == pytest.approx(2.0)
    assert [c["status"] for c in again["chains"]] == ["animated", "merged", "stationary"]
    assert again["merged"] == ["RightHand"] and again["stationary"] == ["Tail"]
    assert again["chains"][1]["reason"] == "moves like LeftHand"
    assert again["chains"][2]["error"] is None  # NaN is null in JSON
    assert again["chains"][0]["target"] == [[0.0, 0.0], [0.5, 1.0], [1.0, 2.0]]
    assert again["timings_s"] == {"load": 0.75, "design": 1.0, "total": 2.0}
    assert again["animation"]["bones"] == [
        {"name": "Hips", "parent": -1},
        {"name": "Arm", "parent": 0},
    ]
    assert again["mechanisms"][0]["parameters"] == {"arm": 20.0, "offset": 10.0}
    assert again["card"] == {"width_mm": 186.0, "depth_mm": 136.5}


def test_an_invalid_built_card_makes_the_report_invalid():
    from popupwb.core import popupcore
    from popupwb.motion.motion_report import build_report

    animation = types.SimpleNamespace(bones=[("Hips", -1)], frames=2, mesh=None)
    report = build_report(
        animation_file="a.bvh",
        animation=animation,
        options={},
        result=_result(popupcore),
        validity={"valid": False, "diagnostics": [{"code": "collision"}]},
        stages=[],
        total_s=1.0,
        files={},
    )
    assert report["valid"] is False and report["core_valid"] is True
    nothing = build_report(
        animation_file="a.bvh",
        animation=animation,
        options={},
        result=None,
        validity=None,
        stages=[],
        total_s=1.0,
        files={},
    )
    assert nothing["valid"] is False and nothing["chains"] == []
    assert nothing["weighted_error"] is None
