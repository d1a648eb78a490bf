"""Headless constructors of PopUp objects: what commands, macros and tests call.

The mechanisms' make_* functions (make_tent_fold, make_box_fold, ...) come from
popupwb.mechanism_registry, one per entry.
"""

from popupwb.make import make_mechanisms
from popupwb.make.make_card import make_card
from popupwb.make.make_cutting_sheet import make_cutting_sheet
from popupwb.make.make_mechanisms import make_mechanism
from popupwb.make.make_scaffold import make_scaffold
from popupwb.mechanism_registry import MECHANISMS

for _mechanism in MECHANISMS:
    globals()[_mechanism.make_name] = getattr(make_mechanisms, _mechanism.make_name)

__all__ = sorted(
    ["make_card", "make_cutting_sheet", "make_mechanism", "make_scaffold"]
    + [m.make_name for m in MECHANISMS]
)
