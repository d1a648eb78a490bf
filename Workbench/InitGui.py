# PopUp workbench, GUI side. FreeCAD exec's this file (no reliable __file__, names defined here are
# not visible inside methods), so paths come from the `popupwb` package and imports stay local.
import FreeCADGui


class PopUpWorkbench(FreeCADGui.Workbench):
    MenuText = "PopUp"
    ToolTip = (
        "Paper pop-up design: cards with nested mechanisms (tent, step, v-fold, box, v-box), "
        "folded on a slider, checked for validity, laid out on cutting sheets; design files"
    )

    def __init__(self):
        import popupwb

        self.__class__.Icon = popupwb.icon_path("PopUp_Workbench")

    def Initialize(self):
        from popupwb import commands as c

        for name, group in c.GROUPS:
            self.appendToolbar(name, group)
        self.appendMenu(c.MENU, c.CARD_COMMANDS + [c.SEPARATOR])
        self.appendMenu(c.MECHANISM_SUBMENU, c.add_mechanism_commands())
        self.appendMenu(
            c.MENU,
            c.PROFILE_COMMANDS
            + [c.SEPARATOR]
            + c.CHECK_COMMANDS
            + [c.SEPARATOR]
            + c.SHEET_COMMANDS,
        )

    def ContextMenu(self, recipient):
        from popupwb.commands import context_menu

        for submenu, entries in context_menu.entries():
            self.appendContextMenu(submenu, entries)

    def Activated(self):
        return None

    def Deactivated(self):
        return None

    def GetClassName(self):
        return "Gui::PythonWorkbench"


FreeCADGui.addWorkbench(PopUpWorkbench())
import popupwb.gui.preferences_page  # noqa: E402,F401 -- adds Edit › Preferences › PopUp
import popupwb.gui.progress_dialog  # noqa: E402,F401 -- progress.run's dialog with Cancel
import popupwb.viewproviders.patch_colours  # noqa: E402,F401 -- a check's verdict in red faces
