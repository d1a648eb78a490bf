"""Edit › Preferences › PopUp: the page that edits popupwb/preferences.py's parameters.

FreeCAD builds the page (PreferencesPage(), its `form` widget) each time the dialog opens, calls
loadSettings() to fill it and saveSettings() on OK or Apply. A value equal to the built-in default
is removed rather than stored, so the default can change with PopUp. A value PopUp cannot use (an
unknown paper, an empty or repeated layer name) is not stored: the report view says why, in one
line naming the preference, and the stored value stays.
"""

import FreeCAD
import FreeCADGui
from PySide import QtGui

from popupwb import preferences

PAGE_NAME = "PopUpPreferences"  # the form's objectName: the tests find the page by it
AUTOMATIC = "Automatic"  # SheetPaper "" in the paper box
PAPER_CHOICES = (AUTOMATIC, "A4", "A3", "Letter", "Tabloid")
RANGES = {  # (minimum, maximum, decimals, step, suffix): the core's ranges (sheet_layout.cpp)
    "PaperThickness": (0.0, 5.0, 3, 0.05, " mm"),
    "Kerf": (0.0, 2.0, 3, 0.05, " mm"),
    "TabWidth": (0.1, 50.0, 2, 0.5, " mm"),
    "TabAngle": (1.0, 90.0, 1, 5.0, " °"),
}


class ColourButton(QtGui.QPushButton):
    """A button showing a colour; clicking it opens the colour dialog."""

    def __init__(self, parent=None):
        super().__init__(parent)
        self.rgb = (0, 0, 0)
        self.setMinimumWidth(60)
        self.clicked.connect(self._choose)

    def set_rgb(self, rgb):
        self.rgb = tuple(int(channel) for channel in rgb)
        self.setStyleSheet("background-color: #{:02x}{:02x}{:02x}".format(*self.rgb))

    def _choose(self):
        colour = QtGui.QColorDialog.getColor(QtGui.QColor(*self.rgb), self, "Line colour")
        if colour.isValid():
            self.set_rgb((colour.red(), colour.green(), colour.blue()))


