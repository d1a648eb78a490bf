"""Outlines on the organic models of the realistic corpus (tools/make_corpus.py, issue 25's goal:
outlines kept on at least half the principal patches of organic models). `popup fit` with the
automatic axes, as tools/corpus_results.py runs it; every design stays valid and its sheets
verify. The parts a silhouette leaves a fold of keep a bridge of paper to it
(core/src/fitting/fold_bridges.cpp) instead of losing their outline, so no profile is dropped
for missing a fold."""

import pytest

from cli_runner import load_tool, read_report, run_design

make_corpus = load_tool("make_corpus")

ORGANIC = [name for name, entry in make_corpus.CORPUS.items() if "organic" in entry["defects"]]
# fit_outlines.cpp's principal_parts: the parts that take the model's outline.
PRINCIPAL = {"box_fold": 8, "tent_fold": 2, "step_fold": 2, "v_fold": 2}


@pytest.fixture(scope="module")
def organic_fits(tmp_path_factory):
    fits = {}
    for name in ORGANIC:
        folder = tmp_path_factory.mktemp(name)
        model = make_corpus.write_corpus_model(
            name, str(folder / f"{name}.{make_corpus.CORPUS[name]['file']}")
        )
        out = folder / "fit"
        proc = run_design("fit", model, out, "--seed", "1")
        fits[name] = (proc, read_report(out))
    return fits


def test_the_corpus_has_the_organic_models():
    assert set(ORGANIC) >= {"statue_pedestal", "dog", "spider", "bust_scan", "bust_scan_dense"}


def test_every_organic_design_is_valid_and_its_sheets_verify(organic_fits):
    for name, (proc, report) in organic_fits.items():
        assert proc.returncode == 0, f"{name}: {proc.stderr}"
        assert report["valid"] is True and report["sheets_ok"] is True, name


def test_outlines_are_kept_on_at_least_half_the_principal_patches(organic_fits):
    kept = principal = 0
    for name, (_, report) in organic_fits.items():
        principal += sum(PRINCIPAL.get(m["type"], 0) for m in report["mechanisms"])
        kept += len(report["profiles"])
    assert principal > 0
    assert 2 * kept >= principal, f"{kept} outlines on {principal} principal patches"


def test_no_outline_is_dropped_for_leaving_a_fold(organic_fits):
    for name, (_, report) in organic_fits.items():
        for r in report["repairs"]:
            if r["action"] == "profile dropped":
                assert "leaves no paper along" not in r["reason"], f"{name}: {r['reason']}"
