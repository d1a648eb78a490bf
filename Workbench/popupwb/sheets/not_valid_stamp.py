"""The "NOT VALID: <reason>" stamp on sheets laid out from a design the validity check rejects.

Sheets are cut only from valid designs, unless the user forces them (`popup sheet --force`, the
CuttingSheet's Force property); forced sheets carry the stamp on every sheet (DXF and SVG on the
LABEL layer, each PDF page, each TechDraw page) and at the top of the instructions, so a printed
or cut sheet cannot pass for a checked one. No FreeCAD needed.
"""

from dataclasses import dataclass
from typing import Tuple

from .sheet_set import paper_size

PREFIX = "NOT VALID: "
# The validity verdicts (popupcore.ValidityReport.to_dict() keys) and how the stamp names them.
VERDICTS = (
    ("foldable", "foldable"),
    ("stable", "stable"),
    ("intersection_free", "intersection-free"),
    ("enclosed", "enclosed"),
)
LARGEST_CAP_HEIGHT = 5.0  # mm, the piece labels' size
SMALLEST_CAP_HEIGHT = 1.5  # mm, still legible on a laser print
STAMP_FONT = "Helvetica"  # measures the stamp's width (the PDF's label font)
CAP_HEIGHT_PER_EM = 0.718  # Helvetica


@dataclass(frozen=True)
class StampLabel:
    """The stamp as the writers draw a label: the fields of popupcore.SheetLabel."""

    text: str
    kind: str  # "stamp"
    position: Tuple[float, float]  # the centre of the cap height, mm
    height: float  # cap height, mm
    angle: float  # degrees counter-clockwise


@dataclass(frozen=True)
class NotValid:
    """Why a design is not valid: the failed verdicts, and the check's findings one line each."""

    reason: str  # "not enclosed", "not stable, not enclosed"
    findings: Tuple[str, ...] = ()

    def text(self):
        return PREFIX + self.reason


def not_valid_of(report):
    """NotValid for a validity report dict (ValidityReport.to_dict()), None when it is valid."""
    from popupwb.validity.report_text import format_diagnostic  # FreeCAD-free

    if report.get("valid"):
        return None
    failed = [f"not {label}" for key, label in VERDICTS if report.get(key) is False]
    findings = tuple(format_diagnostic(d) for d in report.get("diagnostics") or [])
    # A report can be invalid with every verdict true (a mechanism that did not build).
    reason = ", ".join(failed) or (findings[0] if findings else "rejected by the validity check")
    return NotValid(reason, findings)


def stamp_label(width, height, margin, not_valid):
    """The stamp as a sheet label: centred in the top margin band of a width x height mm sheet,
    as large as the band allows (up to the piece labels' 5 mm) and narrow enough to fit across
    the sheet. With a margin under 3 mm it overlaps the top of the sheet's area."""
    from reportlab.pdfbase.pdfmetrics import stringWidth

    text = not_valid.text()
    band = max(margin, 2.0 * SMALLEST_CAP_HEIGHT)
    cap = min(LARGEST_CAP_HEIGHT, 0.6 * band)
    room = width - 2.0 * max(margin, SMALLEST_CAP_HEIGHT)
    text_width = stringWidth(text, STAMP_FONT, cap / CAP_HEIGHT_PER_EM)
    if text_width > room:
        cap = max(SMALLEST_CAP_HEIGHT, cap * room / text_width)
    return StampLabel(text, "stamp", (width / 2.0, height - band / 2.0), cap, 0.0)


def sheet_stamp(sheet_set, not_valid):
    """The stamp on every sheet of the bound `sheet_set` (stamp_label on its paper and margin);
    None when `not_valid` is None."""
    if not_valid is None:
        return None
    width, height = paper_size(sheet_set)
    return stamp_label(width, height, sheet_set.options.margin, not_valid)
