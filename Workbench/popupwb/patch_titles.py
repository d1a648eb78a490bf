"""Patches named the way a maker names them: "Box fold 'BoxFold': top, ground side [#5 BoxFold.TG]".

The core names a card's patches "<Label>.<part>" (the card or mechanism Label and the part code its
generator gives, e.g. BoxFold.TG) and its findings say "patch 5 (BoxFold.TG)". This module knows,
per mechanism kind, what each part code is called, so the check's findings read as a maker speaks;
the short id in brackets stays, to search for and to match `popup check --json`. "#5", not "P5":
P<n> names the cut pieces on the sheets.

validity.card_titles.titles_of_card() gives {patch id: title} for a card (it needs the document
and the mechanism registry); add_titles() puts them on a report's findings (each finding's own
"patch_titles"); name_patches() rewrites a message with them. Plain Python: no FreeCAD, no other
module of the workbench.
"""

import re

CARD_KIND = "Card"

# Part code -> what a maker calls it, per feature TYPE (the card's under CARD_KIND). A box fold and
# a floating layer are both built by the core's parallel box (core/src/mechanisms/parallel_box.cpp).
PART_TITLES = {
    CARD_KIND: {"ground": "ground page", "backdrop": "backdrop page"},
    "PopUp::TentFold": {
        "slope_ground": "slope, ground side",
        "slope_backdrop": "slope, backdrop side",
    },
    "PopUp::StepFold": {"riser": "riser", "tread": "tread"},
    "PopUp::VFold": {"wing_ground": "wing, ground side", "wing_backdrop": "wing, backdrop side"},
    "PopUp::BoxFold": {
        "C": "centre wall",
        "L": "wall, ground side",
        "R": "wall, backdrop side",
        "TG": "top, ground side",
        "TB": "top, backdrop side",
        "FL": "front end, ground side",
        "FR": "front end, backdrop side",
        "BL": "back end, ground side",
        "BR": "back end, backdrop side",
    },
    "PopUp::VBoxFold": {
        "FL": "front wall, ground side",
        "FR": "front wall, backdrop side",
        "TG": "top, ground side",
        "TB": "top, backdrop side",
        "BL": "back wall, ground side",
        "BR": "back wall, backdrop side",
    },
    "PopUp::RotationArm": {"wing_arm": "wing with the arm", "wing_backdrop": "wing, backdrop side"},
    "PopUp::HorizontalTranslation": {"riser": "riser", "tread": "tread", "M": "sliding panel"},
    "PopUp::VerticalTranslation": {
        "FL": "front wall, ground side",
        "FR": "front wall, backdrop side",
        "TG": "top, ground side",
        "TB": "top, backdrop side",
    },
    "PopUp::FloatingLayer": {
        "C": "centre support",
        "L": "support, ground side",
        "R": "support, backdrop side",
        "TG": "platform, ground side",
        "TB": "platform, backdrop side",
        "FL": "front end, ground side",
        "FR": "front end, backdrop side",
        "BL": "back end, ground side",
        "BR": "back end, backdrop side",
    },
}

# An end of several panel pairs numbers its strips from the hinge up: FL1, FL2, ...
_STRIP = re.compile(r"^(?P<code>[A-Z]+)(?P<strip>[0-9]+)$")


def part_title(kind, part):
    """What a maker calls part `part` of a mechanism of TYPE `kind` (the code itself if unknown)."""
    titles = PART_TITLES.get(kind, {})
    if part in titles:
        return titles[part]
    strip = _STRIP.match(part)
    if strip and strip["code"] in titles:
        return f"{titles[strip['code']]}, strip {strip['strip']}"
    return part


def title(kind_text, label, part_text):
    """ "Box fold 'BoxFold': top, ground side" """
    return f"{kind_text} '{label}': {part_text}"


def add_titles(report, titles):
    """Gives each finding of `report` the titles of the patches it is about ("patch_titles",
    {id: title}), which format_diagnostic uses; returns `report`."""
    for finding in report.get("diagnostics") or []:
        about = {int(i): titles[int(i)] for i in finding.get("patches") or [] if int(i) in titles}
        if about:
            finding["patch_titles"] = about
    return report


# "patch 5 (BoxFold.TG)", as the core writes a patch in a message; the name may be absent.
_PATCH = re.compile(r"\bpatch (?P<id>[0-9]+)(?: \((?P<name>[^()]*)\))?")


def name_patches(message, titles):
    """`message` with each "patch 5 (BoxFold.TG)" whose id has a title written
    "Box fold 'BoxFold': top, ground side [#5 BoxFold.TG]"; other text unchanged."""
    titles = {int(k): v for k, v in (titles or {}).items()}  # JSON keys are strings

    def named(match):
        patch_id = int(match["id"])
        if patch_id not in titles:
            return match[0]
        short = f"#{patch_id}" + (f" {match['name']}" if match["name"] else "")
        return f"{titles[patch_id]} [{short}]"

    return _PATCH.sub(named, message)
