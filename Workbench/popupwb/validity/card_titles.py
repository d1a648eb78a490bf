"""The maker's title of every patch of a card ("Box fold 'BoxFold': top, ground side"), from the
card's document objects and the mechanism registry: above the features, beside the check runner.
"""

from popupwb import mechanism_registry
from popupwb.patch_titles import CARD_KIND, part_title, title


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
