"""Patches named the way a maker names them: "Box fold 'BoxFold': top, ground side [#5 BoxFold.TG]".

The core names a card's patches "<Label>.<part>" (the card or mechanism Label and the part code its
generator gives, e.g. BoxFold.TG) and its findings say "patch 5 (BoxFold.TG)", written by one
function, popupcore.patch_subject. The core's mechanism catalogue knows what each part code of
each kind is called (mechanism_catalogue.part_title), so the check's findings read as a maker
speaks; the short id in brackets stays, to search for and to match `popup check --json`. "#5",
not "P5": P<n> names the cut pieces on the sheets.

validity.card_titles.titles_of_card() gives {patch id: title} for a card (it needs the document
and the mechanism registry); add_titles() puts them on a report's findings (each finding's own
"patch_titles", and "patch_names"); name_patches() rewrites a message with them, finding each
patch by the text popupcore.patch_subject writes for it. No FreeCAD.
"""

from popupwb import mechanism_catalogue
from popupwb.core import popupcore

CARD_KIND = "Card"


def part_title(kind, part):
    """What a maker calls part `part` of a mechanism of feature TYPE `kind` ("PopUp::BoxFold"),
    or of the card for CARD_KIND (the code itself if unknown)."""
    if kind == CARD_KIND:
        return mechanism_catalogue.card_part_titles().get(part, part)
    for row in mechanism_catalogue.entries():
        if kind == f"PopUp::{row.feature}":
            return mechanism_catalogue.part_title(row.kind, part)
    return part


def title(kind_text, label, part_text):
    """ "Box fold 'BoxFold': top, ground side" """
    return f"{kind_text} '{label}': {part_text}"


def names_of(scaffold):
    """{patch id: name} of every patch of `scaffold`."""
    return {p.id: p.name for p in scaffold.patches}


def add_titles(report, titles, names):
    """Gives each finding of `report` the titles of the patches it is about ("patch_titles",
    {id: title}) and their names ("patch_names"), which format_diagnostic uses; returns
    `report`."""
    for finding in report.get("diagnostics") or []:
        about = [int(i) for i in finding.get("patches") or [] if int(i) in titles]
        if about:
            finding["patch_titles"] = {i: titles[i] for i in about}
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


def name_patches(message, titles, names=None):
    """`message` with each patch the core names (popupcore.patch_subject: "patch 5 (BoxFold.TG)",
    from its id and `names`) whose id has a title written "Box fold 'BoxFold': top, ground side
    [#5 BoxFold.TG]"; other text unchanged. JSON gives the ids as strings."""
    titles = {int(k): v for k, v in (titles or {}).items()}
    names = {int(k): v for k, v in (names or {}).items()}
    for patch_id, patch_title in titles.items():
        name = names.get(patch_id, "")
        subject = popupcore.patch_subject(patch_id, name)
        short = f"#{patch_id}" + (f" {name}" if name else "")
        message = _replace_whole(message, subject, f"{patch_title} [{short}]")
    return message
