"""The validity check: verdict.py the verdict a card records (below the features), report_text.py
the report as text, check.py the check runner. `popupwb.validity.run_check(card)` is the call the
commands echo and macros use."""

from popupwb.validity.check import add_build_problems, run_check
from popupwb.validity.report_text import design_error, format_diagnostic, format_report
from popupwb.validity.report_text import offending_patches
from popupwb.validity.verdict import INVALID, NOT_CHECKED, VALID, VALIDITY_STATES
from popupwb.validity.verdict import record_verdict, verdict_of_old_file

__all__ = [
    "add_build_problems",
    "design_error",
    "format_diagnostic",
    "format_report",
    "offending_patches",
    "record_verdict",
    "run_check",
    "verdict_of_old_file",
    "INVALID",
    "NOT_CHECKED",
    "VALID",
    "VALIDITY_STATES",
]
