"""View provider of a CuttingSheet: its icon, its TechDraw pages (and the outlines they draw) as
children in the tree, and deleting them with it; its pages' windows open fitted and without view
frames (page_window.py). Module and class names are stored in .FCStd files."""

import popupwb
from popupwb.stateless_proxy import StatelessProxy
from popupwb.viewproviders import page_window
from popupwb.viewproviders.restored_visibility import show_by_role


class CuttingSheetViewProvider(StatelessProxy):
    """Proxy of the CuttingSheet's Gui::ViewProviderPartExt. Keeps no saved state."""

    ICON = "PopUp_CuttingSheet"

    def __init__(self, vobj):
        vobj.Proxy = self
        self.Object = vobj.Object
        page_window.install()
        # Opened from a file saved headless: the sheets and their outline helpers stay hidden.
        show_by_role(vobj, False, self._outlines(vobj.Object))

    def attach(self, vobj):
        self.Object = vobj.Object
        page_window.install()

    def getIcon(self):
        return popupwb.icon_path(self.ICON)

    def updateData(self, obj, prop):
        return None

    def onChanged(self, vobj, prop):
        return None

    def claimChildren(self):
        from popupwb.sheets.techdraw_pages import pages_of

        obj = getattr(self, "Object", None)
        if obj is None:
            return []
        children = []
        for page in pages_of(obj):
            children.append(page)
            children.extend(self._outlines(obj, [page]))
        return children

    @staticmethod
    def _outlines(obj, pages=None):
        """The Part::Feature outlines the sheet's TechDraw pages draw (3D helpers)."""
        from popupwb.sheets.techdraw_pages import page_objects, pages_of

        pages = pages_of(obj) if pages is None else pages
        return [o for page in pages for o in page_objects(page) if o.TypeId == "Part::Feature"]

    def onDelete(self, vobj, subelements):
        # FreeCAD 0.20 calls no unsetupObject of Python features: the pages go here.
        from popupwb.sheets.techdraw_pages import remove_pages

        remove_pages(vobj.Object)
        return True
