"""The validity check of Scaffold and PopUpCard objects: runs popupcore.check_validity on the
object's design, records the verdict (model/validity_state.py) and prints the report (report_text.py).

FreeCAD and popupcore are imported when a check runs.
"""

from popupwb.validity.report_text import design_error, format_diagnostic, format_report
from popupwb.validity.report_text import offending_patches
from popupwb.model.validity_state import INVALID, VALID, record_verdict

# What shows a card's verdict on screen, called as verdict_viewer(card, design digest, offending
# patch ids): the GUI sets it (viewproviders/patch_colours.py, imported by InitGui.py), as it sets
# progress.dialogs, so the check runner stays below the view providers and imports no Qt. None
# headless.
verdict_viewer = None


def run_check(obj, samples=181, clearance=0.0):
    """Checks a Scaffold's or a PopUpCard's design with popupcore.check_validity.

    Writes obj.Validity (a card's), obj.Valid and obj.Diagnostics, prints the report to the report view and returns the
    report dict (ValidityReport.to_dict() plus "object": obj.Name). A design that does not load
    (or, for a card, a mechanism that does not build) gives an INVALID report with a
    "design_error" finding instead of an exception. For a card, in the GUI, the faces of the
    patches the findings name turn red.
    """
    import FreeCAD

    from popupwb import progress
    from popupwb.model import card_scaffold

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


def add_build_problems(report, card, built):
    """Adds to a check_validity report dict of `card` (built: card_scaffold.for_card(card)) a
    design_error finding per mechanism that does not build and per stray PopUp feature; any such
    problem makes the card invalid. Its patches were left out of what the core checked."""
    from popupwb.model import card_scaffold

    problems = list(built.errors.values()) + card_scaffold.stray_features(card.Document)
    for message in problems:
        report["diagnostics"].append(design_error(message))
    report["valid"] = bool(report["valid"]) and not problems
    return report


def _check_card(card, samples, clearance):
    """The card's whole scaffold; mechanisms that do not build are findings of their own."""
    from popupwb import progress
    from popupwb.validity import card_titles
    from popupwb.model import card_scaffold
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
    titles = card_titles.titles_of_card(card, built)
    card_titles.add_scaffold_titles(report, titles, built.scaffold)
    card.CheckedDesign = built.digest
    if verdict_viewer is not None:
        verdict_viewer(card, built.digest, offending_patches(report))
    return report
