"""GUI commands of the PopUp workbench. Importing this package registers them with FreeCADGui."""

from popupwb.commands import (
    animate,
    check_validity,
    create_card,
    create_cutting_sheet,
    create_mechanism,
    export_sheets,
    load_design,
)
from popupwb.mechanism_registry import COMMAND_IDS as MECHANISM_COMMAND_IDS

# Toolbar and menu order: make a card, nest mechanisms on it, check and play it, lay it out on
# cutting sheets and export them; design files.
COMMANDS = (
    [create_card.COMMAND_ID]
    + MECHANISM_COMMAND_IDS
    + [check_validity.COMMAND_ID, animate.COMMAND_ID]
    + [create_cutting_sheet.COMMAND_ID, export_sheets.COMMAND_ID, load_design.COMMAND_ID]
)
