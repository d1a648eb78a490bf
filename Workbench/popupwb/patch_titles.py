"""Patches named the way a maker names them: "Box fold 'BoxFold': top, ground side [#5 BoxFold.TG]".

The core names a card's patches "<Label>.<part>" (the card or mechanism Label and the part code its
generator gives, e.g. BoxFold.TG) and its findings say "patch 5 (BoxFold.TG)", text written by one
function, popupcore.patch_subject. validity.card_titles gives each patch of a card its maker title
(from the core's mechanism catalogue) and that exact text; add_titles() puts both on a report's
findings ("patch_titles", "patch_subjects", "patch_names") and name_patches() puts the titles in
the place of the core's text. The short id in brackets stays, to search for and to match `popup
check --json`. "#5", not "P5": P<n> names the cut pieces on the sheets. Plain text: no FreeCAD,
no other module of the workbench.
"""

CARD_KIND = "Card"


def title(kind_text, label, part_text):
    """ "Box fold 'BoxFold': top, ground side" """
    return f"{kind_text} '{label}': {part_text}"


def add_titles(report, titles, subjects, names):
    """Gives each finding of `report` the titles of the patches it is about ("patch_titles",
    {id: title}), the core's text for each ("patch_subjects") and their names ("patch_names"),
    which format_diagnostic uses; returns `report`."""
    for finding in report.get("diagnostics") or []:
        about = [int(i) for i in finding.get("patches") or [] if int(i) in titles]
        if about:
            finding["patch_titles"] = {i: titles[i] for i in about}
            finding["patch_subjects"] = {i: subjects[i] for i in about}
            finding["patch_names"] = {i: names.get(i, "") for i in about}
    return report


def _replace_whole(message, subject, replacement):
    """`message` with `subject` replaced where it is not the start of a longer number."""
    out, start = [], 0
    while (found := message.find(subject, start)) >= 0:
        end = found + len(subject)
        whole = end == len(message) or not message[end].isdigit()
        out.append(message[start:found] + (replacement if whole else subject))
        start = end
    return "".join(out) + message[start:]


def name_patches(message, titles, subjects, names=None):
    """`message` with the core's text for each patch (`subjects`, {id: "patch 5 (BoxFold.TG)"})
    whose id has a title written "Box fold 'BoxFold': top, ground side [#5 BoxFold.TG]" (the name
    from `names`); other text unchanged. JSON gives the ids as strings."""
    titles = {int(k): v for k, v in (titles or {}).items()}
    subjects = {int(k): v for k, v in (subjects or {}).items()}
    names = {int(k): v for k, v in (names or {}).items()}
    for patch_id in titles.keys() & subjects.keys():
        name = names.get(patch_id, "")
        short = f"#{patch_id}" + (f" {name}" if name else "")
        message = _replace_whole(message, subjects[patch_id], f"{titles[patch_id]} [{short}]")
    return message
