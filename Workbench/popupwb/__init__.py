"""PopUp workbench: paper pop-up design in FreeCAD.

Importing this package is cheap (no FreeCAD, no popupcore): InitGui.py reads icon paths from it.
"""

import os

__version__ = "0.1.0"

PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__))
ICONS_DIR = os.path.join(PACKAGE_DIR, "resources", "icons")
# Source tree root (the Mod folder is usually a symlink to <repo>/Workbench).
REPO_DIR = os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(__file__))))


def icon_path(name):
    """Absolute path of the SVG icon `name` (a command id such as "PopUp_CheckValidity")."""
    return os.path.join(ICONS_DIR, name + ".svg")
