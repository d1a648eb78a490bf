"""The card's scaffold: one popupcore.Scaffold built from a PopUpCard and the mechanism features
nested on it.

A card and its mechanisms are one rigid-body system: the core builds and simulates them together.
Every feature of the card asks this module for the same CardScaffold (built once per design,
cached by a key made of every property that shapes it) and for the same posed compound at the
card's FoldAngle (simulated once per angle, cached), then shows only its own patches
(CardScaffold.own_shape): the card its pages, each mechanism its own patches. assembled_shape()
gives the whole card where one piece is needed.

Design order: the card, then each mechanism after its host (depth first from the card, siblings in
document order, so the patch ids are the same in every process). A mechanism whose generator
raises, or whose host failed, adds nothing; its message is remembered for its own execute().

Formerly popupwb.assembly: it builds a scaffold, and "assembly" is the cutting sheets' glue order.
No document stores this module's name (it holds no proxy class), so the old name is gone.
"""

import collections
import hashlib
import math

from popupwb import freecad_version
from popupwb.model import profile_cutting, profile_storage

CARD_TYPE = "PopUp::Card"
CENTRAL_FOLD = "central fold"  # popupcore.central_fold(card).name

_BUILT = collections.OrderedDict()  # design key -> CardScaffold
_BUILT_CACHE_SIZE = 8
_STATES = collections.OrderedDict()  # (design key, angle) -> FoldState or error text
_STATE_CACHE_SIZE = 64
_SHAPES = collections.OrderedDict()  # (design key, angle, thickness) -> Part.Shape compound
_SHAPE_CACHE_SIZE = 16


def _proxy(obj):
    return getattr(obj, "Proxy", None)


def is_card(obj):
    """True for PopUpCard objects."""
    return getattr(_proxy(obj), "TYPE", None) == CARD_TYPE


def is_mechanism(obj):
    """True for mechanism features (proxies derived from MechanismFeature)."""
    return bool(getattr(_proxy(obj), "IS_MECHANISM", False))


def root_card(obj):
    """The PopUpCard at the root of obj's Host chain (obj itself for a card).

    Raises ValueError naming the first object whose Host is missing, not a PopUp host, or part of
    a loop.
    """
    seen = []
    current = obj
    while not is_card(current):
        if any(current is other for other in seen):
            chain = " -> ".join(o.Label for o in seen + [current])
            # Named by the object's own Host, the property to fix.
            raise ValueError(
                f"{obj.Label}: Host = {obj.Host.Label}, must not lead back to itself ({chain})"
            )
        seen.append(current)
        host = getattr(current, "Host", None)
        if host is None:
            raise ValueError(
                f"{current.Label}: Host is empty, must be a PopUpCard or a mechanism "
                "offering base patch pairs"
            )
        if not (is_card(host) or is_mechanism(host)):
            raise ValueError(
                f"{current.Label}: Host = {host.Label}, must be a PopUpCard or a mechanism "
                "offering base patch pairs"
            )
        current = host
    return current


def host_pair_names(host):
    """Names of the base patch pairs a host offers, without building anything: "central fold" for
    a card, "<Label>.<part>" for a mechanism (the names popupcore gives them)."""
    if is_card(host):
        return [CENTRAL_FOLD]
    if is_mechanism(host):
        return [f"{host.Label}.{part}" for part in _proxy(host).OFFERS]
    return []


def stray_features(doc):
    """Messages for the document's PopUp features that no card builds: a mechanism whose Host
    chain is empty, foreign or loops, and a feature whose code did not load (its proxy module is
    missing). A damaged file must not check VALID with mechanisms silently left out."""
    problems = []
    for obj in doc.Objects:
        if is_mechanism(obj):
            try:
                root_card(obj)
            except ValueError as error:
                problems.append(str(error))
        elif getattr(obj, "Proxy", False) is None and "HostPair" in obj.PropertiesList:
            problems.append(
                f"{obj.Label}: its feature code did not load (proxy module missing): the "
                "document was saved by another version of PopUp or is damaged"
            )
    return problems


def mechanisms_of(card):
    """The mechanisms hosted (directly or through other mechanisms) on `card`, hosts first."""
    children = collections.defaultdict(list)
    for obj in card.Document.Objects:
        if is_mechanism(obj) and getattr(obj, "Host", None) is not None:
            children[obj.Host.Name].append(obj)
    ordered, seen = [], set()
    stack = list(reversed(children[card.Name]))
    while stack:
        obj = stack.pop()
        if obj.Name in seen:  # a Host loop below the card: root_card() reports it
            continue
        seen.add(obj.Name)
        ordered.append(obj)
        stack.extend(reversed(children[obj.Name]))
    return ordered


def _number(value):
    return float(getattr(value, "Value", value))


