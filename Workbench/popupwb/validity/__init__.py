"""The validity check: report_text.py the report as text, check.py the check runner; the verdict a
card records is the model's (model/validity_state.py, below the features).
`popupwb.validity.run_check(card)` is the call the commands echo and macros use."""

from popupwb.validity.check import add_build_problems, run_check
from popupwb.validity.report_text import design_error, format_diagnostic, format_report
from popupwb.validity.report_text import offending_patches
from popupwb.model.validity_state import INVALID, NOT_CHECKED, VALID, VALIDITY_STATES
from popupwb.model.validity_state import record_verdict, verdict_of_old_file

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
