"""View provider of the mechanism features: icon per kind, faces coloured by patch role, the
mechanisms nested on it as tree children, and the parameter task panel on double click (setEdit).
Icon and panel come from popupwb.mechanism_registry. Module and class names are stored in .FCStd
files."""

import importlib

import popupwb
from popupwb.viewproviders.card_viewprovider import CardViewProvider


def _mechanism(holder):
    from popupwb import mechanism_registry

    obj = getattr(holder, "Object", None)  # a view object, or this proxy after attach()
    return mechanism_registry.by_type(getattr(getattr(obj, "Proxy", None), "TYPE", None))


class MechanismViewProvider(CardViewProvider):
    """Proxy of a mechanism's Gui::ViewProviderPartExt. Keeps no saved state."""

    def getIcon(self):
        mechanism = _mechanism(self)
        return mechanism.icon if mechanism else popupwb.icon_path("PopUp_Card")

    def doubleClicked(self, vobj):
        import FreeCADGui

        FreeCADGui.ActiveDocument.setEdit(vobj.Object.Name, 0)
        return True

    def setEdit(self, vobj, mode=0):
        mechanism = _mechanism(vobj)
        if mode != 0 or mechanism is None:
            return None  # transform and other modes: FreeCAD's own
        import FreeCADGui

        module, class_name = mechanism.task_panel
        panel = getattr(importlib.import_module(module), class_name)
        FreeCADGui.Control.showDialog(panel(vobj.Object))
        return True

    def unsetEdit(self, vobj, mode=0):
        if mode != 0:
            return None
        import FreeCADGui

        FreeCADGui.Control.closeDialog()
        return True
