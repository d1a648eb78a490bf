"""GUI commands of the PopUp workbench. Importing this package registers them with FreeCADGui.

GROUPS is how the toolbars and the menu show them, in a maker's order: make a card, nest
mechanisms on it (structures, then motion mechanisms), check and play it, lay it out on cutting
sheets and export them. A mechanism's profile from a sketch (PopUp_SetProfile) sits after the
mechanisms. InitGui builds one toolbar per group, the PopUp menu with a Mechanisms
submenu, and the right-click menu on cards and mechanisms from these lists.
"""

from popupwb.commands import (
    animate,
    check_validity,
    create_card,
    create_cutting_sheet,
    create_mechanism,
    export_sheets,
    from_animation,
    from_model,
    load_design,
    set_profile,
)
from popupwb.mechanism_registry import MOTION_COMMAND_IDS, STRUCTURE_COMMAND_IDS

SEPARATOR = "Separator"

CARD_COMMANDS = [
    create_card.COMMAND_ID,
    load_design.COMMAND_ID,
    from_model.COMMAND_ID,
    from_animation.COMMAND_ID,
]
MECHANISM_COMMANDS = list(STRUCTURE_COMMAND_IDS)
MOTION_COMMANDS = list(MOTION_COMMAND_IDS)
PROFILE_COMMANDS = [set_profile.COMMAND_ID]
CHECK_COMMANDS = [check_validity.COMMAND_ID, animate.COMMAND_ID]
SHEET_COMMANDS = [create_cutting_sheet.COMMAND_ID, export_sheets.COMMAND_ID]

# (toolbar name, commands); the name is also the QToolBar's object name.
GROUPS = (
    ("PopUp card", CARD_COMMANDS),
    ("PopUp mechanisms", MECHANISM_COMMANDS + [SEPARATOR] + PROFILE_COMMANDS),
    ("PopUp motion mechanisms", MOTION_COMMANDS),
    ("PopUp check", CHECK_COMMANDS),
    ("PopUp sheets", SHEET_COMMANDS),
)

COMMANDS = [command for _, commands in GROUPS for command in commands if command != SEPARATOR]

# The PopUp menu: card, the Mechanisms submenu, check, sheets, with separators between.
MENU = "PopUp"
MECHANISM_SUBMENU = [MENU, "Mechanisms"]
ADD_MECHANISM_SUBMENU = "Add mechanism"  # in the right-click menu of a card or host mechanism


def add_mechanism_commands():
    """The mechanism submenu's entries: structures, a separator, motion mechanisms."""
    return MECHANISM_COMMANDS + [SEPARATOR] + MOTION_COMMANDS
