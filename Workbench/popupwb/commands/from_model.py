"""PopUp_FromModel: a pop-up card designed from the selected mesh or Part shape (issue 12), through
FromModelPanel (taskpanels/from_model_panel.py): alignment, maximum mechanisms, detail and seed,
a fit with progress and Cancel, the fitted prisms over the model, then OK builds the card.

With no mesh or Part shape in the document, the command asks for a model file (STL, OBJ, PLY,
glTF, ...): popupcore.load_model reads it (assimp in a child process, so a file that crashes it
cannot take FreeCAD along), it is added as a mesh, and the card remembers the file for the
artwork of its cutting sheets."""

import FreeCAD
import FreeCADGui

import popupwb
from popupwb import preferences
from popupwb.commands.selection import SelectionError, selected_model, selected_objects

COMMAND_ID = "PopUp_FromModel"


class FromModelCommand:
    def GetResources(self):
        return {
            "Pixmap": popupwb.icon_path(COMMAND_ID),
            "MenuText": "Pop-up from model",
            "ToolTip": "Design a pop-up card from the selected mesh or Part shape: prisms fitted "
            "to the model become box, step, v- and tent folds you can keep editing",
        }

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None and FreeCADGui.Control.activeDialog() is False

    def Activated(self):
        from popupwb.model.model_source import top_level_models

        doc = FreeCAD.ActiveDocument
        selected = selected_objects(doc)
        if not selected and not top_level_models(doc):
            path = ask_model_file()
            if path:
                open_panel(path=path)
            return
        open_panel()


MODEL_FILES = "Models (*.stl *.obj *.ply *.off *.gltf *.glb *.fbx *.dae *.3mf);;All files (*)"


def ask_model_file():
    from PySide import QtGui

    path, _ = QtGui.QFileDialog.getOpenFileName(
        FreeCADGui.getMainWindow(), "Pop-up from a model file", "", MODEL_FILES
    )
    return path or None


def card_size():
    """(width, depth) of the maker's new-card preset, or None for a custom one (the core's)."""
    from popupwb.features.card_feature import PRESETS

    return PRESETS.get(preferences.read_or_built_in(COMMAND_ID).card_preset)


def open_panel(obj=None, path=None):
    """Opens the panel on `obj` (default: the selected or only mesh or shape), or on the model
    file `path` (read with popupcore.load_model and added to the document as a mesh); returns
    it, or None with the reason in the report view."""
    from popupwb.taskpanels.from_model_panel import FromModelPanel

    model = None
    try:
        if path is not None:
            obj, model = add_model_file(FreeCAD.ActiveDocument, path)
        obj = obj or selected_model(FreeCAD.ActiveDocument)
    except (SelectionError, ValueError, RuntimeError, OSError) as error:
        FreeCAD.Console.PrintError(f"{COMMAND_ID}: {error}\n")
        return None
    panel = FromModelPanel(obj, card_size(), model=model, source_file=path)
    FreeCADGui.Control.showDialog(panel)
    return panel


def add_model_file(doc, path):
    """(Mesh::Feature, popupcore.ModelMesh) of the model file `path`, read by
    popupcore.load_model and added to `doc` (a new one when none is open) in one undo step;
    ValueError (DesignError) naming the file when it cannot be read."""
    import os

    from popupwb.core import popupcore
    from popupwb.model.model_source import add_source_model

    model = popupcore.load_model(path)
    if doc is None:
        doc = FreeCAD.newDocument()
    doc.openTransaction(f"Import {os.path.basename(path)}")
    identity = [[1.0 if i == j else 0.0 for j in range(4)] for i in range(4)]
    obj = add_source_model(doc, model, identity, name="Model")
    doc.commitTransaction()
    doc.recompute()
    return obj, model


FreeCADGui.addCommand(COMMAND_ID, FromModelCommand())
