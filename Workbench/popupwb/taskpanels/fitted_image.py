"""FittedImage: a picture in a task panel as wide as the side pane lets it be (FreeCAD's combo
view is 300-400 px wide; a picture drawn at a fixed width pushed the panel's right side out of
view). It keeps the image at full size and shows it scaled to the label's width, again at every
resize, never wider than the image itself."""

from PySide import QtCore, QtGui


class FittedImage(QtGui.QLabel):
    def __init__(self, name, tip=""):
        super().__init__()
        self.setObjectName(name)
        self.setAlignment(QtCore.Qt.AlignCenter)
        self.setToolTip(tip)
        # Ignored: the label takes the width the panel gives it and asks for none of its own.
        self.setSizePolicy(QtGui.QSizePolicy.Ignored, QtGui.QSizePolicy.Preferred)
        self.setMinimumWidth(1)
        self._full = None

    def set_png(self, data):
        """Shows the PNG `data` (bytes), scaled to the label's width."""
        self._full = QtGui.QPixmap()
        self._full.loadFromData(data, "PNG")
        self._fit()

    def clear(self):
        self._full = None
        super().clear()

    def full_size(self):
        """(width, height) of the image shown, before scaling; (0, 0) without one."""
        return (self._full.width(), self._full.height()) if self._full else (0, 0)

    def resizeEvent(self, event):
        super().resizeEvent(event)
        self._fit()

    def _fit(self):
        if self._full is None or self._full.isNull():
            return
        width = max(1, min(self.width(), self._full.width()))
        scaled = self._full.scaledToWidth(width, QtCore.Qt.SmoothTransformation)
        self.setPixmap(scaled)
        self.setMinimumHeight(scaled.height())
