"""The validity report as text and its findings: shared by the workbench and the command line.

Needs neither FreeCAD nor popupcore (plain Python can use it).
"""

import math

_VERDICTS = (
    ("foldable", "foldable"),
    ("stable", "stable"),
    ("intersection_free", "intersection-free"),
    ("enclosed", "enclosed"),
)


def format_diagnostic(diagnostic):
    """A diagnostic dict as one line, "code: message" (the message names what it is about). The
    patches it has titles for ("patch_titles", patch_titles.add_titles) are named as a maker
    names them: "Box fold 'BoxFold': top, ground side [#5 BoxFold.TG]"."""
    from popupwb.patch_titles import name_patches
    from popupwb.printable import printable

    message = name_patches(
        diagnostic.get("message", ""),
        diagnostic.get("patch_titles"),
        diagnostic.get("patch_subjects"),
        diagnostic.get("patch_names"),
    )
    return printable(f"{diagnostic.get('code', '')}: {message}")


def format_report(report):
    """Multi-line human text for a ValidityReport.to_dict() dict, starting with VALID or INVALID.

    Keys missing from `report` are left out of the text, so partial reports (a design that does not
    load) format too.
    """
    valid = bool(report.get("valid", False))
    verdicts = [
        label if report[key] else f"NOT {label}" for key, label in _VERDICTS if key in report
    ]
    lines = [("VALID" if valid else "INVALID") + (f": {', '.join(verdicts)}" if verdicts else "")]
    # ValidityReport.to_dict() gives locked_at_deg (None when the motion is free); a raw
    # "locked_at" is in radians, -1 when free.
    locked_deg = report.get("locked_at_deg")
    if locked_deg is None and (report.get("locked_at") or -1.0) >= 0.0:
        locked_deg = math.degrees(report["locked_at"])
    if locked_deg is not None:
        lines.append(f"  locked at           {locked_deg:.2f}°")
    numbers = (
        ("max_hinge_residual", "max hinge residual", " mm"),
        ("max_edge_strain", "max edge strain", ""),
        ("flatness_at_zero", "flatness at 0°", " mm"),
        ("model_size", "model size", " mm"),
    )
    for key, label, unit in numbers:
        if key in report:
            lines.append(f"  {label:<19} {report[key]:.3g}{unit}")
    diagnostics = report.get("diagnostics") or []
    if diagnostics:
        lines.append(f"  {len(diagnostics)} finding(s):")
        lines.extend(f"    {format_diagnostic(d)}" for d in diagnostics)
    return "\n".join(lines)


def design_error(message, parameter=None):
    """A finding of the workbench's own: a design or mechanism that does not load or build."""
    return {
        "code": "design_error",
        "severity": "error",
        "message": message,
        "patches": [],
        "parameter": parameter,
        "angle_deg": None,
    }


def offending_patches(report):
    """Ids of the patches the report's findings are about (their `patches` field)."""
    ids = set()
    for d in report.get("diagnostics") or []:
        ids.update(int(i) for i in d.get("patches") or [])
    return ids
