"""BoxFold: a parallel box fold with top, sides, backbone and front and back panels (thesis
Fig 4.4). It offers its top and both sides as base patch pairs for nesting.

Stored in .FCStd files as popupwb.features.box_fold.BoxFold: never rename.
"""

from popupwb.features.mechanism_feature import MechanismFeature, Parameter


class BoxFold(MechanismFeature):
    TYPE = "PopUp::BoxFold"
    GROUP = "Box fold"
    PARAMS = "BoxFoldParams"
    GENERATOR = "add_box_fold"
    PARAMETERS = (
        Parameter("Offset", "length", "offset", "Start of the box along the host's hinge", 20.0),
        Parameter("Width", "length", "width", "Extent of the box along the host's hinge", 40.0),
        Parameter(
            "DepthGround",
            "length",
            "depth_ground",
            "Depth of the box on the host's ground side (= its top's ground half)",
            30.0,
        ),
        Parameter(
            "DepthBackdrop",
            "length",
            "depth_backdrop",
            "Depth of the box on the host's backdrop side (= its top's backdrop half)",
            30.0,
        ),
        Parameter("Height", "length", "height", "Height of the box's top over the hinge", 30.0),
        Parameter(
            "Front", "bool", "front", "Front panels (without front and back the box shears)", True
        ),
        Parameter("Back", "bool", "back", "Back panels", True),
        Parameter(
            "PanelPairs",
            "integer",
            "panel_pairs",
            "Front and back panel pairs per end, strips stacked up the end",
            1,
        ),
    )
    # popupcore's add_box_fold offers [top, side_ground, side_backdrop], named "<name>.<part>".
    OFFERS = ("top", "side_ground", "side_backdrop")

    @classmethod
    def fitted_parameters(cls, pair):
        # Closed, each end panel reaches DepthGround past the box's end (thesis §4.2.2): with the
        # depth at most half the hinge, the box sweeps at most 70 % of it and leaves room beside.
        depth = min(pair.ground_depth, pair.backdrop_depth, 0.5 * pair.length)
        return {
            "Offset": 0.3 * pair.length,
            "Width": 0.4 * pair.length,
            "DepthGround": 0.3 * depth,
            "DepthBackdrop": 0.3 * depth,
            "Height": 0.3 * depth,
        }
