"""Attaching a feature's view provider by module and class name, as Draft's
gui_utils.restore_view_object does.

Each feature proxy names its view provider as strings (VIEW_PROVIDER: a module of
popupwb.viewproviders and a class in it). make_* attach it to new objects, and a feature's
onDocumentRestored to objects saved without the GUI (make_* outside the GUI, `popup`, the demo),
which open with bare view objects: no role colours, icons or task panels. The module is imported
only when the GUI is up, so features never import GUI code and popupwb.viewproviders never loads
headless.
"""

import importlib

import FreeCAD

VIEW_PROVIDERS = "popupwb.viewproviders"


def view_provider_class(proxy):
    """The view provider class `proxy` (a feature proxy or its class) names in VIEW_PROVIDER."""
    module, class_name = proxy.VIEW_PROVIDER
    return getattr(importlib.import_module(f"{VIEW_PROVIDERS}.{module}"), class_name)


def attach_view_provider(obj):
    """Gives `obj` the view provider its proxy names, when the GUI is up and its view object has
    no proxy yet; True when it did."""
    if not FreeCAD.GuiUp:
        return False
    vobj = getattr(obj, "ViewObject", None)
    if vobj is None or getattr(vobj, "Proxy", None) is not None:
        return False
    view_provider_class(obj.Proxy)(vobj)
    return True
