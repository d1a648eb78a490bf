"""Where mechanisms stand along their host pair's hinge (thesis §4.2.2): the span each one sweeps
over the whole fold, the spans its siblings leave free, and a new mechanism placed in the largest
free span.

The spans are the core's (MechanismParts.sweep_from and sweep_to, mm along the host pair's hinge
from its origin; a box's end panels reach past its ends); this module only reads and compares
them, and measures a new mechanism's span by generating it on a copy of the card's scaffold.
Two mechanisms on one pair whose spans overlap may collide (popupcore.placement_conflicts);
spans on different pairs never conflict by this rule. Headless.
"""

import collections
import dataclasses

from popupwb.model import card_scaffold

# A span in mm along a host pair's hinge; `label` names the mechanism that sweeps it.
Span = collections.namedtuple("Span", "label start end")

# A mechanism shrunk to fit a free span takes this share of it, centred: some paper between
# neighbours, so that one can still be moved without touching the other.
FILL = 0.8
# Shrunk below this share of its fitted size a mechanism is too small to be what the maker asked
# for: that span does not count as free.
SMALLEST_SCALE = 0.1


def millimetres(value):
    return f"{value:.1f}"


def spans_text(spans):
    return ", ".join(f"{s.label} {millimetres(s.start)}–{millimetres(s.end)} mm" for s in spans)


def spans_on(built, pair_name, without=None):
    """Spans of the mechanisms of `built` (a CardScaffold) standing on the pair `pair_name`, by
    start; `without` is an object name left out."""
    spans = [
        Span(parts.name, parts.sweep_from, parts.sweep_to)
        for name, parts in built.parts.items()
        if parts.host == pair_name and name != without
    ]
    return sorted(spans, key=lambda s: (s.start, s.end))


def free_spans(length, spans):
    """The parts of [0, length] that no span covers, as (start, end) in order; empty ones are
    left out."""
    free, cursor = [], 0.0
    for span in spans:
        if span.start > cursor:
            free.append((cursor, min(span.start, length)))
        cursor = max(cursor, span.end)
        if cursor >= length:
            break
    if cursor < length:
        free.append((cursor, length))
    return [(a, b) for a, b in free if b > a]


def largest_free_span(length, spans):
    """The longest free (start, end) of [0, length] (the first of equals), or None."""
    return max(free_spans(length, spans), key=lambda f: f[1] - f[0], default=None)


def host_pair(built, host, pair_name):
    """The popupcore.BasePatchPair `pair_name` that `host` offers in `built`, or None."""
    return next((p for p in built.offered.get(host.Name, []) if p.name == pair_name), None)


def measure(proxy_class, built, pair, values):
    """The (start, end) span a `proxy_class` mechanism with property `values` (name -> mm or
    degrees, defaults for the others) would sweep on `pair`, generated on a copy of the scaffold.
    ValueError (the core's message) when the generator refuses the values."""
    from popupwb.core import popupcore

    plain = [values.get(p.name, p.default) for p in proxy_class.PARAMETERS]
    params = proxy_class.core_parameters(plain, proxy_class.__name__)
    generator = getattr(popupcore, proxy_class.GENERATOR)
    parts = generator(built.scaffold.copy(), pair, params, proxy_class.__name__)
    return parts.sweep_from, parts.sweep_to


@dataclasses.dataclass
class Placed:
    """What place() decided: the values to use, and for the report what it saw."""

    values: dict  # property name -> value, the caller's and the placed ones
    pair_name: str = ""
    length: float = 0.0  # of the host pair's hinge (mm)
    taken: list = dataclasses.field(default_factory=list)  # Spans of the siblings
    span: tuple = None  # (start, end) the new mechanism sweeps, when placed
    free: tuple = None  # the largest free (start, end), None when the pair is full
    no_free_span: bool = False

    def message(self, label):
        """One line for the report view when there was no free span, else None."""
        if not self.no_free_span:
            return None
        if self.free is None:
            room = "none is left"
        else:
            room = (
                f"the largest, {millimetres(self.free[0])}–{millimetres(self.free[1])} mm, is too "
                f"short even at {SMALLEST_SCALE:g} of its fitted size"
            )
        return (
            f"{label}: no free span on {self.pair_name} for it ({room}; 0–"
            f"{millimetres(self.length)} mm taken by {spans_text(self.taken)}): it starts at its "
            "defaults and overlaps, so they may collide as the card folds (thesis §4.2.2); make "
            "room or move it"
        )


