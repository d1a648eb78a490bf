"""The window of a cutting-sheet page (TechDraw's MDIViewPage): when it opens, its view frames go
and the whole page is fitted to the window, so a maker sees the sheet as printed rather than a
corner of it in frames. GUI only.

TechDraw opens a page at a fixed zoom with frames and captions around every view
(ViewProviderPage ShowFrames, default on; a document saved headless has no view provider settings
at all). A page window does not always become the active sub-window when it opens (under Xvfb it
does not), and TechDraw sets its zoom after the window is added. So the hook watches sub-windows
being added to the main window's MDI area, and on the first paint of a page window fits it
through its MDIViewPagePy (fitAll). A window resized later (maximized late) is fitted again until
the maker zooms; from then on their zoom and frame toggle (TechDraw_ToggleFrame) stay as they set
them. A page closed and opened again is fitted again.
"""

_ZOOM = "popupPageZoom"  # Qt property of a page's QGraphicsView: the zoom it was fitted to
_WATCHED = "popupPageWatched"  # Qt property: the page's QGraphicsView has the filter
_hooks = []  # the event filters, kept alive for the session


def install():
    """Installs the hook once per session (the CuttingSheet view provider calls it)."""
    import FreeCADGui
    from PySide import QtCore, QtGui

    if _hooks:
        return
    window = FreeCADGui.getMainWindow()
    area = window.findChild(QtGui.QMdiArea) if window else None
    if area is None:
        return

    class NewWindows(QtCore.QObject):
        def eventFilter(self, watched, event):
            if event.type() == QtCore.QEvent.ChildAdded:
                # The window's page view is built after the window is added.
                QtCore.QTimer.singleShot(0, watch_page_windows)
            return False

    class PageView(QtCore.QObject):
        """On a page's QGraphicsView and its viewport: fit at first paint and on resizes."""

        def eventFilter(self, watched, event):
            kind = event.type()
            if kind in (QtCore.QEvent.Paint, QtCore.QEvent.Resize):
                graphics = watched
                if not isinstance(watched, QtGui.QGraphicsView):  # its viewport
                    graphics = _graphics_named(watched.parentWidget().objectName())
                if graphics is None:
                    return False
                zoom = graphics.property(_ZOOM)
                unzoomed = zoom is not None and abs(graphics.transform().m11() - zoom) < 1e-9
                if zoom is None and kind == QtCore.QEvent.Paint:
                    graphics.setProperty(_ZOOM, -1.0)  # fit pending
                    QtCore.QTimer.singleShot(0, lambda: _fit(graphics))
                elif unzoomed and kind == QtCore.QEvent.Resize:
                    QtCore.QTimer.singleShot(0, lambda: _fit(graphics))
            return False

    new_windows, page_view = NewWindows(area), PageView(area)
    area.viewport().installEventFilter(new_windows)
    _hooks.extend([new_windows, page_view])
    watch_page_windows()


def is_sheet_page(page):
    return page is not None and bool(getattr(page, "CuttingSheet", ""))


def _page_views():
    """{page Name: (page, MDIViewPagePy)} of the open cutting-sheet page windows."""
    import FreeCAD
    import FreeCADGui

    views = {}
    for name in FreeCAD.listDocuments():
        gui_doc = FreeCADGui.getDocument(name)
        # MDIViewPage has no type of its own to ask for: every view, the pages' by getPage.
        for view in gui_doc.mdiViewsOfType("Gui::MDIView") if gui_doc else []:
            if not hasattr(view, "getPage"):
                continue
            try:
                page = view.getPage()
            except (RuntimeError, ReferenceError):
                continue  # closed meanwhile
            if is_sheet_page(page):
                views[page.Name] = (page, view)
    return views


def watch_page_windows():
    """Puts the fit filter on every open cutting-sheet page window that lacks it."""
    import FreeCADGui
    from PySide import QtGui

    if not _hooks:
        return
    area = FreeCADGui.getMainWindow().findChild(QtGui.QMdiArea)
    pages = _page_views()
    for graphics in area.findChildren(QtGui.QGraphicsView):
        # TechDraw names a page's QGraphicsView after the page.
        if graphics.objectName() in pages and not graphics.property(_WATCHED):
            graphics.setProperty(_WATCHED, True)
            graphics.installEventFilter(_hooks[1])
            graphics.viewport().installEventFilter(_hooks[1])
            graphics.viewport().update()


def _graphics_named(name):
    import FreeCADGui
    from PySide import QtGui

    area = FreeCADGui.getMainWindow().findChild(QtGui.QMdiArea)
    return area.findChild(QtGui.QGraphicsView, name) if name else None


def _fit(graphics):
    import FreeCADGui

    from popupwb.sheets.techdraw_pages import hide_frames

    try:
        found = _page_views().get(graphics.objectName())
    except RuntimeError:
        return  # the window closed meanwhile
    if found is None:
        return
    page, view = found
    active = FreeCADGui.activeView()
    if getattr(page.ViewObject, "ShowFrames", False) and getattr(active, "getPage", None):
        shown = active.getPage()
        if (shown.Document.Name, shown.Name) == (page.Document.Name, page.Name):
            # TechDraw's own toggle also redraws the views and hides the template's edit markers;
            # the property alone leaves the frames drawn until the page is reopened.
            FreeCADGui.runCommand("TechDraw_ToggleFrame")
    hide_frames(page)
    view.fitAll()
    graphics.setProperty(_ZOOM, graphics.transform().m11())
