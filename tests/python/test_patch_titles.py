"""Findings name patches as a maker does: "Box fold 'BoxFold': top, ground side [#5 BoxFold.TG]",
in the card's Diagnostics (what the report view shows) and in `popup check`'s text."""

import json
import re
import textwrap

import pytest

from cli_runner import popup, run_freecad_script

# A box fold and a step fold at the box's Offset on one A5 card (an explicit Offset: placement
# would put the step beside the box): the step sits inside the box, so the box's top halves pass
# through the step's riser and tread while the card closes.
BOX_AND_STEP = textwrap.dedent(
    """
    import sys
    import FreeCAD
    from popupwb import make

    doc = FreeCAD.newDocument("box_and_step")
    card = make.make_card(doc, preset="A5")
    box = make.make_box_fold(card)
    make.make_step_fold(card, offset=box.Offset.Value)
    doc.recompute()
    doc.saveAs(sys.argv[1])
    """
)


def _overlapping_card(doc):
    import popupwb.make as make

    card = make.make_card(doc, preset="A5")
    box = make.make_box_fold(card)
    make.make_step_fold(card, offset=box.Offset.Value)
    doc.recompute()
    return card


def _ids_by_name(card):
    from popupwb.model import card_scaffold

    return {p.name: p.id for p in card_scaffold.for_card(card).scaffold.patches}


def test_card_findings_name_patches_as_a_maker_does(doc):
    from popupwb import validity

    card = _overlapping_card(doc)
    ids = _ids_by_name(card)  # the ids from the scaffold itself, not from the message
    report = validity.run_check(card)
    assert report["valid"] is False
    top = f"Box fold 'BoxFold': top, ground side [#{ids['BoxFold.TG']} BoxFold.TG]"
    riser = f"Step fold 'StepFold': riser [#{ids['StepFold.riser']} StepFold.riser]"
    lines = list(card.Diagnostics)
    assert f"intersection: {top} passes through {riser}" in "\n".join(lines), lines
    # The raw "patch N (name)" form is gone from every line that names a patch of the card.
    assert not any(re.search(r"\bpatch [0-9]+ \(", line) for line in lines), lines


def test_a_renamed_mechanism_is_named_by_its_label(doc):
    from popupwb import validity

    card = _overlapping_card(doc)
    doc.getObject("BoxFold").Label = "Castle"
    doc.recompute()
    ids = _ids_by_name(card)
    validity.run_check(card)
    expected = f"Box fold 'Castle': top, backdrop side [#{ids['Castle.TB']} Castle.TB]"
    assert any(expected in line for line in card.Diagnostics), list(card.Diagnostics)


def test_popup_check_prints_the_maker_names(tmp_path, user_home):
    path = tmp_path / "box_and_step.FCStd"
    run_freecad_script(BOX_AND_STEP, path, home=user_home)
    proc = popup("check", str(path), home=user_home)
    assert proc.returncode == 1, proc.stderr
    assert "Box fold 'BoxFold': top, ground side [#" in proc.stdout
    assert "passes through Step fold 'StepFold': riser [#" in proc.stdout
    # --json keeps the core's message and adds the titles, keyed by patch id.
    report = json.loads(popup("check", str(path), "--json", home=user_home).stdout)
    finding = next(d for d in report["diagnostics"] if "(BoxFold.TG)" in d["message"])
    assert finding["message"].startswith("patch ")
    assert sorted(finding["patch_titles"].values()) == [
        "Box fold 'BoxFold': top, ground side",
        "Step fold 'StepFold': riser",
    ]


@pytest.mark.parametrize("index", range(9))
def test_every_part_the_core_builds_has_a_title(doc, index):
    """Drift guard: a part code the core adds without a title here would show as a bare code."""
    from popupwb import mechanism_catalogue, mechanism_registry, make
    from popupwb.model import card_scaffold
    from popupwb.validity import card_titles

    mechanism = mechanism_registry.MECHANISMS[index]
    card = make.make_card(doc, preset="A4")
    extra = {"panel_pairs": 2} if mechanism.feature.__name__ == "BoxFold" else {}
    getattr(make, mechanism.make_name)(card, **extra)
    doc.recompute()
    built = card_scaffold.for_card(card)
    assert not built.errors, built.errors
    titles = card_titles.titles_of_card(card, built)
    assert set(titles) == {p.id for p in built.scaffold.patches}
    table = mechanism_catalogue.part_titles(mechanism.feature.KIND)
    for patch in built.scaffold.patches[2:]:  # the card's ground and backdrop first
        part = patch.name.rsplit(".", 1)[-1]
        assert part.rstrip("0123456789") in table, patch.name
        assert titles[patch.id].startswith(f"{mechanism.menu_text} '{mechanism.feature.__name__}'")
    assert titles[built.scaffold.ground] == "Card 'Card': ground page"


def test_name_patches_leaves_unknown_patches_and_other_text_alone():
    from popupwb.core import popupcore
    from popupwb.patch_titles import name_patches

    assert popupcore.patch_subject(3, "Tent.slope_ground") == "patch 3 (Tent.slope_ground)"
    assert popupcore.patch_subject(3) == "patch 3"

    titles = {"3": "Tent fold 'Tent': slope, ground side"}  # as JSON gives the keys
    names = {"3": "Tent.slope_ground"}
    subjects = {"3": "patch 3 (Tent.slope_ground)"}  # popupcore.patch_subject(3, names["3"])
    message = "patch 3 (Tent.slope_ground) meets patch 4 (Tent.slope_backdrop); dispatch 3 (x)"
    assert name_patches(message, titles, subjects, names) == (
        "Tent fold 'Tent': slope, ground side [#3 Tent.slope_ground] meets patch 4 "
        "(Tent.slope_backdrop); dispatch 3 (x)"
    )
    unnamed = {"3": "patch 3"}  # popupcore.patch_subject(3)
    assert name_patches("patch 3 is stuck", titles, unnamed).startswith("Tent fold 'Tent'")
    assert name_patches("patch 30 is stuck", titles, unnamed) == "patch 30 is stuck"
    assert name_patches(message, None, subjects) == message
