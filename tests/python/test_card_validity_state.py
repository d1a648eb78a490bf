"""A card's Validity: NotChecked, Valid or Invalid, with the older boolean Valid kept in step and
files saved before Validity existed migrated on restore."""

import pytest


@pytest.fixture
def card(doc):
    from popupwb import make

    card = make.make_card(doc, preset="A6", name="Card")
    make.make_tent_fold(card, name="Tent")
    doc.recompute()
    return card


def test_a_new_card_is_not_checked(card):
    assert card.Validity == "NotChecked" and card.Valid is False
    assert card.getEnumerationsOfProperty("Validity") == ["NotChecked", "Valid", "Invalid"]
    assert card.getEditorMode("Validity") == ["ReadOnly"]


def test_the_check_and_a_design_change_move_the_verdict(doc, card):
    from popupwb.validity import run_check

    assert run_check(card)["valid"] is True
    assert (card.Validity, card.Valid, list(card.Diagnostics)) == ("Valid", True, [])
    assert "Touched" not in card.State  # a verdict does not ask for a recompute
    tent = doc.getObject("Tent")
    tent.Foot = -3.0  # the tent no longer builds: the check says so
    doc.recompute()
    report = run_check(card)
    assert report["valid"] is False
    assert (card.Validity, card.Valid) == ("Invalid", False) and len(card.Diagnostics) == 1
    tent.Foot = 10.0  # another design: the verdict is dropped, not kept as Invalid
    doc.recompute()
    assert (card.Validity, card.Valid, list(card.Diagnostics)) == ("NotChecked", False, [])


@pytest.mark.parametrize(
    "valid, diagnostics, expected",
    [
        (True, [], "Valid"),
        (False, ["intersection: Tent crosses the ground"], "Invalid"),
        (False, [], "NotChecked"),
    ],
)
def test_files_saved_with_only_valid_are_migrated(card, valid, diagnostics, expected):
    # An older file: Valid and Diagnostics, no Validity; restoring adds it from them.
    card.removeProperty("Validity")
    card.Valid = valid
    card.Diagnostics = diagnostics
    card.Proxy.onDocumentRestored(card)
    assert card.Validity == expected and card.Valid is valid
