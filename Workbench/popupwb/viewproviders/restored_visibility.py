"""What a PopUp file saved without the GUI shows when it opens in the GUI.

Files written headless (`make demo`, `popup`, any script) have no GuiDocument.xml, and FreeCAD 0.20
then opens every object hidden. Their PopUp objects get their view providers only then, from
onDocumentRestored (view_provider_by_name.attach_view_provider): exactly the objects that came
without GUI data, and only while the document is restoring. Each view provider sets its visibility
by role at that moment: the card, its mechanisms and Scaffolds shown, a cutting sheet and the
outline helpers its TechDraw pages draw hidden. A file saved in the GUI keeps what its user chose:
its view providers are restored, not made again.
"""


def restoring(vobj):
    """True while the document of `vobj`'s object is being opened."""
    return bool(vobj.Object.Document.Restoring)


def show_by_role(vobj, shown, helpers=()):
    """While the document opens: shows `vobj` or hides it, and hides the `helpers` (document
    objects that only serve it). A new object (made in the GUI) is left as FreeCAD made it."""
    if not restoring(vobj):
        return
    vobj.Visibility = shown
    for helper in helpers:
        if getattr(helper, "ViewObject", None) is not None:
            helper.ViewObject.Visibility = False
