"""Validity check of Scaffold and PopUpCard objects, and the text report shared with the
command-line tool.

format_report() and format_diagnostic() need neither FreeCAD nor popupcore (plain Python can use
them); run_check() imports both when called.
"""

import math

_VERDICTS = (
    ("foldable", "foldable"),
    ("stable", "stable"),
    ("intersection_free", "intersection-free"),
    ("enclosed", "enclosed"),
)


# States of a card's Validity property (stored in files: never rename them). Valid, the older
# boolean, stays as Validity == VALID for scripts and files that read it.
NOT_CHECKED, VALID, INVALID = "NotChecked", "Valid", "Invalid"
VALIDITY_STATES = [NOT_CHECKED, VALID, INVALID]


def record_verdict(obj, state, diagnostics=()):
    """Writes the verdict `state` (one of VALIDITY_STATES) into obj.Validity, when it has one,
    obj.Valid and obj.Diagnostics, each only when it changes."""
    if "Validity" in obj.PropertiesList and obj.Validity != state:
        obj.Validity = state
    if obj.Valid != (state == VALID):
        obj.Valid = state == VALID
    if list(obj.Diagnostics) != list(diagnostics):
        obj.Diagnostics = list(diagnostics)


def verdict_of_old_file(obj):
    """The Validity of an object saved before it had one: Valid was True only after a passing
    check, and an invalid verdict always came with findings; anything else was never checked (or
    its verdict was dropped when the design changed)."""
    if obj.Valid:
        return VALID
    return INVALID if list(obj.Diagnostics) else NOT_CHECKED


def format_diagnostic(diagnostic):
    """A diagnostic dict as one line, "code: message" (the message names what it is about). The
    patches it has titles for ("patch_titles", patch_titles.add_titles) are named as a maker
    names them: "Box fold 'BoxFold': top, ground side [#5 BoxFold.TG]"."""
    from popupwb.patch_titles import name_patches
    from popupwb.printable import printable

    message = name_patches(diagnostic.get("message", ""), diagnostic.get("patch_titles"))
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


def run_check(obj, samples=181, clearance=0.0):
    """Checks a Scaffold's or a PopUpCard's design with popupcore.check_validity.

    Writes obj.Validity (a card's), obj.Valid and obj.Diagnostics, prints the report to the report view and returns the
    report dict (ValidityReport.to_dict() plus "object": obj.Name). A design that does not load
    (or, for a card, a mechanism that does not build) gives an INVALID report with a
    "design_error" finding instead of an exception. For a card, in the GUI, the faces of the
    patches the findings name turn red.
    """
    import FreeCAD

    from popupwb import card_scaffold, progress

    try:
        if card_scaffold.is_card(obj):
            report = _check_card(obj, samples, clearance)
        else:
            report = _check_scaffold(obj, samples, clearance)
    except progress.Cancelled as cancelled:  # Valid and Diagnostics keep the last verdict
        FreeCAD.Console.PrintWarning(f"{cancelled}\n")
        return None
    report["object"] = obj.Name
    record_verdict(
        obj,
        VALID if report["valid"] else INVALID,
        [format_diagnostic(d) for d in report["diagnostics"]],
    )

    summary = [line for line in format_report(report).splitlines() if not line.startswith("    ")]
    FreeCAD.Console.PrintMessage(f"{obj.Label}: " + "\n".join(summary) + "\n")
    for line in obj.Diagnostics:
        FreeCAD.Console.PrintWarning(f"{obj.Label}: {line}\n")
    return report


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


def _check_scaffold(obj, samples, clearance):
    from popupwb import progress
    from popupwb.core import popupcore
    from popupwb.features.scaffold_feature import scaffold_of

    try:
        return progress.run(
            f"{obj.Label}: checking validity",
            popupcore.check_validity,
            scaffold_of(obj),
            samples=samples,
            clearance=clearance,
            cancel=progress.CANCEL_FLAG,
        ).to_dict()
    except popupcore.DesignError as error:
        return {"valid": False, "diagnostics": list(error.diagnostics)}
    except ValueError as error:
        return {"valid": False, "diagnostics": [design_error(str(error), "DesignFile")]}


def offending_patches(report):
    """Ids of the patches the report's findings are about (their `patches` field)."""
    ids = set()
    for d in report.get("diagnostics") or []:
        ids.update(int(i) for i in d.get("patches") or [])
    return ids


def add_build_problems(report, card, built):
    """Adds to a check_validity report dict of `card` (built: card_scaffold.for_card(card)) a
    design_error finding per mechanism that does not build and per stray PopUp feature; any such
    problem makes the card invalid. Its patches were left out of what the core checked."""
    from popupwb import card_scaffold

    problems = list(built.errors.values()) + card_scaffold.stray_features(card.Document)
    for message in problems:
        report["diagnostics"].append(design_error(message))
    report["valid"] = bool(report["valid"]) and not problems
    return report


def _check_card(card, samples, clearance):
    """The card's whole scaffold; mechanisms that do not build are findings of their own."""
    import FreeCAD

    from popupwb import card_scaffold, patch_titles, progress
    from popupwb.core import popupcore

    built = card_scaffold.for_card(card)
    if built.card_error:
        return {"valid": False, "diagnostics": [design_error(built.card_error)]}
    report = progress.run(
        f"{card.Label}: checking validity",
        popupcore.check_validity,
        built.scaffold,
        samples=samples,
        clearance=clearance,
        cancel=progress.CANCEL_FLAG,
    ).to_dict()
    add_build_problems(report, card, built)
    patch_titles.add_titles(report, patch_titles.titles_of_card(card, built))
    card.CheckedDesign = built.digest
    if FreeCAD.GuiUp:
        from popupwb.viewproviders import patch_colours

        patch_colours.highlight(card, built.digest, offending_patches(report))
        patch_colours.colour_card_and_mechanisms(card)
    return report
