"""What a mechanism stores of its profiles, and what that says (docs/DESIGN.md, Profiles).

A mechanism stores its profiles in the hidden JSON property `Profiles`
    {part: {"outer": [[u, v], ...], "holes": [[[u, v], ...], ...], "reference": [w, h]}}
and may link a Sketcher sketch (`ProfileSketch`) whose closed wires outline the part named by
`ProfilePart`; the sketch wins over a stored outline of the same part. Coordinates are the part's
profile frame (popupcore.profile_frame): the sketch's own x along the patch's base fold from its
middle, y across the patch away from that fold, mm. `ProfileMode` says what a dimension edit does:
"Clip" keeps the outline in mm and clips it to the new patch; "Scale" first scales u and v by the
patch's new size over its `reference` size (its extent in the profile frame when the profile was
set).
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
