"""The mechanism types of the workbench, listed once.

Each entry ties a feature proxy class to its make_* function (popupwb.make generates them from
this list), its GUI command id, icon, menu text, tool tip and task panel. The kinds, their order,
titles and motion flags are the core's mechanism catalogue's (mechanism_catalogue.py); this module
adds what only the GUI has: the feature class, the tool tip, the task panel. The toolbar, the
menu, the commands, the view provider's icon and edit panel and popupwb.make all read this table;
a new mechanism type is one catalogue row in the core, one feature module and one tool tip here.
Importable headless (no GUI imports).
"""

import dataclasses

import popupwb
from popupwb import mechanism_catalogue
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
    tool_tip: str
    task_panel: tuple = PARAMETER_PANEL

    @property
    def kind(self):
        """The core catalogue's kind, e.g. "tent_fold"."""
        return self.feature.KIND

    @property
    def command_id(self):
        """PopUp_<Feature>; also the icon's name."""
        return f"PopUp_{self.feature.__name__}"

    @property
    def make_name(self):
        """popupwb.make.<make_name>(host, host_pair=None, name=..., **parameters)"""
        return f"make_{self.kind}"

    @property
    def menu_text(self):
        """The kind's title in the catalogue."""
        return mechanism_catalogue.entry(self.kind).title

    @property
    def motion(self):
        """A motion mechanism (thesis §4.3): its own toolbar and menu group."""
        return mechanism_catalogue.entry(self.kind).motion

    @property
    def type_name(self):
        """The feature's TYPE, e.g. "PopUp::TentFold"."""
        return self.feature.TYPE

    @property
    def icon(self):
        """Absolute path of the SVG icon, named after the command id."""
        return popupwb.icon_path(self.command_id)


_FEATURES = (
    TentFold,
    StepFold,
    VFold,
    BoxFold,
    VBoxFold,
    RotationArm,
    HorizontalTranslation,
    VerticalTranslation,
    FloatingLayer,
)
# What the toolbar button says a kind does (GUI words; the catalogue holds the kind's facts).
_TOOL_TIPS = {
    "tent_fold": "Add a tent fold (two slopes meeting at an apex) on the selected card, box fold "
    "or floating layer",
    "step_fold": "Add a parallelogram step fold on the selected card, box fold or floating layer",
    "v_fold": "Add a v-fold (two triangles on a spine) on the selected card, box fold or "
    "floating layer",
    "box_fold": "Add a box fold on the selected card, box fold or floating layer; it offers its "
    "top and sides as hosts",
    "v_box_fold": "Add a type-1 v-fold (four walls on a rhombus, two-triangle top) on the "
    "selected card or box fold",
    "rotation_arm": "Add a rotation arm (a v-fold whose wing carries an arm past the spine) on the "
    "selected card, box fold or floating layer (on a layer's side pair it turns off the "
    "central fold)",
    "horizontal_translation": "Add a horizontal translation (a step fold and a patch sliding "
    "through a slit at its nose) on the selected card or box fold",
    "vertical_translation": "Add a vertical translation (front walls and a two-triangle top whose "
    "front corner slides along the fold) on the selected card or box fold",
    "floating_layer": "Add a floating layer (a platform parallel to its host on two supports) on "
    "the selected card or box fold; it offers its platform and supports as hosts",
}


def _in_catalogue_order():
    by_kind = {feature.KIND: feature for feature in _FEATURES}
    return tuple(
        Mechanism(by_kind[row.kind], _TOOL_TIPS[row.kind]) for row in mechanism_catalogue.entries()
    )


# Toolbar and menu order: the catalogue's.
MECHANISMS = _in_catalogue_order()

COMMAND_IDS = [m.command_id for m in MECHANISMS]
# Structures that stand or carry (tent, step, boxes, floating layer), and the motion mechanisms
# whose parts slide or swing as the card opens: the two groups of the toolbars and menus.
STRUCTURE_COMMAND_IDS = [m.command_id for m in MECHANISMS if not m.motion]
MOTION_COMMAND_IDS = [m.command_id for m in MECHANISMS if m.motion]
_BY_COMMAND = {m.command_id: m for m in MECHANISMS}
_BY_TYPE = {m.type_name: m for m in MECHANISMS}
# The core catalogue's kind ("box_fold", as popupcore.fit_design names a FittedMechanism's kind).
_BY_CORE_KIND = {m.feature.KIND: m for m in MECHANISMS}


def by_command(command_id):
    """The Mechanism of a command id (KeyError for another id)."""
    return _BY_COMMAND[command_id]


def by_type(type_name):
    """The Mechanism whose feature has TYPE `type_name`, or None."""
    return _BY_TYPE.get(type_name)


def by_core_kind(kind):
    """The Mechanism of the core catalogue's kind ("box_fold", "tent_fold"...), or None."""
    return _BY_CORE_KIND.get(kind)
