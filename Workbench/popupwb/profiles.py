"""Profiles of mechanism features: outlines cut into their patches (docs/DESIGN.md, Profiles).

A mechanism stores its profiles in the hidden JSON property `Profiles`
    {part: {"outer": [[u, v], ...], "holes": [[[u, v], ...], ...], "reference": [w, h]}}
and may link a Sketcher sketch (`ProfileSketch`) whose closed wires outline the part named by
`ProfilePart`; the sketch wins over a stored outline of the same part. Coordinates are the part's
profile frame (popupcore.profile_frame): the sketch's own x along the patch's base fold from its
middle, y across the patch away from that fold, mm. `ProfileMode` says what a dimension edit does:
"Clip" keeps the outline in mm and clips it to the new patch; "Scale" first scales u and v by the
patch's new size over its `reference` size (its extent in the profile frame when the profile was
set). card_scaffold.build applies the profiles right after each generator call, so validity, the
shown shape and the cutting sheets all use the profiled patches.
"""

import json
import math

MODES = ["Clip", "Scale"]
PROPERTIES = ("Profiles", "ProfileSketch", "ProfilePart", "ProfileMode")
# Chord error (mm) when arcs and B-splines of a sketch become polygon edges: far below a cutter's
# resolution, so a round outline stays round.
DEFLECTION = 0.002


def add_properties(obj):
    """Adds the profile properties a mechanism lacks (documents from before profiles open
    unchanged: empty Profiles, no sketch, Clip)."""
    have = set(obj.PropertiesList)
    group = "Profile"
    if "Profiles" not in have:
        obj.addProperty(
            "App::PropertyString",
            "Profiles",
            group,
            "Outlines per part as JSON {part: {outer, holes, reference}} (profile frame, mm)",
        )
        obj.setEditorMode("Profiles", 2)
    if "ProfileSketch" not in have:
        obj.addProperty(
            "App::PropertyLink",
            "ProfileSketch",
            group,
            "A sketch whose closed wires outline ProfilePart (x along its fold from the middle, "
            "y away from the fold, mm)",
        )
    if "ProfilePart" not in have:
        obj.addProperty(
            "App::PropertyString",
            "ProfilePart",
            group,
            "The part the sketch outlines (riser, tread, TG, FL, ...)",
        )
    if "ProfileMode" not in have:
        obj.addProperty(
            "App::PropertyEnumeration",
            "ProfileMode",
            group,
            "After a dimension edit: Clip keeps the outline in mm, Scale scales it with the part",
        )
        obj.ProfileMode = MODES
        obj.ProfileMode = "Clip"


def _points(value, what):
    try:
        points = [(float(p[0]), float(p[1])) for p in value]
    except (TypeError, ValueError, IndexError, KeyError) as error:
        raise ValueError(f"{what} must be a list of [u, v] pairs ({error})") from None
    return points


def stored(obj):
    """{part: {"outer", "holes", "reference"}} from obj.Profiles; ValueError names the entry."""
    text = getattr(obj, "Profiles", "") or ""
    if not text.strip():
        return {}
    try:
        data = json.loads(text)
    except ValueError as error:
        raise ValueError(f"{obj.Label}: Profiles is not JSON ({error})") from None
    if not isinstance(data, dict):
        raise ValueError(f"{obj.Label}: Profiles must be a JSON object {{part: profile}}")
    out = {}
    for part, entry in data.items():
        what = f"{obj.Label}: Profiles['{part}']"
        if not isinstance(entry, dict):
            raise ValueError(f"{what} must be an object with outer, holes, reference")
        profile = {"name": entry.get("name") or f"{obj.Label}.{part}"}
        if "outer" in entry:
            profile["outer"] = _points(entry["outer"], f"{what}.outer")
            profile["holes"] = [
                _points(h, f"{what}.holes[{i}]") for i, h in enumerate(entry.get("holes", []))
            ]
        reference = entry.get("reference")
        if reference is not None:
            ref = _points([reference], f"{what}.reference")[0]
            if not all(math.isfinite(x) and x > 0 for x in ref):
                raise ValueError(f"{what}.reference = {list(ref)}, must be two lengths > 0 mm")
            profile["reference"] = ref
        out[part] = profile
    return out


def write_stored(obj, profiles):
    """Writes {part: {"outer", "holes", "reference"}} to obj.Profiles as JSON."""
    data = {}
    for part, p in sorted(profiles.items()):
        entry = {}
        if "outer" in p:
            entry["outer"] = [list(q) for q in p["outer"]]
            entry["holes"] = [[list(q) for q in h] for h in p.get("holes", [])]
        if p.get("reference") is not None:
            entry["reference"] = list(p["reference"])
        data[part] = entry
    obj.Profiles = json.dumps(data, sort_keys=True) if data else ""