def place(proxy_class, host, pair_name, values, given=()):
    """`values` (the fitted parameters) placed in the largest free span of `host`'s pair
    `pair_name`: Offset centres the new mechanism's span there and, when the span is too short,
    the length parameters not `given` by the caller shrink together. Nothing moves when the pair
    carries no mechanism yet, when the caller gave the Offset, or when the host does not build;
    Placed.no_free_span when nothing fits (the values stay the fitted ones)."""
    values = dict(values)
    try:
        built = card_scaffold.for_card(card_scaffold.root_card(host))
    except ValueError:
        return Placed(values)
    pair = host_pair(built, host, pair_name)
    if pair is None or "Offset" in given:
        return Placed(values)
    placed = Placed(values, pair.name, pair.length, spans_on(built, pair.name))
    if not placed.taken:
        return placed
    try:
        start, end = measure(proxy_class, built, pair, values)
    except ValueError:
        return placed  # the new object shows the core's message on its own
    free = placed.free = largest_free_span(pair.length, placed.taken)
    width = end - start
    room = 0.0 if free is None else free[1] - free[0]
    scale = 1.0 if width <= FILL * room else FILL * room / width
    if free is None or scale < SMALLEST_SCALE:
        placed.no_free_span = True
        return placed

    lengths = [p.name for p in proxy_class.PARAMETERS if p.kind == "length"]
    offset = values.get("Offset", 0.0)
    trial = dict(values)
    for name in lengths:
        if name != "Offset" and name not in given and name in trial:
            trial[name] = scale * trial[name]
    # Offset moves the whole span; the rest of the span scales with the lengths.
    before, after = (start - offset) * scale, (end - offset) * scale
    trial["Offset"] = 0.5 * (free[0] + free[1]) - 0.5 * (before + after)
    try:
        span = measure(proxy_class, built, pair, trial)
    except ValueError:
        span = None
    tolerance = 1e-9 * max(pair.length, 1.0)
    if span is None or span[0] < free[0] - tolerance or span[1] > free[1] + tolerance:
        placed.no_free_span = True
        return placed
    placed.values, placed.span = trial, span
    return placed


def overlaps(obj):
    """(own Span, [Spans of siblings on the same pair it overlaps], host pair) for a built
    mechanism, by the core's placement_conflicts; None when it did not build."""
    from popupwb.core import popupcore

    try:
        built = card_scaffold.for_card(card_scaffold.root_card(obj))
    except ValueError:
        return None
    parts = built.parts.get(obj.Name)
    if parts is None:
        return None
    siblings = [p for n, p in built.parts.items() if p.host == parts.host and n != obj.Name]
    conflicts = popupcore.placement_conflicts([parts] + siblings)
    hit = {b if a == parts.name else a for a, b in conflicts if parts.name in (a, b)}
    own = Span(parts.name, parts.sweep_from, parts.sweep_to)
    others = [Span(p.name, p.sweep_from, p.sweep_to) for p in siblings if p.name in hit]
    return own, sorted(others, key=lambda s: s.start), host_pair(built, obj.Host, parts.host)


def span_report(obj):
    """(text, ok) about obj's span for its task panel: where it stands on its host pair, and
    what it overlaps or how far it reaches past the pair's ends; None when it did not build."""
    found = overlaps(obj)
    if found is None:
        return None
    own, others, pair = found
    length = pair.length if pair is not None else float("inf")
    text = (
        f"{obj.Label} spans {millimetres(own.start)}–{millimetres(own.end)} mm of "
        f"{pair.name if pair is not None else obj.HostPair} (0–{millimetres(length)} mm)"
    )
    problems = []
    if others:
        problems.append(
            f"overlaps {spans_text(others)}: they may collide as the card folds (thesis §4.2.2)"
        )
    if own.start < 0 or own.end > length:
        past = max(-own.start, own.end - length)
        problems.append(f"reaches {millimetres(past)} mm past the end of its host pair")
    if problems and pair is not None:
        try:
            built = card_scaffold.for_card(card_scaffold.root_card(obj))
            taken = spans_on(built, pair.name, without=obj.Name)
        except ValueError:
            taken = []
        free = largest_free_span(length, taken)
        problems.append(
            f"largest free span {millimetres(free[0])}–{millimetres(free[1])} mm"
            if free
            else f"no free span left on {pair.name}"
        )
    return (text + ("; " + "; ".join(problems) if problems else ""), not problems)
