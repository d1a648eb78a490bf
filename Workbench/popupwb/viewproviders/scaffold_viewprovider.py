"""View provider of a Scaffold: its icon, and faces coloured by the role of their patch."""

import popupwb
from popupwb.stateless_proxy import StatelessProxy

# Paper-like tints per patch role (RGB 0..1); the base patches stay closest to white card.
ROLE_COLOURS = {
    "ground": (0.93, 0.91, 0.85),
    "backdrop": (0.88, 0.86, 0.80),
    "support": (0.55, 0.73, 0.90),
    "top": (0.60, 0.83, 0.56),
    "front": (0.96, 0.66, 0.38),
    "back": (0.97, 0.85, 0.45),
    "tab": (0.70, 0.70, 0.70),
    "other": (0.86, 0.60, 0.78),
}


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
            # Python's updateData runs before the C++ one rebuilds the face set, and DiffuseColor
            # only takes when its length matches the face set: colour now (same face count, the
            # usual case) and once more after the rebuild.
            self.colour_faces(obj)
            from PySide import QtCore

            QtCore.QTimer.singleShot(0, lambda: self.colour_faces(obj))

    def onChanged(self, vobj, prop):
        return None

    @staticmethod
    def colour_faces(obj):
        """DiffuseColor per face from the patch roles. The compound holds one child (face or
        thickened solid) per patch, in scaffold order."""
        try:
            vobj = obj.ViewObject
            if vobj is None or obj.Shape.isNull():
                return
        except (ReferenceError, RuntimeError):
            return  # deleted before a deferred call
        from popupwb.features.scaffold_feature import scaffold_of

        try:
            patches = scaffold_of(obj).patches
        except ValueError:
            return  # the feature itself reports a bad design
        children = obj.Shape.childShapes()
        if len(children) != len(patches):
            return
        colours = []
        for child, patch in zip(children, patches):
            colour = ROLE_COLOURS.get(patch.role, ROLE_COLOURS["other"])
            colours.extend([colour + (0.0,)] * len(child.Faces))
        if list(vobj.DiffuseColor) != colours:
            vobj.DiffuseColor = colours
