"""FittedImage: a picture in a task panel as wide as the side pane lets it be (FreeCAD's combo
view is 300-400 px wide; a picture drawn at a fixed width pushed the panel's right side out of
view). It keeps the image at full size and shows it scaled to the label's width, again at every
resize, never wider than the image itself; an animated GIF (set_movie) plays the same way."""

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
        self.movie = None  # the QMovie playing, or None

    def set_png(self, data):
        """Shows the PNG `data` (bytes), scaled to the label's width."""
        self._full = QtGui.QPixmap()
        self._full.loadFromData(data, "PNG")
        self._fit()

    def set_movie(self, path):
        """Plays the animated GIF at `path` in a loop, scaled to the label's width."""
        self.clear()
        self.movie = QtGui.QMovie(path)
        self.movie.jumpToFrame(0)
        self._full = self.movie.currentPixmap()
        self.setMovie(self.movie)
        self._fit()
        self.movie.start()

    def clear(self):
        if self.movie is not None:
            self.movie.stop()
            self.movie = None
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
        height = round(self._full.height() * width / self._full.width())
        if self.movie is not None:
            self.movie.setScaledSize(QtCore.QSize(width, height))
        else:
            self.setPixmap(self._full.scaledToWidth(width, QtCore.Qt.SmoothTransformation))
        self.setMinimumHeight(height)
