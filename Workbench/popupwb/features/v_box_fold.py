"""VBoxFold: a type-1 v-fold (v-box), four walls on a rhombus across the host's hinge closed by a
two-triangle top (thesis Fig 4.3a). Needs a host open flat at the design state.

Stored in .FCStd files as popupwb.features.v_box_fold.VBoxFold: never rename.
"""

from popupwb.features.mechanism_feature import MechanismFeature, Parameter


class VBoxFold(MechanismFeature):
    TYPE = "PopUp::VBoxFold"
    GROUP = "V-box"
    PARAMS = "VBoxFoldParams"
    GENERATOR = "add_v_box_fold"
    PARAMETERS = (
        Parameter("Offset", "length", "offset", "Front corner along the host's hinge", 20.0),
        Parameter("Side", "length", "side", "Length of each wall along the host", 40.0),
        Parameter("Height", "length", "height", "Height of the walls at the design state", 30.0),
        Parameter(
            "WallAngle", "angle", "wall_angle", "Angle between each wall and the host's hinge", 45.0
        ),
    )

    @classmethod
    def fitted_parameters(cls, pair):
        depth = min(pair.ground_depth, pair.backdrop_depth)
        return {
            "Offset": 0.3 * pair.length,
            "Side": min(0.3 * depth, 0.25 * pair.length),
            "Height": 0.3 * depth,
        }
