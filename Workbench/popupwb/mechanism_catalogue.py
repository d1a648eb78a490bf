"""The core's mechanism catalogue as the Workbench reads it (popupcore.mechanism_catalogue(),
core/include/popup/mechanisms/mechanism_catalogue.hpp): per kind its parameters, the base patch
pairs it offers and its parts' titles. The features' parameter tables, the registry and the part
titles come from here, so a kind's facts live once, in the core. Headless (no FreeCAD).
"""

import collections
import functools
import math

from popupwb.core import popupcore

# One parameter of a feature: its property `name`, `kind` ("length": App::PropertyDistance, mm,
# signed so that the core, not FreeCAD's clamping, judges a negative value; "angle":
# App::PropertyAngle, degrees, radians for the core; "bool"; "integer": App::PropertyInteger, a
# count), the core's params `field`, its `doc` (with its range), its `default` and `range`.
Parameter = collections.namedtuple("Parameter", "name kind field doc default range")

# The catalogue's units as the features' property kinds.
_KINDS = {"length": "length", "angle": "angle", "flag": "bool", "count": "integer"}


def entry(kind):
    """The catalogue's row of `kind` ("box_fold"...); ValueError naming the known kinds."""
    return popupcore.catalogue_entry(kind)


def entries():
    """Every kind's row, in toolbar order."""
    return list(popupcore.mechanism_catalogue())


def _default(field, kind):
    if kind == "angle":
        return round(math.degrees(field.default), 9)  # 60°, not 59.99999999999999°
    if kind == "bool":
        return bool(field.default)
    if kind == "integer":
        return int(field.default)
    return float(field.default)


@functools.lru_cache(maxsize=None)
def parameters(kind):
    """The Parameter tuple of `kind`, in the task panel's order."""
    table = []
    for field in entry(kind).fields:
        property_kind = _KINDS[field.unit]
        table.append(
            Parameter(
                field.property,
                property_kind,
                field.name,
                f"{field.doc} ({field.range})",
                _default(field, property_kind),
                field.range,
            )
        )
    return tuple(table)


def part_titles(kind):
    """{part code: maker title} of `kind`'s parts."""
    return dict(entry(kind).parts)


def card_part_titles():
    """{part code: maker title} of the card's own parts (its two pages)."""
    return dict(popupcore.card_part_titles())


def part_title(kind, code):
    """What a maker calls part `code` of a `kind` mechanism (strips "FL2" included)."""
    return popupcore.part_title(kind, code)
