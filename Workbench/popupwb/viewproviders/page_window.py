"""The window of a cutting-sheet page (TechDraw's MDIViewPage): the first time it becomes active,
its view frames go and the whole page is fitted to the window, so a maker sees the sheet as
printed rather than a corner of it in frames. GUI only.

TechDraw opens a page at a fixed zoom with frames and captions around every view (ViewProviderPage
ShowFrames, default on; a document saved headless has no view provider settings at all). The
hook listens to the main window's MDI area; after the first activation the maker's own zoom and
frame toggle (TechDraw_ToggleFrame) stay as they set them.
"""

_FITTED = "popupPageFitted"  # Qt property on the sub-window: already fitted once
_installed = []  # the connected MDI area, kept alive for the session


def install():
    """Connects the hook once per session (the CuttingSheet view provider calls it)."""
    import FreeCADGui
    from PySide import QtGui

    if _installed:
        return
    window = FreeCADGui.getMainWindow()
    area = window.findChild(QtGui.QMdiArea) if window else None
    if area is None:
        return
    area.subWindowActivated.connect(_activated)
    _installed.append(area)


def is_sheet_page(page):
    return page is not None and bool(getattr(page, "CuttingSheet", ""))


def _activated(sub_window):
    from PySide import QtCore

    if sub_window is None or sub_window.property(_FITTED):
        return
    # TechDraw lays the page out after the activation: fit on the next turn of the event loop.
    QtCore.QTimer.singleShot(0, lambda: _fit_active_page(sub_window))


def _fit_active_page(sub_window):
    import FreeCADGui

    from popupwb.sheets.techdraw_pages import hide_frames

    view = FreeCADGui.activeView()
    if not hasattr(view, "getPage"):
        return
    try:
        page = view.getPage()
    except (RuntimeError, ReferenceError):
        return  # closed meanwhile
    if not is_sheet_page(page):
        return
    hide_frames(page)
    view.fitAll()
    sub_window.setProperty(_FITTED, True)
