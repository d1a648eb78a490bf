"""The maker's profile edits: an outline stored for a part, a Sketcher sketch linked as one (in
Clip or Scale mode) or unlinked, the reference size Scale mode scales from, and what a profile can
be drawn for (the parts of a mechanism, the sketches of a document). The caller recomputes.
"""

from popupwb.model.profile_storage import MODES, sketch_loops, stored, write_stored


def record_reference(obj, part, built):
    """Stores the current size of `part` (from the CardScaffold `built`) as its reference, so
    Scale mode scales from the size the outline was drawn for."""
    size = built.sizes.get(obj.Name, {}).get(part)
    if size is None:
        return
    profiles = stored(obj)
    entry = profiles.setdefault(part, {})
    entry["reference"] = size
    write_stored(obj, profiles)


def set_profile(obj, part, outer, holes=(), reference=None):
    """Stores an outline for `part` of mechanism `obj` (profile frame, mm); the reference size
    defaults to the part's current size. The caller recomputes."""
    from popupwb.model import card_scaffold

    profiles = stored(obj)
    entry = {"outer": [tuple(map(float, q)) for q in outer]}
    entry["holes"] = [[tuple(map(float, q)) for q in h] for h in holes]
    if reference is None:
        built = card_scaffold.for_card(card_scaffold.root_card(obj))
        reference = built.sizes.get(obj.Name, {}).get(part)
    if reference is not None:
        entry["reference"] = tuple(map(float, reference))
    profiles[part] = entry
    write_stored(obj, profiles)


def sketches_of(doc):
    """The Sketcher sketches of `doc`, in document order (what a profile can be drawn in)."""
    return [o for o in doc.Objects if getattr(o, "TypeId", "") == "Sketcher::SketchObject"]


def profile_parts(obj):
    """{part: (w, h)} of the principal parts of mechanism `obj` that take a profile, as its card
    builds them now; ValueError naming obj when it does not build (its parts are unknown then)."""
    from popupwb.model import card_scaffold

    built = card_scaffold.for_card(card_scaffold.root_card(obj))
    if obj.Name in built.errors and obj.Name not in built.sizes:
        raise ValueError(f"{obj.Label} is in error, fix it first: {built.errors[obj.Name]}")
    sizes = built.sizes.get(obj.Name)
    if not sizes:
        raise ValueError(f"{obj.Label}: has no part that takes a profile")
    return dict(sizes)


def outline_area(outer, holes=()):
    """Area (mm²) of an outline with holes: the shoelace formula on each loop."""

    def shoelace(loop):
        return 0.5 * sum(
            u0 * v1 - u1 * v0 for (u0, v0), (u1, v1) in zip(loop, list(loop[1:]) + [loop[0]])
        )

    return abs(shoelace(outer)) - sum(abs(shoelace(h)) for h in holes)


def set_profile_sketch(obj, sketch, part, mode="Clip"):
    """Links the Sketcher sketch `sketch` as the outline of `part` of mechanism `obj`, in `mode`
    (Clip or Scale), after checking the sketch holds one closed outline (its holes inside) and
    that obj has the part; records the part's current size as the reference Scale mode scales
    from. ValueError, one line naming obj, the sketch or the part and what is allowed. The
    caller recomputes (PopUp_SetProfile does it in one undo step)."""
    if not hasattr(obj, "ProfileSketch"):
        raise ValueError(f"{getattr(obj, 'Label', obj)}: is not a PopUp mechanism (no profile)")
    if mode not in MODES:
        raise ValueError(f"{obj.Label}: ProfileMode = {mode!r}, must be one of {', '.join(MODES)}")
    if sketch is None:
        raise ValueError(f"{obj.Label}: no sketch given; pick a Sketcher sketch")
    sketch_loops(obj, sketch)  # raises naming the sketch: open wire, no wire, crossing
    sizes = profile_parts(obj)
    if part not in sizes:
        raise ValueError(
            f"{obj.Label}: ProfilePart = {part!r}, must be one of its parts "
            f"({', '.join(sorted(sizes))})"
        )
    obj.ProfileSketch = sketch
    obj.ProfilePart = part
    obj.ProfileMode = mode
    entry_profiles = stored(obj)
    entry_profiles.setdefault(part, {})["reference"] = tuple(map(float, sizes[part]))
    write_stored(obj, entry_profiles)


def clear_profile_sketch(obj):
    """Unlinks obj's profile sketch (stored outlines stay). The caller recomputes."""
    obj.ProfileSketch = None
    obj.ProfilePart = ""
