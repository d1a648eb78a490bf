"""A coin node a task panel draws into a document's 3D view, and takes out again (GUI only)."""

import FreeCADGui


def view_root(doc_name):
    """The scene graph of the document's active 3D view, or None (no GUI view)."""
    gui_doc = FreeCADGui.getDocument(doc_name)
    view = gui_doc.ActiveView if gui_doc is not None else None
    if view is None or not hasattr(view, "getSceneGraph"):
        return None
    return view.getSceneGraph()


def detach(node, doc_name):
    """Takes `node` out of the document's view, if it is still there."""
    if node is None:
        return
    try:
        root = view_root(doc_name)
    except (RuntimeError, ReferenceError):  # the document is closing or gone
        root = None
    if root is not None and root.findChild(node) >= 0:
        root.removeChild(node)
