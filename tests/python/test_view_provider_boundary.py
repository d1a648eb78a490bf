"""Features and view providers: features name their view provider by module and class and never
import GUI code; one module writes face colours."""

import ast
import os

from conftest import WORKBENCH_DIR

PACKAGE_DIR = os.path.join(WORKBENCH_DIR, "popupwb")


def python_files(folder):
    for root, _, names in os.walk(folder):
        for name in sorted(names):
            if name.endswith(".py"):
                yield os.path.join(root, name)


def imported_modules(path):
    """Every module `path` imports, at module level or inside functions."""
    with open(path, encoding="utf-8") as f:
        tree = ast.parse(f.read(), path)
    names = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.extend(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            names.append(base)
            names.extend(f"{base}.{alias.name}" for alias in node.names)
    return names


def test_features_never_import_view_providers():
    features = list(python_files(os.path.join(PACKAGE_DIR, "features")))
    assert len(features) >= 14  # the card, scaffold, cutting sheet, base classes and 9 mechanisms
    offenders = {
        os.path.basename(path): [m for m in imported_modules(path) if "viewproviders" in m]
        for path in features
    }
    assert {name: found for name, found in offenders.items() if found} == {}


def test_only_patch_colours_writes_face_colours():
    writers = set()
    for path in python_files(PACKAGE_DIR):
        with open(path, encoding="utf-8") as f:
            tree = ast.parse(f.read(), path)
        for node in ast.walk(tree):
            targets = node.targets if isinstance(node, ast.Assign) else []
            for target in targets:
                if isinstance(target, ast.Attribute) and target.attr in (
                    "DiffuseColor",
                    "ShapeColor",
                ):
                    writers.add(os.path.relpath(path, PACKAGE_DIR))
    assert writers == {os.path.join("viewproviders", "patch_colours.py")}


def feature_classes():
    """Every proxy class of a document object the features package defines (TYPE set)."""
    import importlib
    import pkgutil

    import popupwb.features

    classes = []
    for info in pkgutil.iter_modules(popupwb.features.__path__):
        module = importlib.import_module(f"popupwb.features.{info.name}")
        classes.extend(
            value
            for value in vars(module).values()
            if isinstance(value, type)
            and value.__module__ == module.__name__
            and getattr(value, "TYPE", None)
        )
    return classes


def test_every_feature_names_a_view_provider_class(freecad):
    from popupwb.view_provider_by_name import view_provider_class

    named = {cls.__name__: view_provider_class(cls) for cls in feature_classes()}
    assert len(named) == 12
    for feature, view_provider in named.items():
        assert view_provider.__module__.startswith("popupwb.viewproviders."), feature
        assert callable(getattr(view_provider, "getIcon")), feature
    # The names documents saved from the GUI store (tests/data/legacy_card_gui.FCStd).
    assert named["PopUpCard"].__name__ == "CardViewProvider"
    assert named["TentFold"].__module__ == "popupwb.viewproviders.mechanism_viewprovider"
    assert named["CuttingSheet"].__name__ == "CuttingSheetViewProvider"


HEADLESS_LIFECYCLE = r"""
import json, os, sys, tempfile
from popupwb import make
doc = FreeCAD.newDocument("Boundary")
card = make.make_card(doc, preset="A5")
make.make_box_fold(card)
make.make_scaffold(doc, %(design)r)
make.make_cutting_sheet(card, paper="A4", make_pages=False)
doc.recompute()
path = os.path.join(tempfile.mkdtemp(), "boundary.FCStd")
doc.saveAs(path)
FreeCAD.closeDocument(doc.Name)
doc = FreeCAD.openDocument(path)
doc.getObject("Card").FoldAngle = 90
doc.recompute()
print(json.dumps({
    "states": sorted(set(s for o in doc.Objects for s in o.State)),
    "proxies": sorted(type(o.Proxy).__name__ for o in doc.Objects),
    "gui_modules": sorted(m for m in sys.modules if m.startswith("popupwb.viewproviders")),
}))
"""


def test_headless_documents_never_load_view_providers(run_fresh_freecad, data_dir):
    design = os.path.join(data_dir, "tent_fold.json")
    out = run_fresh_freecad(HEADLESS_LIFECYCLE % {"design": design})
    assert out["states"] == ["Up-to-date"]
    assert out["proxies"] == ["BoxFold", "CuttingSheet", "PopUpCard", "ScaffoldFeature"]
    assert out["gui_modules"] == []
