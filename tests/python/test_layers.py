"""The layers hold: no include or import runs back up a floor, none joins areas of one floor, and
nothing forms a circle (tools/layers.py, docs/DESIGN.md "Layers"). Static: reads the sources only."""

import os

import pytest

from cli_runner import SOURCE_DIR, load_tool


@pytest.fixture(scope="module")
def layers():
    return load_tool("layers")


def write(root, path, text):
    full = os.path.join(root, path)
    os.makedirs(os.path.dirname(full), exist_ok=True)
    with open(full, "w") as f:
        f.write(text)


def problems_of(layers, root):
    layers.set_root(str(root))
    try:
        return [line for wing in layers.wings() for line in wing.problems()]
    finally:
        layers.set_root(SOURCE_DIR)


def test_the_house_has_no_arrow_back_up_and_no_circle(layers):
    """None but the arrows tools/layers.py lists as still open, with their reasons."""
    problems = problems_of(layers, SOURCE_DIR)
    assert problems == []


def test_every_arrow_listed_as_still_open_is_still_there(layers):
    layers.set_root(SOURCE_DIR)
    assert layers.stale_exceptions(layers.wings()) == []
    assert layers.STILL_OPEN == {}  # the list only shrinks, and is empty


def test_the_house_is_read(layers):
    layers.set_root(SOURCE_DIR)
    core, workbench = layers.wings()
    # every core area and the workbench's packages appear: the reader did not miss the tree
    areas = {node.split("/")[0] for arrow in core.arrows for node in arrow}
    assert {"geometry", "model", "simulation", "sheets", "fitting", "motion", "bindings"} <= areas
    assert len(core.arrows) > 200 and len(workbench.arrows) > 200


def test_an_include_back_up_is_found(layers, tmp_path):
    write(tmp_path, "core/include/popup/model/patch.hpp", "#pragma once\n")
    write(tmp_path, "core/src/geometry/polygon.cpp", '#include "popup/model/patch.hpp"\n')
    assert problems_of(layers, tmp_path) == [
        "core + bindings (includes): arrow runs back up: geometry/polygon -> model/patch"
    ]


def test_a_circle_of_imports_is_found(layers, tmp_path):
    write(tmp_path, "Workbench/popupwb/__init__.py", "")
    write(tmp_path, "Workbench/popupwb/features/__init__.py", "")
    write(tmp_path, "Workbench/popupwb/features/a.py", "from popupwb.features import b\n")
    write(tmp_path, "Workbench/popupwb/features/b.py", "def f():\n    from . import a\n")
    assert problems_of(layers, tmp_path) == [
        "Workbench (imports): circle: popupwb.features.a <-> popupwb.features.b"
    ]


def test_a_stage_including_its_driver_is_a_circle(layers, tmp_path):
    # the driver includes its stage, the stage includes the driver's header for its types
    write(tmp_path, "core/include/popup/sheets/layout.hpp", "#pragma once\n")
    write(
        tmp_path,
        "core/src/sheets/layout.cpp",
        '#include "popup/sheets/layout.hpp"\n' '#include "tabs.hpp"\n',
    )
    write(tmp_path, "core/src/sheets/tabs.hpp", "#pragma once\n")
    write(tmp_path, "core/src/sheets/tabs.cpp", '#include "popup/sheets/layout.hpp"\n')
    assert problems_of(layers, tmp_path) == [
        "core + bindings (includes): circle: sheets/layout <-> sheets/tabs"
    ]
