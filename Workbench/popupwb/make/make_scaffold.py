"""make_scaffold: a Scaffold object from a design file, headless or in the GUI."""

import os

import FreeCAD

from popupwb.features.scaffold_feature import ScaffoldFeature, load_design
from popupwb.view_provider_by_name import view_provider_class


def make_scaffold(doc, design_file, fold_angle=180.0, name="Scaffold"):
    """Adds a Scaffold showing `design_file` (JSON) at `fold_angle` degrees to `doc`.

    PaperThickness starts at the design's value. The caller recomputes. A file that exists but is
    not a valid design still gives an object: its recompute fails with a message naming the file.
    """
    path = os.path.abspath(design_file)
    if not os.path.isfile(path):
        raise FileNotFoundError(f"make_scaffold: design file '{path}' does not exist")
    obj = doc.addObject("Part::FeaturePython", name)
    ScaffoldFeature(obj)
    obj.DesignFile = path
    obj.FoldAngle = fold_angle
    try:
        obj.PaperThickness = load_design(path).paper_thickness
    except (OSError, ValueError):
        pass  # execute() puts the object in error with the reason
    if FreeCAD.GuiUp:
        view_provider_class(obj.Proxy)(obj.ViewObject)
    return obj
