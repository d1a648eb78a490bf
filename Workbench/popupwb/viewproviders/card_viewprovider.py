"""View provider of a PopUpCard: its icon, faces coloured by patch role, and the mechanisms
standing on it as children in the tree. Module and class names are stored in .FCStd files."""

import popupwb
from popupwb.stateless_proxy import StatelessProxy


def deferred_colour(obj):
    """Colours now and once more after the C++ view provider rebuilt its face set (Python's
    updateData runs first, and DiffuseColor only takes when its length matches the faces)."""
    from PySide import QtCore

    from popupwb.viewproviders.patch_colours import colour_object

    colour_object(obj)
    QtCore.QTimer.singleShot(0, lambda: colour_object(obj))


def hosted_on(obj):
    """The mechanisms whose Host is `obj`, in document order."""
    from popupwb import card_scaffold

    try:
        objects = obj.Document.Objects
    except (ReferenceError, RuntimeError):
        return []
    return [o for o in objects if card_scaffold.is_mechanism(o) and getattr(o, "Host", None) is obj]


def attach_if_missing(obj, view_provider_class):
    """Gives `obj` its view provider when it has none: documents saved headless (make_* outside
    the GUI) open with bare view objects, without role colours, icons or task panels."""
    vobj = getattr(obj, "ViewObject", None)
    if vobj is not None and getattr(vobj, "Proxy", None) is None:
        view_provider_class(vobj)


class CardViewProvider(StatelessProxy):
    """Proxy of the PopUpCard's Gui::ViewProviderPartExt. Keeps no saved state (the object is
    remembered in attach(), which runs again after a file is opened)."""

    ICON = "PopUp_Card"

    def __init__(self, vobj):
        vobj.Proxy = self
        self.Object = vobj.Object
        # Paper is seen from both sides: light the back of every patch too.
        if "Lighting" in vobj.PropertiesList:
            vobj.Lighting = "Two side"

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        return popupwb.icon_path(self.ICON)

    def updateData(self, obj, prop):
        if prop == "Shape":
            deferred_colour(obj)

    def onChanged(self, vobj, prop):
        return None

    def claimChildren(self):
        obj = getattr(self, "Object", None)
        return hosted_on(obj) if obj is not None else []
