"""GUI commands of the PopUp workbench. Importing this package registers them with FreeCADGui."""

from popupwb.commands import check_validity, load_design

COMMANDS = [load_design.COMMAND_ID, check_validity.COMMAND_ID]
