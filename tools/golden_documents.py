#!/usr/bin/python3
"""Saved documents across FreeCAD versions (README "Platforms"): golden .FCStd files written by
one FreeCAD, opened and recomputed by the others.

    golden_documents.py write --demo out/demo --out tests/data/golden
        copies the three documents `make demo` wrote with the FreeCAD running here (a card of
        mechanism features, a design fitted to a model, an animated design) into
        <out>/freecad-<version>/ with figures.json: what this FreeCAD reads from each file;
    golden_documents.py figures FILE.FCStd
        prints (JSON) what the FreeCAD running here reads from FILE as saved, and after every
        object is recomputed: per object its type, proxy, PopUp properties and shape figures.

Run with FreeCAD's interpreter (/usr/bin/python3) and the workbench and core on PYTHONPATH, as
the tests do. tests/python/test_golden_documents.py compares every version's files with the
figures their writer recorded.
"""

import argparse
import json
import math
import os
import shutil
import sys

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.append(os.path.join(REPO, "Workbench"))
from popupwb import freecad_version  # noqa: E402  (importable before FreeCAD)

sys.path.append(freecad_version.freecad_lib_dir())

# demo output -> golden name
DEMO_DOCUMENTS = {
    "card.FCStd": "card.FCStd",
    "fit/design.FCStd": "fitted.FCStd",
    "animate/design.FCStd": "animated.FCStd",
}
# Property types compared: the design's own numbers and words. Links, files, shapes and
# placements are compared through the shape figures; FreeCAD's bookkeeping is left out.
VALUE_TYPES = (
    "App::PropertyFloat", "App::PropertyLength", "App::PropertyDistance", "App::PropertyAngle",
    "App::PropertyInteger", "App::PropertyBool", "App::PropertyString",
    "App::PropertyEnumeration", "App::PropertyPercent", "App::PropertyFloatConstraint",
    "App::PropertyIntegerConstraint", "App::PropertyStringList", "App::PropertyFloatList",
)  # fmt: skip
DIGITS = 9  # significant digits kept: far below paper, above OCCT's rounding between versions


def rounded(value):
    if hasattr(value, "Value") and hasattr(value, "Unit"):  # a Quantity (length, angle)
        value = float(value.Value)
    if isinstance(value, float):
        return float(f"{value:.{DIGITS}g}") if math.isfinite(value) else str(value)
    if isinstance(value, (list, tuple)):
        return [rounded(v) for v in value]
    return value


def plain_properties():
    """What every Python feature has (FreeCAD's own): left out of the comparison."""
    import FreeCAD

    doc = FreeCAD.newDocument("PlainProbe")
    names = set(doc.addObject("Part::FeaturePython", "Plain").PropertiesList)
    names |= set(doc.addObject("App::FeaturePython", "PlainApp").PropertiesList)
    FreeCAD.closeDocument(doc.Name)
    return names


def shape_figures(shape):
    box = shape.BoundBox
    return {
        "valid": shape.isValid(),
        "faces": len(shape.Faces),
        "edges": len(shape.Edges),
        "area": rounded(shape.Area),
        "bound_box": rounded([box.XMin, box.YMin, box.ZMin, box.XMax, box.YMax, box.ZMax]),
    }


def object_figures(obj, plain):
    proxy = getattr(obj, "Proxy", None)
    figures = {
        "type": obj.TypeId,
        "proxy": f"{type(proxy).__module__}.{type(proxy).__name__}" if proxy else None,
        "properties": {},
    }
    for name in sorted(set(obj.PropertiesList) - plain):
        if obj.getTypeIdOfProperty(name) in VALUE_TYPES:
            figures["properties"][name] = rounded(getattr(obj, name))
    shape = getattr(obj, "Shape", None)
    if shape is not None and not shape.isNull():
        figures["shape"] = shape_figures(shape)
    return figures


def recheck(doc):
    """Re-runs the validity check of every card that was checked when saved: a recompute marks
    a changed card NotChecked, and the verdict is part of what must come out the same."""
    from popupwb.validity.check import run_check

    for obj in doc.Objects:
        if obj.TypeId == "Part::FeaturePython" and hasattr(obj, "Validity"):
            run_check(obj)


def document_figures(path):
    """{"saved": figures as read, "recomputed": after every object is recomputed and every card
    checked again, "errors": objects FreeCAD marks invalid}."""
    import FreeCAD

    plain = plain_properties()
    doc = FreeCAD.openDocument(path)
    try:
        popup_objects = [o for o in doc.Objects if "popupwb" in str(type(getattr(o, "Proxy", "")))]
        saved = {o.Name: object_figures(o, plain) for o in popup_objects}
        for obj in doc.Objects:
            obj.touch()
        doc.recompute()
        recheck(doc)
        recomputed = {o.Name: object_figures(o, plain) for o in popup_objects}
        errors = {
            o.Name: o.State for o in doc.Objects if "Invalid" in o.State or "Error" in o.State
        }
    finally:
        FreeCAD.closeDocument(doc.Name)
    return {"saved": saved, "recomputed": recomputed, "errors": errors}


def write(demo, out):
    import FreeCAD

    version = ".".join(FreeCAD.Version()[:3])
    folder = os.path.join(out, f"freecad-{version}")
    os.makedirs(folder, exist_ok=True)
    figures = {"freecad": version, "documents": {}}
    for source, name in DEMO_DOCUMENTS.items():
        target = os.path.join(folder, name)
        shutil.copyfile(os.path.join(demo, source), target)
        figures["documents"][name] = document_figures(target)["saved"]
    with open(os.path.join(folder, "figures.json"), "w") as handle:
        json.dump(figures, handle, indent=1, sort_keys=True)
    print(f"golden documents of FreeCAD {version}: {folder}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    writer = sub.add_parser("write")
    writer.add_argument("--demo", required=True, help="the folder `make demo` wrote")
    writer.add_argument("--out", default=os.path.join(REPO, "tests", "data", "golden"))
    reader = sub.add_parser("figures")
    reader.add_argument("file")
    args = parser.parse_args()
    if args.command == "write":
        write(args.demo, args.out)
    else:
        print(json.dumps(document_figures(os.path.abspath(args.file)), sort_keys=True))
    return 0


if __name__ == "__main__":
    sys.exit(main())
