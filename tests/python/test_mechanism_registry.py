"""popupwb.mechanism_registry lists every mechanism type once, and popupwb.make, the commands and
the view provider read it (the GUI side is checked in tests/gui/run_gui_smoke.py)."""

import importlib
import os
import pkgutil

from conftest import WORKBENCH_DIR


def mechanism_feature_classes():
    """Every MechanismFeature subclass the features package defines."""
    import popupwb.features
    from popupwb.features.mechanism_feature import MechanismFeature

    for info in pkgutil.iter_modules(popupwb.features.__path__):
        importlib.import_module(f"popupwb.features.{info.name}")
    found, stack = set(), [MechanismFeature]
    while stack:
        for sub in stack.pop().__subclasses__():
            found.add(sub)
            stack.append(sub)
    return found


def test_registry_covers_every_mechanism_feature_once(freecad):
    from popupwb.mechanism_registry import MECHANISMS

    features = [m.feature for m in MECHANISMS]
    assert len(features) == len(set(features)) == 9
    assert set(features) == mechanism_feature_classes()


def test_registry_entries_are_unique_and_have_their_icons(freecad):
    from popupwb.mechanism_registry import COMMAND_IDS, MECHANISMS, by_command, by_type

    for field in ("command_id", "make_name", "menu_text", "type_name"):
        values = [getattr(m, field) for m in MECHANISMS]
        assert len(set(values)) == len(values), field
    for m in MECHANISMS:
        assert m.command_id == "PopUp_" + m.feature.__name__  # icons are named after commands
        assert os.path.isfile(m.icon), m.icon
        assert by_command(m.command_id) is m and by_type(m.type_name) is m
        module, class_name = m.task_panel
        path = os.path.join(WORKBENCH_DIR, *module.split(".")) + ".py"
        with open(path, encoding="utf-8") as f:
            assert f"\nclass {class_name}" in f.read(), m.task_panel
    assert COMMAND_IDS == [m.command_id for m in MECHANISMS]
    assert by_type("PopUp::Card") is None


def test_every_entry_has_a_make_function_building_its_feature(doc):
    import popupwb.make
    from popupwb.mechanism_registry import MECHANISMS

    card = popupwb.make.make_card(doc, preset="A5")
    made = []
    for m in MECHANISMS:
        make = getattr(popupwb.make, m.make_name)
        assert make.__name__ == m.make_name and m.make_name in popupwb.make.__all__
        for p in m.feature.PARAMETERS:
            assert p.field in make.__doc__, (m.make_name, p.field)
        obj = make(card)
        assert type(obj.Proxy) is m.feature
        assert obj.Proxy.TYPE == m.type_name
        assert obj.Name.startswith(m.feature.__name__) and obj.Host is card
        made.append(obj)
    assert [o.Name for o in made] == [m.feature.__name__ for m in MECHANISMS]


def test_make_functions_take_the_parameters_of_their_feature(doc):
    import pytest

    import popupwb.make

    card = popupwb.make.make_card(doc, preset="A5")
    tent = popupwb.make.make_tent_fold(card, foot=12.0, Slope=31.0, name="Tent")
    assert (tent.Foot.Value, tent.Slope.Value, tent.Name) == (12.0, 31.0, "Tent")
    with pytest.raises(TypeError, match=r"unknown parameter\(s\) \['height'\]"):
        popupwb.make.make_tent_fold(card, height=3.0)