class PreferencesPage:
    def __init__(self, parent=None):
        self.form = QtGui.QWidget(parent)
        self.form.setObjectName(PAGE_NAME)
        self.form.setWindowTitle("PopUp")  # the page's tab in the PopUp group
        self.fields = {}
        layout = QtGui.QVBoxLayout(self.form)
        layout.addWidget(self._card_box())
        layout.addWidget(self._sheet_box())
        layout.addWidget(self._layer_box())
        layout.addWidget(self._folder_box())
        layout.addStretch()

    # --- the widgets -------------------------------------------------------------------------

    def _field(self, key, widget):
        widget.setObjectName(key)
        widget.setToolTip(preferences.BY_KEY[key].doc)
        self.fields[key] = widget
        return widget

    def _spin(self, key):
        low, high, decimals, step, suffix = RANGES[key]
        spin = QtGui.QDoubleSpinBox()
        spin.setRange(low, high)
        spin.setDecimals(decimals)
        spin.setSingleStep(step)
        spin.setSuffix(suffix)
        return self._field(key, spin)

    def _card_box(self):
        from popupwb.features.card_feature import PRESETS

        box = QtGui.QGroupBox("New cards")
        form = QtGui.QFormLayout(box)
        preset = self._field("CardPreset", QtGui.QComboBox())
        preset.addItems(list(PRESETS))
        form.addRow("Size", preset)
        form.addRow("Paper thickness", self._spin("PaperThickness"))
        return box

    def _sheet_box(self):
        box = QtGui.QGroupBox("Cutting sheets")
        form = QtGui.QFormLayout(box)
        paper = self._field("SheetPaper", QtGui.QComboBox())
        paper.setEditable(True)  # or WxH in mm
        paper.addItems(list(PAPER_CHOICES))
        form.addRow("Paper", paper)
        form.addRow("Kerf", self._spin("Kerf"))
        form.addRow("Tab width", self._spin("TabWidth"))
        form.addRow("Tab angle", self._spin("TabAngle"))
        return box

    def _layer_box(self):
        box = QtGui.QGroupBox("Layers (DXF layers, SVG layers, line colours)")
        grid = QtGui.QGridLayout(box)
        for row, layer in enumerate(preferences.LAYERS):
            grid.addWidget(QtGui.QLabel(layer.capitalize()), row, 0)
            grid.addWidget(self._field(f"{layer.capitalize()}LayerName", QtGui.QLineEdit()), row, 1)
            grid.addWidget(self._field(f"{layer.capitalize()}LayerColour", ColourButton()), row, 2)
        return box

    def _folder_box(self):
        box = QtGui.QGroupBox("Export")
        row = QtGui.QHBoxLayout(box)
        row.addWidget(QtGui.QLabel("Folder"))
        folder = self._field("ExportFolder", QtGui.QLineEdit())
        folder.setPlaceholderText("ask every time")
        row.addWidget(folder)
        browse = QtGui.QPushButton("…")
        browse.clicked.connect(self._browse)
        row.addWidget(browse)
        return box

    def _browse(self):
        folder = QtGui.QFileDialog.getExistingDirectory(
            self.form, "Export folder", self.fields["ExportFolder"].text()
        )
        if folder:
            self.fields["ExportFolder"].setText(folder)

    # --- FreeCAD's calls ---------------------------------------------------------------------

    def loadSettings(self):
        values = preferences.built_in()
        values.update(preferences.stored(preferences.parameter_group()))
        for key, value in values.items():
            self.set_value(key, value)

    def saveSettings(self):
        built_in = preferences.built_in()
        changes = {}
        for key in self.fields:
            value = self.value(key)
            if value == built_in[key]:
                changes[key] = None
                continue
            try:  # alone: an unusable value is reported and not stored
                preferences.from_values({key: value}, preferences.config_path())
            except preferences.PreferenceError as error:
                FreeCAD.Console.PrintError(f"{error}; not saved\n")
                continue
            changes[key] = value
        group = preferences.parameter_group()
        preferences.write(group, changes)
        FreeCAD.saveParameter()  # now, so `popup` run beside the GUI sees it
        try:  # together: layer names that repeat, a kerf too wide for the spacing
            preferences.read(group)
        except preferences.PreferenceError as error:
            FreeCAD.Console.PrintError(f"{error}\n")

    # --- one field's value, as preferences.py has it -----------------------------------------

    def value(self, key):
        widget = self.fields[key]
        if isinstance(widget, ColourButton):
            return widget.rgb
        if isinstance(widget, QtGui.QDoubleSpinBox):
            return widget.value()
        if isinstance(widget, QtGui.QComboBox):
            text = widget.currentText().strip()
            return "" if key == "SheetPaper" and text == AUTOMATIC else text
        return widget.text().strip()

    def set_value(self, key, value):
        widget = self.fields[key]
        if isinstance(widget, ColourButton):
            widget.set_rgb(value)
        elif isinstance(widget, QtGui.QDoubleSpinBox):
            widget.setValue(float(value))
        elif isinstance(widget, QtGui.QComboBox):
            text = value or AUTOMATIC
            index = widget.findText(text)
            if index >= 0:
                widget.setCurrentIndex(index)
            elif widget.isEditable():  # a paper given as WxH
                widget.setEditText(text)
        else:
            widget.setText(str(value))


def _register():
    import popupwb

    # The dialog's list shows the group with the icon named "preferences-<group>".
    with open(popupwb.icon_path("PopUp_Workbench"), "rb") as icon:
        FreeCADGui.addIcon("preferences-popup", icon.read().decode("utf-8"), "SVG")
    FreeCADGui.addPreferencePage(PreferencesPage, "PopUp")


_register()
