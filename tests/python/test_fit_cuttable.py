"""Fitted designs a maker can cut and FreeCAD can rebuild (issue 12 follow-up).

- Narrow mechanisms made uncuttable sheets: the truck and the L building must come back with
  sheets free of errors (no_room_for_tab), and FitOptions.min_part_mm must be the shortest
  crease that carries the narrowest default glue tab, derived here from the sheet options.
- Fitted parameters landed exactly on a generator's bound (truck, seed 2: a step as long as its
  box), where FreeCAD's rebuild refused them: every mechanism fitted for seeds 1..5 of each model
  is rebuilt through the FreeCAD features without error."""

import math
import os

import pytest

from cli_runner import read_report
from test_cli_fit import UPRIGHT, fit, make_models

MODELS = ("cuboid", "house", "truck", "tent", "l_building", "blob", "figure")


@pytest.fixture(scope="module")
def model_files(tmp_path_factory):
    folder = tmp_path_factory.mktemp("cuttable_models")
    return {name: make_models.write_model(name, str(folder / f"{name}.stl")) for name in MODELS}


def test_min_part_default_is_the_shortest_crease_of_the_narrowest_default_tab(freecad):
    from popupwb.core import popupcore
    from popupwb.sheets import sheet_options

    defaults = {o.name: o for o in sheet_options.SHEET_OPTIONS}
    assert {"min_tab_width", "tab_angle"} <= set(defaults)
    core = popupcore.SheetOptions()
    # glue_tabs.cpp: a tab is at most 0.45 · crease · tan(angle) deep, and may be held back by a
    # fifth of the crease at each end: 3 / (0.45 · 1 · 0.6) = 11.11 mm for the defaults.
    expected = core.min_tab_width / (0.45 * math.tan(math.radians(core.tab_angle)) * 0.6)
    assert core.min_tab_width == 3.0 and core.tab_angle == 45.0
    assert popupcore.FitOptions().min_part_mm == pytest.approx(expected, rel=1e-12)
    assert expected == pytest.approx(11.111, abs=1e-3)


@pytest.mark.parametrize("name", ["truck", "l_building"])
def test_sheets_of_truck_and_l_building_have_no_errors(name, model_files, tmp_path, user_home):
    from popupwb.core import popupcore

    proc = fit(model_files[name], tmp_path, *UPRIGHT, home=user_home)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    report = read_report(tmp_path)
    sheets = read_report(tmp_path, "sheets")
    assert report["valid"] is True and report["sheets_ok"] is True
    assert sheets["errors"] == [], sheets["errors"]
    # Every glued crease of a box fold is at least min_part_mm (less the range margin).
    shortest = popupcore.FitOptions().min_part_mm - 1e-3
    for m in report["mechanisms"]:
        q = m["parameters"]
        assert q["width"] >= shortest, m
        if m["type"] == "box_fold":
            for key in ("depth_ground", "depth_backdrop", "height"):
                assert q[key] >= shortest, m


def _rebuild_all(freecad, path, alignment, min_part_mm):
    """[(model, seed, error)] for every fitted design of `path` that FreeCAD cannot rebuild."""
    from popupwb.model import card_scaffold
    from popupwb.fitting import fit_run
    from popupwb.fitting.design_from_fit import build_design

    failures = []
    model, _ = fit_run.read_model(path)
    model, _ = fit_run.clean_model(model)
    for seed in range(1, 6):
        # The card `popup fit` makes for its default paper.
        card_size = fit_run.card_size_for_paper("A4")
        options = fit_run.fit_options(seed=seed, card_size=card_size, **alignment)
        if min_part_mm is not None:
            options.min_part_mm = min_part_mm
        try:
            result = fit_run.fit(model, options)
        except Exception as e:  # no design at all is not this test's concern
            if "no_design_found" in str(e) or "no valid design" in str(e):
                continue
            raise
        doc = freecad.newDocument(f"Rebuild{seed}")
        try:
            design = build_design(doc, result, model, source_file=path)
            built = card_scaffold.for_card(design.card)
            problems = ([built.card_error] if built.card_error else []) + list(
                built.errors.values()
            )
            if problems:
                failures.append((os.path.basename(path), seed, problems))
        finally:
            freecad.closeDocument(doc.Name)
    return failures


# min_part_mm 0 gives the thin mechanisms of before, among them the truck's seed-2 step exactly
# as long as its box's side (upright): the range margin alone must keep it buildable.
@pytest.mark.parametrize("min_part_mm", [None, 0.0])
@pytest.mark.parametrize("aligned", ["upright", "default"])
def test_every_fitted_mechanism_rebuilds_in_freecad_for_seeds_1_to_5(
    aligned, min_part_mm, model_files, freecad
):
    alignment = {"up": (0, 0, 1), "facing": (0, -1, 0)} if aligned == "upright" else {}
    failures = []
    for name in MODELS:
        failures += _rebuild_all(freecad, model_files[name], alignment, min_part_mm)
    assert failures == []