def _as_saved(item):
    """`item` with every float as a .FCStd file gives it back: FreeCAD writes floats with 16
    decimals, so 0.00018599999999935335 reopens as 0.0001859999999994. Keyed as saved, a card
    checked before saving keeps its verdict when reopened and recomputed (by any version)."""
    if isinstance(item, float):
        return float(f"{item:.16f}") if math.isfinite(item) else item
    if isinstance(item, tuple):
        return tuple(_as_saved(part) for part in item)
    return item


def design_key(card):
    """Everything that shapes the card's scaffold, as a hashable tuple (FoldAngle and Thickened
    are not in it: they pose and display the same design)."""
    parts = [
        (
            card.Name,
            _number(card.Width),
            _number(card.Depth),
            _number(card.PaperThickness),
        )
    ]
    for obj in mechanisms_of(card):
        parts.append(
            (obj.Name, obj.Label, obj.Proxy.TYPE, obj.Host.Name, obj.HostPair)
            + tuple(_proxy(obj).parameter_values(obj))
            + (profile_storage.key_of(obj),)
        )
    return _as_saved(tuple(parts))


class CardScaffold:
    """One card's scaffold with everything the features need to show their part of it.

    scaffold          popupcore.Scaffold of the card and every mechanism that built
    order             object names in design order (the card first)
    patches           {object name: [patch ids]} (the card owns its ground and backdrop)
    errors            {object name: message} for mechanisms that added nothing
    offered           {object name: [popupcore.BasePatchPair]} for the card and built mechanisms
    parts             {object name: popupcore.MechanismParts} for built mechanisms (their host
                      pair and swept span, popupwb.model.placement)
    sizes             {object name: {part: (w, h)}}: each part's extent in its profile frame as
                      generated, before profiles (popupwb.profiles, Scale mode)
    card_error        message when the card itself cannot be built (then nothing is)
    key, digest       the design key and a short stable hash of it
    """

    def __init__(self, key):
        self.key = key
        self.digest = hashlib.sha1(repr(key).encode("utf-8")).hexdigest()[:16]
        self.scaffold = None
        self.order = []
        self.patches = {}
        self.errors = {}
        self.offered = {}
        self.parts = {}
        self.sizes = {}
        self.card_error = None

    def pair_names(self, name):
        """Names of the pairs the object `name` offers ([] if it did not build)."""
        return [pair.name for pair in self.offered.get(name, [])]

    def patch_owner(self, patch_id):
        """Name of the object owning patch `patch_id` (None if out of range)."""
        for name, ids in self.patches.items():
            if patch_id in ids:
                return name
        return None

    def state_at(self, angle_deg):
        """popupcore.FoldState of the whole card at `angle_deg`, simulated once per angle.

        Raises ValueError saying why the angle cannot be reached.
        """
        from popupwb.core import popupcore

        cache_key = (self.key, round(float(angle_deg), 12))
        state = _STATES.get(cache_key)
        if state is None:
            # Dragging the angle: continue from the nearest angle already solved for this
            # design, a few steps instead of a sweep from the design state.
            nearest = self._nearest_state(angle_deg)
            if nearest is None:
                sweep = popupcore.simulate_fold(self.scaffold, [math.radians(angle_deg)])
            else:
                sweep = popupcore.continue_fold(self.scaffold, nearest, [math.radians(angle_deg)])
            if sweep.complete and sweep.states:
                state = sweep.states[0]
            else:
                findings = "; ".join(d.message for d in sweep.diagnostics)
                if sweep.locked_at >= 0.0:
                    reason = f"the design locks at {math.degrees(sweep.locked_at):.2f}°"
                else:
                    reason = "the simulation did not reach it"
                state = f"cannot be reached, {reason}" + (f" ({findings})" if findings else "")
            _remember(_STATES, cache_key, state, _STATE_CACHE_SIZE)
        else:
            _STATES.move_to_end(cache_key)
        if isinstance(state, str):
            raise ValueError(state)
        return state

    def _nearest_state(self, angle_deg):
        """The cached state of this design closest in angle to `angle_deg`, or None."""
        best = None
        for (key, angle), state in _STATES.items():
            if key != self.key or isinstance(state, str):
                continue
            if best is None or abs(angle - angle_deg) < abs(best[0] - angle_deg):
                best = (angle, state)
        return None if best is None else best[1]

    def shape_at(self, angle_deg, thickness=0.0):
        """Part compound with one child (face, or solid when thickness > 0) per patch, in patch id
        order, at `angle_deg`; built once per (design, angle, thickness). Do not modify it."""
        import Part

        from popupwb.core import popupcore

        cache_key = (self.key, round(float(angle_deg), 12), float(thickness))
        shape = _SHAPES.get(cache_key)
        if shape is None:
            brep = popupcore.patches_to_brep(self.scaffold, self.state_at(angle_deg), thickness)
            shape = Part.Shape()
            shape.importBrepFromString(brep, False)  # returns None, fills `shape`
            _remember(_SHAPES, cache_key, shape, _SHAPE_CACHE_SIZE)
        else:
            _SHAPES.move_to_end(cache_key)
        return shape

    def own_shape(self, name, angle_deg, thickness=0.0):
        """Compound of the patches object `name` owns (the card its pages, a mechanism its own),
        cut from shape_at(): what that object shows, one child per patch in id order."""
        children = self.shape_at(angle_deg, thickness).childShapes()
        return freecad_version.compound([children[i] for i in self.patches[name]])


