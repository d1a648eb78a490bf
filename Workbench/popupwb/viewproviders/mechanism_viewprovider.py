"""View provider of the mechanism features: icon per kind, faces coloured by patch role, the
mechanisms nested on it as tree children, and the parameter task panel on double click (setEdit).
Module and class names are stored in .FCStd files."""

import popupwb
from popupwb.viewproviders.card_viewprovider import CardViewProvider

# Icon (= creating command id) per feature TYPE.
ICONS = {
    "PopUp::TentFold": "PopUp_TentFold",
    "PopUp::StepFold": "PopUp_StepFold",
    "PopUp::VFold": "PopUp_VFold",
    "PopUp::BoxFold": "PopUp_BoxFold",
    "PopUp::VBoxFold": "PopUp_VBoxFold",
    "PopUp::RotationArm": "PopUp_RotationArm",
    "PopUp::VerticalTranslation": "PopUp_VerticalTranslation",
    "PopUp::HorizontalTranslation": "PopUp_HorizontalTranslation",
    "PopUp::FloatingLayer": "PopUp_FloatingLayer",
}


class MechanismViewProvider(CardViewProvider):
    """Proxy of a mechanism's Gui::ViewProviderPartExt. Keeps no saved state."""

    def getIcon(self):
        obj = getattr(self, "Object", None)
        kind = getattr(getattr(obj, "Proxy", None), "TYPE", None)
        return popupwb.icon_path(ICONS.get(kind, "PopUp_Card"))

    def doubleClicked(self, vobj):
        import FreeCADGui

        FreeCADGui.ActiveDocument.setEdit(vobj.Object.Name, 0)
        return True

    def setEdit(self, vobj, mode=0):
        if mode != 0:
            return None  # transform and other modes: FreeCAD's own
        import FreeCADGui

        from popupwb.taskpanels.mechanism_panel import MechanismPanel

        FreeCADGui.Control.showDialog(MechanismPanel(vobj.Object))
        return True

    def unsetEdit(self, vobj, mode=0):
        if mode != 0:
            return None
        import FreeCADGui

        FreeCADGui.Control.closeDialog()
        return True
