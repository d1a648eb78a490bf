"""The NOT VALID stamp (popupwb.sheets.not_valid_stamp): its text from a validity report and its
place on a sheet, derived by hand from the paper size and margin."""

from popupwb.sheets.not_valid_stamp import NotValid, not_valid_of, stamp_label


def test_the_stamp_says_which_verdicts_failed():
    report = {"valid": False, "foldable": True, "stable": False, "intersection_free": True}
    report.update(
        enclosed=False,
        diagnostics=[
            {"code": "c", "message": "m", "patches": [], "parameter": None, "angle_deg": None}
        ],
    )
    not_valid = not_valid_of(report)
    assert not_valid.text() == "NOT VALID: not stable, not enclosed"
    # One line per finding, "code: message" (validity.format_diagnostic; its tail may name more).
    assert len(not_valid.findings) == 1 and not_valid.findings[0].startswith("c: m")
    assert not_valid_of({"valid": True, "diagnostics": []}) is None


def test_the_stamp_sits_in_the_top_margin_and_fits_the_width():
    label = stamp_label(210.0, 297.0, 10.0, NotValid("not enclosed"))
    assert label.text == "NOT VALID: not enclosed" and label.kind == "stamp"
    assert label.position == (105.0, 292.0)  # centred in the 10 mm band at the top
    assert label.height == 5.0  # the piece labels' size: 0.6 x 10 mm would be more
    long = stamp_label(100.0, 150.0, 10.0, NotValid("not foldable, not stable, not enclosed"))
    assert 1.5 <= long.height < 5.0  # shrunk to fit 80 mm across