def assembled_shape(card):
    """The whole card as one compound (its pages and every mechanism that builds, one child per
    patch in id order) at its FoldAngle, thickened as shown, placed at card.Placement.

    No object shows it (each shows its own patches, so selecting or hiding a mechanism acts on its
    faces): this is for what needs the card in one piece (export, tests). ValueError says why the
    card cannot be built or posed."""
    built = for_card(card)
    if built.card_error:
        raise ValueError(built.card_error)
    thickness = card.PaperThickness.Value if card.Thickened else 0.0
    shape = built.shape_at(card.FoldAngle.Value, thickness).copy()
    shape.Placement = card.Placement
    return shape


def _remember(cache, key, value, size):
    cache[key] = value
    while len(cache) > size:
        cache.popitem(last=False)


def _card_params(card):
    from popupwb.core import popupcore

    params = popupcore.CardParams()
    params.width = _number(card.Width)
    params.depth = _number(card.Depth)
    params.paper_thickness = _number(card.PaperThickness)
    params.name = card.Label
    return params


def _resolve_pair(obj, pairs):
    """The pair named by obj.HostPair; a stale name (the host was renamed) matches by its part."""
    wanted = obj.HostPair
    if not wanted:
        return pairs[0] if pairs else None
    for pair in pairs:
        if pair.name == wanted:
            return pair
    part = wanted.rsplit(".", 1)[-1]
    for pair in pairs:
        if pair.name.rsplit(".", 1)[-1] == part:
            return pair
    return None


def build(card):
    """A new CardScaffold of `card` (no cache; for_card() is the cached entry point)."""
    from popupwb.core import popupcore

    built = CardScaffold(design_key(card))
    try:
        scaffold = popupcore.make_card(_card_params(card))
    except ValueError as error:  # DesignError
        built.card_error = str(error)  # names the card by its Label and the parameter
        for obj in mechanisms_of(card):
            built.errors[
                obj.Name
            ] = f"{obj.Label}: the card {card.Label} cannot be built, fix it first"
        return built
    built.scaffold = scaffold
    built.order.append(card.Name)
    built.patches[card.Name] = [scaffold.ground, scaffold.backdrop]
    built.offered[card.Name] = [popupcore.central_fold(scaffold)]
    for obj in mechanisms_of(card):
        host = obj.Host
        if host.Name not in built.offered:
            built.errors[
                obj.Name
            ] = f"{obj.Label}: Host = {host.Label}, which is in error; fix it first"
            continue
        pairs = built.offered[host.Name]
        pair = _resolve_pair(obj, pairs)
        if pair is None:
            choices = ", ".join(f"'{p.name}'" for p in pairs) or "none"
            built.errors[obj.Name] = (
                f"{obj.Label}: HostPair = '{obj.HostPair}', must be one of the pairs "
                f"{host.Label} offers ({choices})"
            )
            continue
        try:
            parts = obj.Proxy.generate(obj, scaffold, pair)
        except ValueError as error:  # DesignError names the mechanism (its Label) and parameter
            built.errors[obj.Name] = str(error)
            continue
        built.order.append(obj.Name)
        built.patches[obj.Name] = list(parts.patches)
        built.offered[obj.Name] = list(parts.offered)
        built.parts[obj.Name] = parts
        built.sizes[obj.Name] = profile_cutting.part_sizes(scaffold, obj.Label, set(parts.patches))
        try:
            profile_cutting.apply_profiles(obj, scaffold, built.sizes[obj.Name])
        except ValueError as error:
            # The mechanism stays as generated so what stands on it still builds; the card is
            # not valid while this error stands (validity counts built.errors).
            built.errors[obj.Name] = str(error)
    return built


def for_card(card):
    """The CardScaffold of `card`, built once per design key (module-level cache, never saved)."""
    key = design_key(card)
    built = _BUILT.get(key)
    if built is None:
        built = build(card)
        _remember(_BUILT, key, built, _BUILT_CACHE_SIZE)
    else:
        _BUILT.move_to_end(key)
    return built


def clear_caches():
    """Forgets every cached scaffold, state and shape (tests, timing)."""
    _BUILT.clear()
    _STATES.clear()
    _SHAPES.clear()
