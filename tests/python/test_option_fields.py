"""The automatic designs' options come from the core's tables (popupcore.FitOptions.fields(),
MotionOptions.fields()): `popup fit --help` and `popup animate --help` show the core's ranges and
defaults, a value out of range is refused with the core's range named, the reports list every
field, and the results carry the no-mechanism rule and their total time themselves."""

import argparse

import pytest


@pytest.fixture(scope="module")
def core():
    from popupwb.core import popupcore

    return popupcore


def command_help(command):
    """`popup COMMAND --help` as argparse writes it, on one line."""
    from popupwb import cli

    parser = cli.build_parser()
    (commands,) = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
    return " ".join(commands.choices[command].format_help().split())


def fields(core, options_type):
    return {f.name: f for f in getattr(core, options_type).fields()}


def test_the_tables_hold_the_structs_defaults(core):
    fit = fields(core, "FitOptions")
    assert fit["max_mechanisms"].default == core.FitOptions().max_mechanisms == 8
    assert fit["max_mechanisms"].range == "1 to 32"
    assert fit["card_width"].default == core.FitOptions().card_width == core.CardParams().width
    assert fit["up"].kind == "direction" and fit["up"].default is None and fit["up"].optional
    motion = fields(core, "MotionOptions")
    assert motion["iterations"].default == core.MotionOptions().iterations
    assert motion["prune_fraction"].group == "chains"
    assert motion["card_depth"].group == "view"
    assert motion["card_depth"].default == core.MotionView().card_depth == core.CardParams().depth
    assert all(f.doc for f in list(fit.values()) + list(motion.values()))


def test_popup_fit_help_shows_the_cores_ranges_and_defaults(core):
    text = command_help("fit")
    fit = fields(core, "FitOptions")
    for name in ("max_mechanisms", "seed", "min_part_mm"):
        assert fit[name].range in text, name
    assert "at most this many mechanisms; 1 to 32; default 8" in text
    assert f"default {fit['min_part_mm'].default:g}" in text


def test_popup_animate_help_shows_the_cores_ranges_and_defaults(core):
    from popupwb.motion.motion_run import MIN_ITERATIONS

    text = command_help("animate")
    motion = fields(core, "MotionOptions")
    iterations = motion["iterations"]
    # A maker's run anneals at least once; the top of the range is the core's.
    assert f"{MIN_ITERATIONS} to {int(iterations.max)}; default {iterations.default}" in text
    for name in ("first_frame", "last_frame", "scale", "seed"):
        assert motion[name].range in text, name
    assert "default 0,0,-1" in text and "default 0,1,0" in text  # MotionView()'s view and up


def test_out_of_range_options_name_the_option_and_the_cores_range(core):
    from popupwb.fitting import fit_run
    from popupwb.motion import motion_run

    with pytest.raises(ValueError, match="max_mechanisms = 33, must be 1 to 32"):
        fit_run.fit_options(max_mechanisms=33)
    with pytest.raises(ValueError, match="seed = -1, must be 0 to"):
        fit_run.fit_options(seed=-1)
    with pytest.raises(ValueError, match="prune_fraction = 2, must be >= 0 and <= 1"):
        motion_run.motion_options(prune_fraction=2.0)
    # A rule between two options is the core's check: its own message.
    with pytest.raises(ValueError, match="MotionView.last_frame = 3, must be -1"):
        motion_run.motion_options(first_frame=3, last_frame=3)
    options = motion_run.motion_options(iterations=0, card_size=(100.0, 80.0))
    assert options.iterations == 0 and options.view.card.width == 100.0


def test_the_reports_list_every_field_of_the_tables(core):
    from popupwb.fitting import fit_run
    from popupwb.motion import motion_run

    fit = fit_run.options_dict(fit_run.fit_options(seed=3))
    assert set(fit) == set(fields(core, "FitOptions")) and fit["seed"] == 3
    motion = motion_run.options_dict(motion_run.motion_options(scale=2.5))
    groups = {}
    for field in core.MotionOptions.fields():
        groups.setdefault(field.group, set()).add(field.name)
    assert set(motion) == groups[""] | {"view", "chains"}
    assert set(motion["view"]) == groups["view"] and set(motion["chains"]) == groups["chains"]
    assert motion["view"]["scale"] == 2.5 and motion["view"]["up"] == [0.0, 1.0, 0.0]


def test_options_check_names_each_bad_option(core):
    options = core.MotionOptions()
    assert options.check() == []
    options.search_chains = 0
    options.view.margin = 0.5
    bad = options.check()
    assert [d["parameter"] for d in bad] == ["search_chains", "margin"]
    assert bad[1]["message"].startswith("MotionView.margin = 0.5, must be >= 0 and < 0.5")
    fit = core.FitOptions()
    fit.card = core.CardParams()
    fit.card_depth = 40.0
    assert [d["parameter"] for d in fit.check()] == ["min_part_mm"]  # > a quarter of 40 mm


def test_a_bare_card_does_not_pop_up_and_timings_carry_their_total(core):
    from test_fit_design import box_mesh

    v, t = box_mesh((-20, 0, 0), (20, 120, 30))
    r = core.fit_design(core.ModelMesh(v, t), core.FitOptions())
    assert r.valid and len(r.mechanisms) == 1 and r.pops_up
    timings = r.timings
    assert [name for name, _ in timings.stages][:2] == ["align", "sample"]
    assert timings.total_s + 1e-9 >= sum(seconds for _, seconds in timings.stages)
    assert list(timings)[-1] == ("total", timings.total_s)  # as report.json lists them
