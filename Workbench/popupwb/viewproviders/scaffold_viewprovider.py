"""View provider of a Scaffold: its icon, and faces coloured by the role of their patch. Module and
class names are stored in .FCStd files."""

import popupwb
from popupwb.stateless_proxy import StatelessProxy


class ScaffoldViewProvider(StatelessProxy):
    """Proxy of the Scaffold's Gui::ViewProviderPartExt. Keeps no state."""

    def __init__(self, vobj):
        vobj.Proxy = self

    def attach(self, vobj):
        return None

    def getIcon(self):
        return popupwb.icon_path("PopUp_Scaffold")

    def updateData(self, obj, prop):
        if prop == "Shape":
            from popupwb.viewproviders.patch_colours import colour_after_shape_change

            colour_after_shape_change(obj)

    def onChanged(self, vobj, prop):
        return None
