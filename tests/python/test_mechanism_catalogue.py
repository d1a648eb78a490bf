"""The Workbench reads every mechanism kind's facts from the core's catalogue: the feature
parameter tables, offered pairs, registry titles and part titles are what makers had before the
catalogue moved them into the core (the literal tables below are the Workbench's old ones)."""

import pytest

# (property, kind, field, default) per feature, as the feature modules listed them.
OLD_PARAMETERS = {
    "TentFold": [
        ("Offset", "length", "offset", 20.0),
        ("Width", "length", "width", 40.0),
        ("Foot", "length", "foot", 20.0),
        ("FootBackdrop", "length", "foot_backdrop", 20.0),
        ("Slope", "length", "slope", 30.0),
    ],
    "StepFold": [
        ("Offset", "length", "offset", 20.0),
        ("Width", "length", "width", 40.0),
        ("RunGround", "length", "run_ground", 30.0),
        ("RunBackdrop", "length", "run_backdrop", 20.0),
    ],
    "VFold": [
        ("Offset", "length", "offset", 20.0),
        ("Run", "length", "run", 40.0),
        ("HingeAngle", "angle", "hinge_angle", 45.0),
        ("Spine", "length", "spine", 45.0),
        ("SpineAngle", "angle", "spine_angle", 60.0),
    ],
    "BoxFold": [
        ("Offset", "length", "offset", 20.0),
        ("Width", "length", "width", 40.0),
        ("DepthGround", "length", "depth_ground", 30.0),
        ("DepthBackdrop", "length", "depth_backdrop", 30.0),
        ("Height", "length", "height", 30.0),
        ("Front", "bool", "front", True),
        ("Back", "bool", "back", True),
        ("PanelPairs", "integer", "panel_pairs", 1),
    ],
    "VBoxFold": [
        ("Offset", "length", "offset", 20.0),
        ("Side", "length", "side", 40.0),
        ("Height", "length", "height", 30.0),
        ("WallAngle", "angle", "wall_angle", 45.0),
    ],
    "RotationArm": [
        ("Offset", "length", "offset", 20.0),
        ("Spine", "length", "spine", 40.0),
        ("Run", "length", "run", 30.0),
        ("Arm", "length", "arm", 20.0),
    ],
    "HorizontalTranslation": [
        ("Offset", "length", "offset", 20.0),
        ("Width", "length", "width", 40.0),
        ("RunGround", "length", "run_ground", 40.0),
        ("RunBackdrop", "length", "run_backdrop", 20.0),
        ("Reach", "length", "reach", 60.0),
    ],
    "VerticalTranslation": [
        ("Offset", "length", "offset", 20.0),
        ("Side", "length", "side", 40.0),
        ("Height", "length", "height", 30.0),
        ("WallAngle", "angle", "wall_angle", 45.0),
    ],
    "FloatingLayer": [
        ("Offset", "length", "offset", 20.0),
        ("Width", "length", "width", 40.0),
        ("Height", "length", "height", 25.0),
        ("Support", "length", "support", 20.0),
        ("Overhang", "length", "overhang", 15.0),
    ],
}
OLD_OFFERS = {
    "BoxFold": ("top", "side_ground", "side_backdrop"),
    "FloatingLayer": ("top", "side_ground", "side_backdrop"),
    "VFold": ("wings",),
}
OLD_MENU = [
    ("TentFold", "Tent fold", False),
    ("StepFold", "Step fold", False),
    ("VFold", "V-fold", False),
    ("BoxFold", "Box fold", False),
    ("VBoxFold", "V-box", False),
    ("RotationArm", "Rotation arm", True),
    ("HorizontalTranslation", "Horizontal translation", True),
    ("VerticalTranslation", "Vertical translation", True),
    ("FloatingLayer", "Floating layer", False),
]


def test_the_features_parameter_tables_come_from_the_catalogue_unchanged():
    from popupwb.mechanism_registry import MECHANISMS

    for m in MECHANISMS:
        name = m.feature.__name__
        got = [(p.name, p.kind, p.field, p.default) for p in m.feature.PARAMETERS]
        assert got == OLD_PARAMETERS[name], name
        assert m.feature.OFFERS == OLD_OFFERS.get(name, ()), name
        assert m.feature.TYPE == f"PopUp::{name}"
        for p in m.feature.PARAMETERS:
            assert p.range and p.range in p.doc, (name, p.name)  # the tool tip gives the range


def test_the_registry_takes_order_titles_and_groups_from_the_catalogue():
    from popupwb.mechanism_registry import MECHANISMS

    assert [(m.feature.__name__, m.menu_text, m.motion) for m in MECHANISMS] == OLD_MENU
    assert [m.make_name for m in MECHANISMS][:3] == [
        "make_tent_fold",
        "make_step_fold",
        "make_v_fold",
    ]


def test_part_titles_come_from_the_catalogue():
    from popupwb.patch_titles import CARD_KIND
    from popupwb.validity.card_titles import part_title

    assert part_title("PopUp::BoxFold", "TG") == "top, ground side"
    assert part_title("PopUp::BoxFold", "BR2") == "back end, backdrop side, strip 2"
    assert part_title("PopUp::FloatingLayer", "L") == "support, ground side"
    assert part_title("PopUp::HorizontalTranslation", "M") == "sliding panel"
    assert part_title(CARD_KIND, "backdrop") == "backdrop page"
    assert part_title("PopUp::Unknown", "TG") == "TG"


def test_an_unknown_kind_names_the_known_ones():
    from popupwb import mechanism_catalogue

    with pytest.raises(ValueError, match=r"'cube_fold' is not in the catalogue \(known: tent_fold"):
        mechanism_catalogue.entry("cube_fold")
