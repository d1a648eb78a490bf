"""Headless constructors of PopUp objects: what commands, macros and tests call."""

from popupwb.make.make_scaffold import make_scaffold

__all__ = ["make_scaffold"]
