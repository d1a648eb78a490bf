"""The maker's title of every patch of a card ("Box fold 'BoxFold': top, ground side"), from the
card's document objects, the mechanism registry and the core's catalogue, and the text the core's
messages use for each patch (popupcore.patch_subject): above the features, beside the check runner.
"""

from popupwb import mechanism_catalogue, mechanism_registry
from popupwb.core import popupcore
from popupwb.patch_titles import CARD_KIND, add_titles, title


def part_title(kind, part):
    """What a maker calls part `part` of a mechanism of feature TYPE `kind` ("PopUp::BoxFold"),
    or of the card for CARD_KIND (the code itself if unknown)."""
    if kind == CARD_KIND:
        return mechanism_catalogue.card_part_titles().get(part, part)
    mechanism = mechanism_registry.by_type(kind)
    if mechanism is None:
        return part
    return mechanism_catalogue.part_title(mechanism.kind, part)


def titles_of_card(card, built):
    """{patch id: maker title} of every patch of the card's CardScaffold `built`."""
    names = {p.id: p.name for p in built.scaffold.patches}
    titles = {}
    for obj_name, ids in built.patches.items():
        obj = card.Document.getObject(obj_name)
        if obj is None:
            continue
        kind = getattr(obj.Proxy, "TYPE", None)
        mechanism = mechanism_registry.by_type(kind)
        kind_text = mechanism.menu_text if mechanism else CARD_KIND
        table_kind = kind if mechanism else CARD_KIND
        for patch_id in ids:
            raw = names.get(patch_id, "")
            prefix = obj.Label + "."
            part = raw[len(prefix) :] if raw.startswith(prefix) else raw
            titles[patch_id] = title(kind_text, obj.Label, part_title(table_kind, part))
    return titles


def subjects_and_names(scaffold):
    """({patch id: the core's text for it, "patch 5 (BoxFold.TG)"}, {patch id: name}) of every
    patch of `scaffold`."""
    names = {p.id: p.name for p in scaffold.patches}
    return {i: popupcore.patch_subject(i, name) for i, name in names.items()}, names


def add_scaffold_titles(report, titles, scaffold):
    """patch_titles.add_titles with the core's text and the name of each patch of `scaffold`."""
    return add_titles(report, titles, *subjects_and_names(scaffold))
