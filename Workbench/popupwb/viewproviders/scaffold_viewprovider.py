"""View provider of a Scaffold: its icon, and faces coloured by the role of their patch. Module and
class names are stored in .FCStd files."""

import popupwb
from popupwb.stateless_proxy import StatelessProxy
from popupwb.viewproviders.restored_visibility import show_by_role


class ScaffoldViewProvider(StatelessProxy):
    """Proxy of the Scaffold's Gui::ViewProviderPartExt. Keeps no state."""

    def __init__(self, vobj):
        vobj.Proxy = self
        show_by_role(vobj, True)  # opened from a file saved headless: the design is shown

    def attach(self, vobj):
        return None

    def getIcon(self):
        return popupwb.icon_path("PopUp_Scaffold")

    def updateData(self, obj, prop):
        if prop == "Shape":
            from popupwb.viewproviders.patch_colours import colour_after_shape_change

            colour_after_shape_change(obj)

    def onChanged(self, vobj, prop):
        if prop == "Visibility":
            from popupwb.viewproviders.offending_overlay import follow_visibility

            follow_visibility(vobj)
