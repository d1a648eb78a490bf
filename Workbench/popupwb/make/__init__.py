"""Headless constructors of PopUp objects: what commands, macros and tests call."""

from popupwb.make.make_card import make_card
from popupwb.make.make_cutting_sheet import make_cutting_sheet
from popupwb.make.make_mechanisms import (
    make_box_fold,
    make_floating_layer,
    make_horizontal_translation,
    make_mechanism,
    make_rotation_arm,
    make_step_fold,
    make_tent_fold,
    make_v_box_fold,
    make_v_fold,
    make_vertical_translation,
)
from popupwb.make.make_scaffold import make_scaffold

__all__ = [
    "make_box_fold",
    "make_card",
    "make_cutting_sheet",
    "make_floating_layer",
    "make_horizontal_translation",
    "make_mechanism",
    "make_rotation_arm",
    "make_scaffold",
    "make_step_fold",
    "make_tent_fold",
    "make_v_box_fold",
    "make_v_fold",
    "make_vertical_translation",
]
