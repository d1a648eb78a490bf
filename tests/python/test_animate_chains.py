"""`popup animate --chains` and `--list-chains` (issue 26 item 1) on rig_four.bvh, four arms each
on one mechanism's closed form (tests/data/animations): the chains listed are the four arms, all
moving; animating two of them leaves the other two held still with the maker's reason; a name no
chain has is one error line naming it and the chains found."""

import os

import pytest

from cli_runner import assert_named_error, data, popup, read_report, run_design

RIG = "animations/rig_four.bvh"
ARMS = tuple(
    "EndSite_" + arm
    for arm in ("DiagonalArmFore", "HorizontalArmFore", "RotationArmFore", "VerticalArmFore")
)
CHOSEN = ("EndSite_RotationArmFore", "EndSite_VerticalArmFore")


@pytest.fixture(scope="module")
def listed(user_home):
    return popup("animate", data(RIG), "--list-chains", home=user_home)


@pytest.fixture(scope="module")
def chosen(tmp_path_factory, user_home):
    out = tmp_path_factory.mktemp("chosen")
    proc = run_design(
        "animate",
        data(RIG),
        out,
        "--chains",
        ",".join(CHOSEN),
        "--iterations",
        "1500",
        "--seed",
        "2",
        home=user_home,
    )
    assert proc.returncode in (0, 1), proc.stderr[-2000:]
    return read_report(out)


def test_list_chains_prints_the_arms_as_moving_and_designs_nothing(listed):
    assert listed.returncode == 0, listed.stderr
    lines = {line.split(":")[0]: line for line in listed.stdout.splitlines() if ": " in line}
    for arm in ARMS:
        assert arm in lines, listed.stdout
        assert lines[arm].endswith(", moving") and " bones, reach " in lines[arm], lines[arm]
    assert "chain(s); animate some with --chains" in listed.stdout
    assert "designing" not in listed.stderr


def test_the_chosen_arms_move_and_the_others_are_held_still_by_the_maker(chosen):
    chains = {c["name"]: c for c in chosen["chains"]}
    assert set(ARMS) <= set(chains)
    for name in CHOSEN:
        assert chains[name]["mechanism"] != "stationary", chains[name]
        assert "did not choose" not in chains[name]["reason"]
    for name in set(chains) - set(CHOSEN):
        assert chains[name]["mechanism"] == "stationary", chains[name]
        assert chains[name]["status"] in ("stationary", "merged"), chains[name]
        assert "the maker did not choose it to animate" in chains[name]["reason"], chains[name]
    # The report's options record the choice; the reach floor does not depend on it.
    assert chosen["options"]["animate_only"] == list(CHOSEN)
    assert all(c["floor"] >= 0 for c in chosen["chains"])


def test_an_unknown_chain_is_one_error_line_naming_it_and_the_chains_found(tmp_path, user_home):
    out = tmp_path / "out"
    proc = run_design(
        "animate", data(RIG), out, "--chains", "EndSite_RotationArmFore,Hand.L", home=user_home
    )
    assert_named_error(proc, "--chains", '"Hand.L"', *ARMS)
    assert not os.path.exists(out / "design.FCStd")


def test_an_empty_chain_list_is_refused(tmp_path, user_home):
    proc = run_design("animate", data(RIG), tmp_path / "out", "--chains", " , ", home=user_home)
    assert_named_error(proc, "--chains", "name at least one chain")


def test_designing_without_out_is_refused_naming_the_flag(user_home):
    proc = popup("animate", data(RIG), home=user_home)
    assert_named_error(proc, "--out DIR is required")
