"""`popup check` on a document with several cards: every card, or the one --card names, each with
its own verdict; exit 0 only when every checked card is valid."""

import json

import pytest

from cli_documents import BAD_OVERHANG, build_cards
from cli_runner import assert_clean_error, data, popup


@pytest.fixture(scope="module")
def cards(tmp_path_factory, user_home):
    return build_cards(tmp_path_factory.mktemp("cards"), user_home)


def test_check_reports_every_card_with_a_header(cards, user_home):
    proc = popup("check", str(cards / "two_cards.FCStd"), home=user_home)
    assert proc.returncode == 1, proc.stderr
    blocks = proc.stdout.split("\n\n")
    assert blocks[0].splitlines()[:2] == [
        "== Good ==",
        "VALID: foldable, stable, " "intersection-free, enclosed",
    ]
    bad = blocks[1].splitlines()
    assert bad[0] == "== Tall tent card (Bad) =="
    assert bad[1] == "INVALID: foldable, stable, intersection-free, NOT enclosed"
    assert f"sticks out of the closed card by {BAD_OVERHANG:g} mm" in blocks[1]
    assert proc.stdout.strip().splitlines()[-1] == "2 cards checked: 1 valid, 1 invalid"


def test_check_json_lists_a_report_per_card(cards, user_home):
    proc = popup("check", str(cards / "two_cards.FCStd"), "--json", home=user_home)
    assert proc.returncode == 1, proc.stderr
    result = json.loads(proc.stdout)
    assert result["valid"] is False
    assert result["file"] == str(cards / "two_cards.FCStd")
    assert "enclosed" not in result  # several cards: verdicts only per card
    by_name = {card["object"]: card for card in result["cards"]}
    assert list(by_name) == ["Good", "Bad"]  # document order
    assert by_name["Good"]["label"] == "Good" and by_name["Good"]["valid"] is True
    bad = by_name["Bad"]
    assert bad["label"] == "Tall tent card" and bad["valid"] is False
    assert (bad["foldable"], bad["stable"], bad["intersection_free"]) == (True, True, True)
    assert bad["enclosed"] is False
    assert any(f"by {BAD_OVERHANG:g} mm" in d["message"] for d in bad["diagnostics"])


@pytest.mark.parametrize(
    "card, name, status", [("Good", "Good", 0), ("Bad", "Bad", 1), ("Tall tent card", "Bad", 1)]
)
def test_card_option_checks_one_card_by_name_or_label(cards, user_home, card, name, status):
    proc = popup("check", str(cards / "two_cards.FCStd"), "--card", card, "--json", home=user_home)
    assert proc.returncode == status, proc.stderr
    result = json.loads(proc.stdout)
    # One card: its report at the top level, as for a document with one card, and in "cards".
    assert result["object"] == name and result["valid"] is (status == 0)
    assert [c["object"] for c in result["cards"]] == [name]
    assert result["cards"][0]["enclosed"] == result["enclosed"]

    text = popup("check", str(cards / "two_cards.FCStd"), "--card", card, home=user_home)
    assert text.returncode == status
    assert text.stdout.startswith("VALID" if status == 0 else "INVALID")  # no header for one


def test_unknown_card_lists_the_cards(cards, user_home):
    path = str(cards / "two_cards.FCStd")
    proc = popup("check", path, "--card", "Nope", home=user_home)
    assert_clean_error(proc, path, "--card Nope", "Good, Bad ('Tall tent card')")


def test_card_option_is_for_documents_only():
    design = data("tent_fold.json")
    assert_clean_error(popup("check", design, "--card", "Good"), "--card Good", design)


def test_a_json_design_keeps_its_flat_report():
    proc = popup("check", data("tent_fold.json"), "--json")
    assert proc.returncode == 0, proc.stderr
    result = json.loads(proc.stdout)
    assert result["valid"] is True and result["enclosed"] is True
    assert "cards" not in result and "object" not in result
