"""make_tent_fold, make_step_fold, make_v_fold, make_box_fold, make_v_box_fold,
make_floating_layer: mechanisms on a host, headless or in the GUI.

Keyword parameters are the popupcore field names (foot, run_ground, hinge_angle...) or the property
names (Foot, RunGround, HingeAngle...); lengths in mm, angles in degrees as in FreeCAD. Parameters
left out start fitted to the host pair (its hinge length and depths), or at the property defaults
when the host does not build.
"""

import FreeCAD

from popupwb import card_scaffold
from popupwb.features.box_fold import BoxFold
from popupwb.features.floating_layer import FloatingLayer
from popupwb.features.horizontal_translation import HorizontalTranslation
from popupwb.features.step_fold import StepFold
from popupwb.features.tent_fold import TentFold
from popupwb.features.rotation_arm import RotationArm
from popupwb.features.v_box_fold import VBoxFold
from popupwb.features.vertical_translation import VerticalTranslation
from popupwb.features.v_fold import VFold
from popupwb.view_provider_by_name import view_provider_class


def _host_pair(host, name):
    """The popupcore.BasePatchPair `name` of `host` from the card's scaffold, or None."""
    try:
        built = card_scaffold.for_card(card_scaffold.root_card(host))
    except ValueError:
        return None
    for pair in built.offered.get(host.Name, []):
        if pair.name == name:
            return pair
    return None


def make_mechanism(proxy_class, host, host_pair=None, name=None, **params):
    """Adds a `proxy_class` mechanism on `host` (a PopUpCard or a mechanism) at its base patch pair
    `host_pair` (default: the first it offers). The caller recomputes."""
    if not (card_scaffold.is_card(host) or card_scaffold.is_mechanism(host)):
        label = getattr(host, "Label", host)
        raise ValueError(f"{proxy_class.__name__}: host {label} must be a PopUpCard or a mechanism")
    choices = card_scaffold.host_pair_names(host)
    if not choices:
        raise ValueError(f"{proxy_class.__name__}: {host.Label} offers no base patch pair")
    if host_pair is None:
        host_pair = choices[0]
    if host_pair not in choices:
        raise ValueError(
            f"{proxy_class.__name__}: host_pair = {host_pair!r}, must be one of {choices}"
        )
    by_key = {}
    for p in proxy_class.PARAMETERS:
        by_key[p.name] = by_key[p.field] = p.name
    unknown = sorted(set(params) - set(by_key))
    if unknown:
        raise TypeError(
            f"{proxy_class.__name__}: unknown parameter(s) {unknown}; "
            f"known: {[p.field for p in proxy_class.PARAMETERS]}"
        )

    values = {}
    pair = _host_pair(host, host_pair)
    if pair is not None:
        values.update(proxy_class.fitted_parameters(pair))
    values.update({by_key[key]: value for key, value in params.items()})

    doc = host.Document
    obj = doc.addObject("Part::FeaturePython", name or proxy_class.__name__)
    proxy_class(obj)
    for prop, value in values.items():
        setattr(obj, prop, value)
    obj.Host = host  # sets Card and the HostPair choices
    obj.HostPair = host_pair
    if FreeCAD.GuiUp:
        view_provider_class(obj.Proxy)(obj.ViewObject)
    return obj


def make_tent_fold(host, host_pair=None, name="TentFold", **params):
    """A TentFold on `host`: offset, width, foot, foot_backdrop, slope (mm)."""
    return make_mechanism(TentFold, host, host_pair, name, **params)


def make_step_fold(host, host_pair=None, name="StepFold", **params):
    """A StepFold on `host`: offset, width, run_ground, run_backdrop (mm)."""
    return make_mechanism(StepFold, host, host_pair, name, **params)


def make_v_fold(host, host_pair=None, name="VFold", **params):
    """A VFold on `host`: offset, run, spine (mm), hinge_angle, spine_angle (degrees)."""
    return make_mechanism(VFold, host, host_pair, name, **params)


def make_box_fold(host, host_pair=None, name="BoxFold", **params):
    """A BoxFold on `host`: offset, width, depth_ground, depth_backdrop, height (mm), front and
    back (bools)."""
    return make_mechanism(BoxFold, host, host_pair, name, **params)


def make_v_box_fold(host, host_pair=None, name="VBoxFold", **params):
    """A VBoxFold (type-1 v-fold) on `host`: offset, side, height (mm), wall_angle (degrees)."""
    return make_mechanism(VBoxFold, host, host_pair, name, **params)


def make_floating_layer(host, host_pair=None, name="FloatingLayer", **params):
    """A FloatingLayer on `host`: offset, width, height, support, overhang (mm)."""
    return make_mechanism(FloatingLayer, host, host_pair, name, **params)


def make_rotation_arm(host, host_pair=None, name="RotationArm", **params):
    """A RotationArm on `host` (open flat): offset, spine, run, arm (mm)."""
    return make_mechanism(RotationArm, host, host_pair, name, **params)


def make_vertical_translation(host, host_pair=None, name="VerticalTranslation", **params):
    """A VerticalTranslation on `host` (open flat): offset, side, height (mm), wall_angle (deg)."""
    return make_mechanism(VerticalTranslation, host, host_pair, name, **params)


def make_horizontal_translation(host, host_pair=None, name="HorizontalTranslation", **params):
    """A HorizontalTranslation on `host` (open flat): offset, width, run_ground, run_backdrop,
    reach (mm)."""
    return make_mechanism(HorizontalTranslation, host, host_pair, name, **params)
