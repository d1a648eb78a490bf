"""Windows (holes) in patches: paper passing through a window is not an intersection, paper that
hits the window's rim is; holes are validated (crossing, nested, either orientation); base
patches must lie where the design angle puts them. Designs: tests/data/windows/ (made here) and
the mechanism samples with a window cut into one patch."""

import copy
import json
import os

import popupcore
import pytest

SOURCE_DIR = os.environ.get("POPUP_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
FLAG = os.path.join(SOURCE_DIR, "tests", "data", "windows", "flag_through_window.json")
MECHANISMS = os.path.join(SOURCE_DIR, "tests", "data", "mechanisms")


def load(path):
    with open(path) as f:
        return json.load(f)


def check(design):
    return popupcore.check_validity(popupcore.scaffold_from_json(json.dumps(design)))


def refused(design):
    with pytest.raises(popupcore.DesignError) as caught:
        check(design)
    return caught.value.diagnostics


def window_in(design, patch_name, scale=0.5):
    """The design with a window in the named patch: its outline shrunk about its centroid,
    clockwise (as the format asks) seen from the patch's normal."""
    patch = next(p for p in design["patches"] if p["name"] == patch_name)
    outline = patch["outline"]
    centre = [sum(v[k] for v in outline) / len(outline) for k in range(3)]
    hole = [[c + scale * (v[k] - c) for k, c in enumerate(centre)] for v in outline]
    patch["holes"] = [hole[::-1]]
    return design


def test_a_flag_through_a_window_is_clear_and_without_it_is_not():
    flag = load(FLAG)
    assert check(flag).intersection_free
    closed = copy.deepcopy(flag)
    del closed["patches"][1]["holes"]
    report = check(closed)
    assert not report.intersection_free
    (hit,) = [d for d in report.diagnostics if d.code == "intersection"]
    assert set(hit.patches) == {1, 2}
    # A window too narrow: the flag meets the paper beyond its rim (x = -25 mm, the flag reaches
    # 36 mm from the fold).
    narrow = copy.deepcopy(flag)
    narrow["patches"][1]["holes"] = [[[-70, 80, 0], [-70, 120, 0], [-25, 120, 0], [-25, 80, 0]]]
    assert not check(narrow).intersection_free


def test_a_counter_clockwise_window_is_the_same_window():
    flag = load(FLAG)
    turned = copy.deepcopy(flag)
    turned["patches"][1]["holes"] = [flag["patches"][1]["holes"][0][::-1]]
    a, b = check(flag), check(turned)
    assert (a.foldable, a.stable, a.intersection_free, a.enclosed) == (
        b.foldable,
        b.stable,
        b.intersection_free,
        b.enclosed,
    )
    assert [d.code for d in a.diagnostics] == [d.code for d in b.diagnostics]


@pytest.mark.parametrize(
    "sample, patch",
    [("box.json", "BoxFold.FL"), ("step.json", "StepFold.riser"), ("box.json", "BoxFold.TG")],
)
def test_a_window_changes_no_verdict(sample, patch):
    design = load(os.path.join(MECHANISMS, sample))
    plain, windowed = check(design), check(window_in(copy.deepcopy(design), patch))
    verdict = lambda r: (r.foldable, r.stable, r.intersection_free, r.enclosed)  # noqa: E731
    assert verdict(windowed) == verdict(plain) == (True, True, True, True)
    assert [d.code for d in windowed.diagnostics if d.severity == "error"] == []


def test_holes_that_overlap_or_nest_are_named():
    flag = load(FLAG)
    nested = copy.deepcopy(flag)
    nested["patches"][1]["holes"].append([[-60, 90, 0], [-60, 110, 0], [-10, 110, 0], [-10, 90, 0]])
    (d,) = refused(nested)
    assert d["code"] == "holes_overlap" and d["patches"] == [1]
    assert "hole 1 and hole 2 lie one inside the other" in d["message"]
    crossing = copy.deepcopy(flag)
    crossing["patches"][1]["holes"].append(
        [[-100, 100, 0], [-100, 130, 0], [-50, 130, 0], [-50, 100, 0]]
    )
    (d,) = refused(crossing)
    assert d["code"] == "holes_overlap" and "cross or touch at (-70, 100, 0)" in d["message"]


def test_base_patches_off_the_design_angle_are_named():
    tent = load(os.path.join(SOURCE_DIR, "tests", "data", "tent_fold.json"))
    tent["design_angle_deg"] = 90.0  # coordinates are those of the card opened flat
    found = refused(tent)
    assert {d["code"] for d in found} == {"base_patch_misplaced"}
    assert {d["parameter"] for d in found} == {"design_angle"}
    ground = next(d for d in found if d["patches"] == [0])
    # Opened flat from 90°, the ground's far corner (140, 0, 0) rises 140 sin 45° = 98.99 mm.
    assert "would stand 98.99 mm off the page" in ground["message"]
    swapped = load(os.path.join(SOURCE_DIR, "tests", "data", "tent_fold.json"))
    swapped["ground"], swapped["backdrop"] = swapped["backdrop"], swapped["ground"]
    messages = [d["message"] for d in refused(swapped)]
    assert any("lies on the backdrop's side of the central fold" in m for m in messages)