def sketch_loops(obj, sketch):
    """(outer, holes) of `sketch` in its own x, y (mm): its closed wires, arcs and B-splines
    discretised to DEFLECTION. ValueError (one line, naming the sketch) for an open wire, no wire
    or several separate outlines."""
    import FreeCAD
    import Part

    what = f"{obj.Label}: ProfileSketch {sketch.Label}"
    if getattr(sketch, "TypeId", "") != "Sketcher::SketchObject":
        raise ValueError(
            f"{obj.Label}: ProfileSketch = {sketch.Label} ({sketch.TypeId}), must be a Sketcher "
            "sketch"
        )
    shape = sketch.Shape.copy()
    shape.Placement = FreeCAD.Placement()  # the sketch's own plane coordinates
    wires = shape.Wires
    if not wires:
        raise ValueError(f"{what} has no wire; draw a closed outline")
    loops = []
    for i, wire in enumerate(wires):
        if not wire.isClosed():
            raise ValueError(
                f"{what}: wire {i + 1} is open; close it (an outline is a closed loop)"
            )
        try:
            points = wire.discretize(Deflection=DEFLECTION)
        except Part.OCCError as error:
            raise ValueError(f"{what}: wire {i + 1} cannot be followed ({error})") from None
        loop = [(p.x, p.y) for p in points]
        if len(loop) > 1 and math.dist(loop[0], loop[-1]) < 1e-9:
            loop.pop()
        try:
            area = Part.Face(wire).Area
        except Part.OCCError:
            raise ValueError(f"{what}: wire {i + 1} crosses itself") from None
        loops.append((area, i, loop, wire))
    loops.sort(key=lambda item: -item[0])
    _, _, outer, outer_wire = loops[0]
    outer_face = Part.Face(outer_wire)
    holes = []
    for _, i, loop, wire in loops[1:]:
        if not outer_face.isInside(wire.Vertexes[0].Point, 1e-7, True):
            raise ValueError(
                f"{what} has {len(loops)} separate outlines (wire {i + 1} lies outside the "
                "largest); one outline per part, holes inside it"
            )
        holes.append(loop)
    return outer, holes


def profiles_of(obj):
    """The profiles obj asks for: stored ones, the sketch's outline for ProfilePart on top."""
    profiles = stored(obj)
    sketch = getattr(obj, "ProfileSketch", None)
    if sketch is not None:
        part = (getattr(obj, "ProfilePart", "") or "").strip()
        if not part:
            raise ValueError(
                f"{obj.Label}: ProfilePart is empty, must name the part {sketch.Label} outlines"
            )
        outer, holes = sketch_loops(obj, sketch)
        entry = dict(profiles.get(part, {}))
        entry.update(outer=outer, holes=holes, name=sketch.Label)
        profiles[part] = entry
    return {part: p for part, p in profiles.items() if "outer" in p}


def key_of(obj):
    """What of obj's profiles shapes the design (for card_scaffold.design_key): the stored JSON,
    the mode, the part and the sketch's outline, or the reason it cannot be read."""
    if not hasattr(obj, "Profiles"):
        return ()
    try:
        drawn = profiles_of(obj)
        outlines = tuple(
            (part, tuple(p["outer"]), tuple(tuple(h) for h in p["holes"]))
            for part, p in sorted(drawn.items())
        )
    except ValueError as error:
        outlines = (str(error),)
    return (obj.Profiles, obj.ProfileMode, obj.ProfilePart, outlines)


def part_size(scaffold, patch_id):
    """(width along u, height along v) of a patch in its profile frame (mm)."""
    from popupwb.core import popupcore

    frame = popupcore.profile_frame(scaffold, patch_id)
    patch = next(p for p in scaffold.patches if p.id == patch_id)
    us, vs = [], []
    for x in patch.outer:
        d = x - frame.origin
        us.append(float(d @ frame.u))
        vs.append(float(d @ frame.v))
    return (max(us) - min(us), max(vs) - min(vs))


def part_sizes(scaffold, label, patch_ids):
    """{part: (w, h)} of a mechanism's patches (named "<label>.<part>"), as generated."""
    sizes = {}
    for patch in scaffold.patches:
        if patch.id in patch_ids and patch.name.startswith(label + "."):
            try:
                sizes[patch.name[len(label) + 1 :]] = part_size(scaffold, patch.id)
            except ValueError:
                pass  # a patch without folds takes no profile
    return sizes


def fitted_outline(profile, mode, size):
    """(outer, holes) for a part now `size` (w, h): as stored for Clip; for Scale, u and v
    multiplied by the new size over the reference size."""
    outer, holes = profile["outer"], profile.get("holes", [])
    reference = profile.get("reference")
    if mode != "Scale" or reference is None:
        return outer, holes
    su, sv = size[0] / reference[0], size[1] / reference[1]

    def scaled(loop):
        return [(u * su, v * sv) for u, v in loop]

    return scaled(outer), [scaled(h) for h in holes]


def apply_profiles(obj, scaffold, sizes):
    """Cuts obj's parts to its profiles in `scaffold` (just generated; `sizes` from part_sizes).
    ValueError names the feature, the part and the profile."""
    import FreeCAD

    from popupwb.core import popupcore

    for part, profile in sorted(profiles_of(obj).items()):
        if part not in sizes:
            choices = ", ".join(sorted(sizes)) or "none"
            raise ValueError(
                f"{obj.Label}: profile part = '{part}', must be one of its parts ({choices})"
            )
        outer, holes = fitted_outline(profile, obj.ProfileMode, sizes[part])
        loops = [outer] + list(holes)
        short = next((i for i, loop in enumerate(loops) if len(loop) < 3), None)
        if short is not None:
            which = "outer loop" if short == 0 else f"hole {short}"
            raise ValueError(
                f"{obj.Label}: profile of {part}: its {which} has {len(loops[short])} points, "
                "needs 3 or more"
            )
        # Lists of (u, v) pairs convert to the core's Nx2 arrays.
        core_profile = popupcore.Profile(
            [list(q) for q in outer], [[list(q) for q in h] for h in holes], profile["name"]
        )
        try:
            applied = popupcore.apply_profile(scaffold, obj.Label, part, core_profile)
        except ValueError as error:  # DesignError: names the patch, the fold and the profile
            raise ValueError(f"{obj.Label}: {error}") from None
        for warning in applied.warnings:
            FreeCAD.Console.PrintWarning(f"{obj.Label}: {warning['message']}\n")


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
    from popupwb import card_scaffold

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
    from popupwb import card_scaffold

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
