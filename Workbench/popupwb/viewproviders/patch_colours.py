"""Face colours of card and mechanism objects: by patch role, offending patches in red.

PopUp_CheckValidity marks the patches its findings name (highlight()); the marks last while the
card's design is the one checked (a changed design drops them). Kept in memory, never saved.
"""

from popupwb.viewproviders.scaffold_viewprovider import ROLE_COLOURS

OFFENDING = (0.90, 0.10, 0.10)

_HIGHLIGHTS = {}  # (document name, card name) -> (design digest, set of patch ids)


def highlight(card, digest, patch_ids):
    """Marks `patch_ids` of `card` red while its design digest is `digest`."""
    _HIGHLIGHTS[(card.Document.Name, card.Name)] = (digest, set(patch_ids))


def highlighted(card, digest):
    """Patch ids of `card` marked red for the design `digest`."""
    marked = _HIGHLIGHTS.get((card.Document.Name, card.Name))
    return marked[1] if marked and marked[0] == digest else set()


def colour_object(obj):
    """Sets obj.ViewObject.DiffuseColor from the roles of its patches (a PopUpCard shows every
    patch of its scaffold, a mechanism its own). Quietly does nothing when the shape and the
    scaffold do not match (the feature itself reports errors)."""
    from popupwb import card_scaffold

    try:
        vobj = obj.ViewObject
        if vobj is None or obj.Shape.isNull():
            return
        card = card_scaffold.root_card(obj)
    except (ReferenceError, RuntimeError, ValueError, AttributeError):
        return  # deleted before a deferred call, or a broken Host chain
    built = card_scaffold.for_card(card)
    if built.scaffold is None or obj.Name not in built.patches:
        return
    ids = (
        list(range(len(built.scaffold.patches)))
        if card_scaffold.is_card(obj)
        else built.patches[obj.Name]
    )
    children = obj.Shape.childShapes()
    if len(children) != len(ids):
        return
    red = highlighted(card, built.digest)
    patches = built.scaffold.patches
    colours = []
    for child, patch_id in zip(children, ids):
        if patch_id in red:
            colour = OFFENDING
        else:
            colour = ROLE_COLOURS.get(patches[patch_id].role, ROLE_COLOURS["other"])
        colours.extend([colour + (0.0,)] * len(child.Faces))
    if list(vobj.DiffuseColor) != colours:
        vobj.DiffuseColor = colours


def colour_card_and_mechanisms(card):
    """Recolours a card and every mechanism of it (after a validity check)."""
    from popupwb import card_scaffold

    for obj in [card] + card_scaffold.mechanisms_of(card):
        colour_object(obj)
