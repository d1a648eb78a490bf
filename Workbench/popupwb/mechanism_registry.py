"""The mechanism types of the workbench, listed once.

Each entry ties a feature proxy class to its make_* function (popupwb.make generates them from
this list), its GUI command id, icon, menu text, tool tip and task panel. The toolbar, the menu,
the commands, the view provider's icon and edit panel and popupwb.make all read this table; a new
mechanism type is one feature module and one entry here. Importable headless (no GUI imports).
"""

import dataclasses

import popupwb
from popupwb.features.box_fold import BoxFold
from popupwb.features.floating_layer import FloatingLayer
from popupwb.features.horizontal_translation import HorizontalTranslation
from popupwb.features.rotation_arm import RotationArm
from popupwb.features.step_fold import StepFold
from popupwb.features.tent_fold import TentFold
from popupwb.features.v_box_fold import VBoxFold
from popupwb.features.v_fold import VFold
from popupwb.features.vertical_translation import VerticalTranslation

# The parameter task panel (GUI only, so named, not imported): module and class.
PARAMETER_PANEL = ("popupwb.taskpanels.mechanism_panel", "MechanismPanel")


@dataclasses.dataclass(frozen=True)
class Mechanism:
    """One mechanism type. The new object's Name is the feature class name (TentFold, ...)."""

    feature: type  # the MechanismFeature subclass (its module and name are stored in files)
    command_id: str  # PopUp_<Thing>; also the icon's name
    make_name: str  # popupwb.make.<make_name>(host, host_pair=None, name=..., **parameters)
    menu_text: str
    tool_tip: str
    motion: bool = False  # a motion mechanism (thesis §4.3): its own toolbar and menu group
    task_panel: tuple = PARAMETER_PANEL

    @property
    def type_name(self):
        """The feature's TYPE, e.g. "PopUp::TentFold"."""
        return self.feature.TYPE

    @property
    def icon(self):
        """Absolute path of the SVG icon, named after the command id."""
        return popupwb.icon_path(self.command_id)


# Toolbar and menu order.
MECHANISMS = (
    Mechanism(
        TentFold,
        "PopUp_TentFold",
        "make_tent_fold",
        "Tent fold",
        "Add a tent fold (two slopes meeting at an apex) on the selected card, box fold or "
        "floating layer",
    ),
    Mechanism(
        StepFold,
        "PopUp_StepFold",
        "make_step_fold",
        "Step fold",
        "Add a parallelogram step fold on the selected card, box fold or floating layer",
    ),
    Mechanism(
        VFold,
        "PopUp_VFold",
        "make_v_fold",
        "V-fold",
        "Add a v-fold (two triangles on a spine) on the selected card, box fold or floating layer",
    ),
    Mechanism(
        BoxFold,
        "PopUp_BoxFold",
        "make_box_fold",
        "Box fold",
        "Add a box fold on the selected card, box fold or floating layer; it offers its top and "
        "sides as hosts",
    ),
    Mechanism(
        VBoxFold,
        "PopUp_VBoxFold",
        "make_v_box_fold",
        "V-box",
        "Add a type-1 v-fold (four walls on a rhombus, two-triangle top) on the selected card "
        "or box fold",
    ),
    Mechanism(
        RotationArm,
        "PopUp_RotationArm",
        "make_rotation_arm",
        "Rotation arm",
        "Add a rotation arm (a v-fold whose wing carries an arm past the spine) on the "
        "selected card, box fold or floating layer (on a layer's side pair it turns off the "
        "central fold)",
        motion=True,
    ),
    Mechanism(
        HorizontalTranslation,
        "PopUp_HorizontalTranslation",
        "make_horizontal_translation",
        "Horizontal translation",
        "Add a horizontal translation (a step fold and a patch sliding through a slit at its "
        "nose) on the selected card or box fold",
        motion=True,
    ),
    Mechanism(
        VerticalTranslation,
        "PopUp_VerticalTranslation",
        "make_vertical_translation",
        "Vertical translation",
        "Add a vertical translation (front walls and a two-triangle top whose front corner slides "
        "along the fold) on the selected card or box fold",
        motion=True,
    ),
    Mechanism(
        FloatingLayer,
        "PopUp_FloatingLayer",
        "make_floating_layer",
        "Floating layer",
        "Add a floating layer (a platform parallel to its host on two supports) on the selected "
        "card or box fold; it offers its platform and supports as hosts",
    ),
)

COMMAND_IDS = [m.command_id for m in MECHANISMS]
# Structures that stand or carry (tent, step, boxes, floating layer), and the motion mechanisms
# whose parts slide or swing as the card opens: the two groups of the toolbars and menus.
STRUCTURE_COMMAND_IDS = [m.command_id for m in MECHANISMS if not m.motion]
MOTION_COMMAND_IDS = [m.command_id for m in MECHANISMS if m.motion]
_BY_COMMAND = {m.command_id: m for m in MECHANISMS}
_BY_TYPE = {m.type_name: m for m in MECHANISMS}
# The core's generator kind ("box_fold", as popupcore.fit_design names a FittedMechanism's type):
# the feature's GENERATOR is "add_<kind>".
_BY_CORE_KIND = {m.feature.GENERATOR[len("add_") :]: m for m in MECHANISMS}


def by_command(command_id):
    """The Mechanism of a command id (KeyError for another id)."""
    return _BY_COMMAND[command_id]


def by_type(type_name):
    """The Mechanism whose feature has TYPE `type_name`, or None."""
    return _BY_TYPE.get(type_name)


def by_core_kind(kind):
    """The Mechanism whose core generator is add_<kind> ("box_fold", "tent_fold"...), or None."""
    return _BY_CORE_KIND.get(kind)
