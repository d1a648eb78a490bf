"""View provider of a PopUpCard: its icon (marked by the validity verdict), its pages coloured by
patch role, and the mechanisms standing on it as children in the tree. Module and class names are stored in .FCStd files."""

import popupwb
from popupwb.stateless_proxy import StatelessProxy
from popupwb.viewproviders.restored_visibility import show_by_role


def hosted_on(obj):
    """The mechanisms whose Host is `obj`, in document order."""
    from popupwb.model import card_scaffold

    try:
        objects = obj.Document.Objects
    except (ReferenceError, RuntimeError):
        return []
    return [o for o in objects if card_scaffold.is_mechanism(o) and getattr(o, "Host", None) is obj]


class CardViewProvider(StatelessProxy):
    """Proxy of the PopUpCard's Gui::ViewProviderPartExt. Keeps no saved state (the object is
    remembered in attach(), which runs again after a file is opened)."""

    ICON = "PopUp_Card"
    # Icons by the card's Validity: the tree marks a checked card, red when it failed.
    VERDICT_ICONS = {"Valid": "PopUp_CardValid", "Invalid": "PopUp_CardInvalid"}

    def __init__(self, vobj):
        vobj.Proxy = self
        self.Object = vobj.Object
        # Paper is seen from both sides: light the back of every patch too.
        if "Lighting" in vobj.PropertiesList:
            vobj.Lighting = "Two side"
        show_by_role(vobj, True)  # opened from a file saved headless: the design is shown

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        verdict = getattr(getattr(self, "Object", None), "Validity", None)
        return popupwb.icon_path(self.VERDICT_ICONS.get(verdict, self.ICON))

    def updateData(self, obj, prop):
        if prop == "Shape":
            from popupwb.viewproviders.patch_colours import colour_after_shape_change

            colour_after_shape_change(obj)
        elif prop == "Validity" and obj.ViewObject is not None:
            obj.ViewObject.signalChangeIcon()

    def onChanged(self, vobj, prop):
        if prop == "Visibility":
            from popupwb.viewproviders.offending_overlay import follow_visibility

            follow_visibility(vobj)

    def doubleClicked(self, vobj):
        import FreeCADGui

        FreeCADGui.ActiveDocument.setEdit(vobj.Object.Name, 0)
        return True

    def setEdit(self, vobj, mode=0):
        if mode != 0:
            return None  # transform and other modes: FreeCAD's own
        import FreeCADGui

        from popupwb.taskpanels.card_panel import CardPanel

        FreeCADGui.Control.showDialog(CardPanel(vobj.Object))
        return True

    def unsetEdit(self, vobj, mode=0):
        if mode != 0:
            return None
        import FreeCADGui

        from popupwb.taskpanels.card_panel import finish_panel_of

        finish_panel_of(vobj.Object)  # its transaction committed, its animation stopped
        FreeCADGui.Control.closeDialog()
        return True

    def claimChildren(self):
        obj = getattr(self, "Object", None)
        return hosted_on(obj) if obj is not None else []
