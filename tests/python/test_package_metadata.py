"""package.xml, FreeCAD's package metadata (https://wiki.freecad.org/Package_Metadata): a real
maintainer entry and the dependencies, checked against what the workbench's code imports."""

import ast
import os
import sys
import xml.etree.ElementTree as ET

from conftest import SOURCE_DIR, WORKBENCH_DIR

NAMESPACE = {"p": "https://wiki.freecad.org/Package_Metadata"}
# Modules FreeCAD itself provides (the workbenches and its Qt binding), and this project's own.
# pivy is the Coin binding FreeCAD ships with (its 3D view is a Coin scene graph).
FREECAD_MODULES = {
    "FreeCAD",
    "FreeCADGui",
    "Mesh",
    "Part",
    "PySide",
    "TechDraw",
    "TechDrawGui",
    "pivy",
}
# Import names of modules shipped by another dependency: mpl_toolkits comes with matplotlib.
DISTRIBUTION_OF = {"mpl_toolkits": "matplotlib"}
OWN_MODULES = {"popupwb", "popupcore"}


def package():
    return ET.parse(os.path.join(SOURCE_DIR, "package.xml")).getroot()


def depends(kind):
    return {
        d.text.strip() for d in package().findall("p:depend", NAMESPACE) if d.get("type") == kind
    }


def imported_modules():
    """Top-level modules imported anywhere in Workbench/, read from the syntax trees."""
    modules = set()
    for folder, _, files in os.walk(WORKBENCH_DIR):
        for name in files:
            if name.endswith(".py"):
                with open(os.path.join(folder, name), encoding="utf-8") as f:
                    tree = ast.parse(f.read())
                for node in ast.walk(tree):
                    if isinstance(node, ast.Import):
                        modules.update(alias.name.split(".")[0] for alias in node.names)
                    elif isinstance(node, ast.ImportFrom) and node.level == 0:
                        modules.add(node.module.split(".")[0])
    return modules


def test_the_maintainer_is_not_a_placeholder():
    (maintainer,) = package().findall("p:maintainer", NAMESPACE)
    assert maintainer.text.strip() == "PopUp developers"
    email = maintainer.get("email")
    assert email and "example.org" not in email and "@" in email


def test_the_workbenches_it_builds_on_are_dependencies():
    assert depends("internal") == {"Part", "TechDraw", "Mesh"}
    sources = []
    for folder, _, files in os.walk(WORKBENCH_DIR):
        for name in files:
            if name.endswith(".py"):
                with open(os.path.join(folder, name), encoding="utf-8") as f:
                    sources.append(f.read())
    assert any("import Part" in text for text in sources)
    assert any('"TechDraw::DrawPage"' in text for text in sources)


def test_every_third_party_import_is_a_python_dependency():
    imported = imported_modules() - set(sys.stdlib_module_names) - FREECAD_MODULES - OWN_MODULES
    third_party = {DISTRIBUTION_OF.get(name, name) for name in imported}
    assert (
        depends("python")
        == third_party
        == {"ezdxf", "svgwrite", "reportlab", "matplotlib", "numpy", "PIL"}
    )


def test_freecad_reads_the_same_metadata(freecad):
    metadata = freecad.Metadata(os.path.join(SOURCE_DIR, "package.xml"))
    assert metadata.Maintainer == [{"name": "PopUp developers", "email": "no-one@freecad.org"}]
    assert [d["package"] for d in metadata.Depend] == [
        "Part",
        "TechDraw",
        "Mesh",
        "ezdxf",
        "svgwrite",
        "reportlab",
        "matplotlib",
        "numpy",
        "PIL",
    ]


def test_the_addon_fields_freecad_checks_are_there(freecad):
    root = package()
    assert root.find("p:date", NAMESPACE).text == "2026-11-28"
    assert root.find("p:pythonmin", NAMESPACE).text == "3.11"
    icon = os.path.join(SOURCE_DIR, root.find("p:icon", NAMESPACE).text)
    assert os.path.getsize(icon) < 10 * 1024  # the Addon Manager's limit for a package icon
    metadata = freecad.Metadata(os.path.join(SOURCE_DIR, "package.xml"))
    assert metadata.FreeCADMin.split(".")[:2] == ["0", "20"]
    assert metadata.supportsCurrentFreeCAD()
    (workbench,) = metadata.Content["workbench"]
    assert workbench.Subdirectory == "Workbench" and workbench.Classname == "PopUpWorkbench"
