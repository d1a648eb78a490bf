"""Face colours of every PopUp object that shows patches (Scaffold, card, mechanism): by patch
role, offending patches in red and outlined in red over any selection colour. The only place that
writes DiffuseColor.

PopUp_CheckValidity marks the patches its findings name (highlight()); the marks last while the
card's design is the one checked (a changed design drops them). Kept in memory, never saved.
"""

# Paper-like tints per patch role (RGB 0..1); the base patches stay closest to white card.
ROLE_COLOURS = {
    "ground": (0.93, 0.91, 0.85),
    "backdrop": (0.88, 0.86, 0.80),
    "support": (0.55, 0.73, 0.90),
    "top": (0.60, 0.83, 0.56),
    "front": (0.96, 0.66, 0.38),
    "back": (0.97, 0.85, 0.45),
    "tab": (0.70, 0.70, 0.70),
    "other": (0.86, 0.60, 0.78),
}
OFFENDING = (0.90, 0.10, 0.10)

_HIGHLIGHTS = {}  # (document name, card name) -> (design digest, set of patch ids)

from popupwb.validity import check  # noqa: E402 -- below the view providers


def highlight(card, digest, patch_ids):
    """Marks `patch_ids` of `card` red while its design digest is `digest`."""
    _HIGHLIGHTS[(card.Document.Name, card.Name)] = (digest, set(patch_ids))


def highlighted(card, digest):
    """Patch ids of `card` marked red for the design `digest`."""
    marked = _HIGHLIGHTS.get((card.Document.Name, card.Name))
    return marked[1] if marked and marked[0] == digest else set()


def _shown_patches(obj):
    """(patches of the design, ids of the ones `obj` shows in shape order, ids marked red), or None
    when `obj` shows no design (the feature itself reports why)."""
    from popupwb.model import card_scaffold
    from popupwb.features.scaffold_feature import is_scaffold, scaffold_of

    if is_scaffold(obj):
        try:
            patches = scaffold_of(obj).patches
        except ValueError:
            return None
        return patches, list(range(len(patches))), set()
    try:
        card = card_scaffold.root_card(obj)
    except ValueError:
        return None  # a broken Host chain
    built = card_scaffold.for_card(card)
    if built.scaffold is None or obj.Name not in built.patches:
        return None
    return built.scaffold.patches, built.patches[obj.Name], highlighted(card, built.digest)


def colour_object(obj):
    """Sets obj.ViewObject.DiffuseColor from the roles of the patches it shows (a Scaffold every
    patch of its design, a card its pages, a mechanism its own patches), and outlines the red ones
    (offending_overlay) so that they show even while the object is selected. Its shape holds one
    child (face, or solid when thickened) per patch; nothing happens when the shape and the design
    do not match, and an object without a shape (in error) loses its marks."""
    from popupwb.viewproviders import offending_overlay

    try:
        vobj = obj.ViewObject
        if vobj is None:
            return
        shown = None if obj.Shape.isNull() else _shown_patches(obj)
    except (ReferenceError, RuntimeError, AttributeError):
        return  # deleted before a deferred call
    if shown is None:
        offending_overlay.show_outlines(vobj, [])
        return
    patches, ids, red = shown
    # Without the Placement (cumLoc False): the view's transform applies it to the outlines.
    children = obj.Shape.childShapes(True, False)
    if len(children) != len(ids):
        return
    colours, marked = [], []
    for child, patch_id in zip(children, ids):
        if patch_id in red:
            colour = OFFENDING
            marked.append(child)
        else:
            colour = ROLE_COLOURS.get(patches[patch_id].role, ROLE_COLOURS["other"])
        colours.extend([colour] * len(child.Faces))
    # RGB without alpha: opaque on every version. FreeCAD 0.20 reads a fourth value as
    # transparency, 1.1 as opacity (0.0 made every face invisible there).
    if [tuple(c[:3]) for c in vobj.DiffuseColor] != colours:
        vobj.DiffuseColor = colours
    offending_overlay.show_outlines(vobj, marked)


def colour_after_shape_change(obj):
    """Colours now and once more after the C++ view provider rebuilt its face set (Python's
    updateData runs first, and DiffuseColor only takes when its length matches the faces)."""
    from PySide import QtCore

    colour_object(obj)
    QtCore.QTimer.singleShot(0, lambda: colour_object(obj))


def colour_card_and_mechanisms(card):
    """Recolours a card and every mechanism of it (after a validity check)."""
    from popupwb.model import card_scaffold

    for obj in [card] + card_scaffold.mechanisms_of(card):
        colour_object(obj)


def show_verdict(card, digest, patch_ids):
    """A check's verdict on screen: the patches its findings name in red, every colour redone."""
    highlight(card, digest, patch_ids)
    colour_card_and_mechanisms(card)


check.verdict_viewer = show_verdict
