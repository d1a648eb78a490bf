"""make_mechanism and one make_* per mechanism type of popupwb.mechanism_registry (make_tent_fold,
make_step_fold, make_box_fold, ...): mechanisms on a host, headless or in the GUI.

Keyword parameters are the popupcore field names (foot, run_ground, hinge_angle...) or the property
names (Foot, RunGround, HingeAngle...); lengths in mm, angles in degrees as in FreeCAD. Parameters
left out start fitted to the host pair (its hinge length and depths), or at the property defaults
when the host does not build; without an Offset, a mechanism joining others on the pair is placed
in its largest free span (popupwb.model.placement), with a warning when there is none.
"""

import FreeCAD

from popupwb.model import card_scaffold, placement
from popupwb.mechanism_registry import MECHANISMS
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
    given = {by_key[key]: value for key, value in params.items()}
    values.update(given)
    # Beside the mechanisms already on that pair, not inside them (thesis §4.2.2).
    placed = placement.place(proxy_class, host, host_pair, values, given)
    values = placed.values

    doc = host.Document
    obj = doc.addObject("Part::FeaturePython", name or proxy_class.__name__)
    proxy_class(obj)
    for prop, value in values.items():
        setattr(obj, prop, value)
    obj.Host = host  # sets Card and the HostPair choices
    obj.HostPair = host_pair
    if FreeCAD.GuiUp:
        view_provider_class(obj.Proxy)(obj.ViewObject)
    message = placed.message(obj.Label)
    if message:
        FreeCAD.Console.PrintWarning(message + "\n")
    return obj


_UNITS = {"length": "mm", "angle": "degrees", "bool": "bool", "integer": "count"}


def _make_function(mechanism):
    """make_<type>(host, host_pair=None, name=<class name>, **parameters) for one registry entry,
    documented from the feature's parameters (so the list cannot drift from the properties)."""
    feature = mechanism.feature

    def make(host, host_pair=None, name=feature.__name__, **params):
        return make_mechanism(feature, host, host_pair, name, **params)

    fields = ", ".join(f"{p.field} ({_UNITS[p.kind]})" for p in feature.PARAMETERS)
    make.__name__ = make.__qualname__ = mechanism.make_name
    make.__doc__ = (
        f"A {feature.__name__} on `host` at its base patch pair `host_pair` (default: the first "
        f"it offers); parameters: {fields}. The caller recomputes."
    )
    return make


for _mechanism in MECHANISMS:
    globals()[_mechanism.make_name] = _make_function(_mechanism)
