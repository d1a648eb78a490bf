"""VerticalTranslation: two v-folds joined along the front spine (the front walls on the host, the
top halves on the walls); the top's front corner slides along the host's hinge as the card closes
(thesis §4.3.2; docs/MATH.md, Vertical translation).

Stored in .FCStd files as popupwb.features.vertical_translation.VerticalTranslation: never rename.
"""

from popupwb.features.mechanism_feature import MechanismFeature, Parameter


class VerticalTranslation(MechanismFeature):
    TYPE = "PopUp::VerticalTranslation"
    GROUP = "Vertical translation"
    PARAMS = "VBoxFoldParams"
    # Params fields the generator fixes (add_vertical_translation builds the v-box's triangular
    # half: no back walls): a design may state them, with these values only.
    FIXED_FIELDS = {"back": 0.0}
    GENERATOR = "add_vertical_translation"
    PARAMETERS = (
        Parameter("Offset", "length", "offset", "Front corner along the host's hinge", 20.0),
        Parameter("Side", "length", "side", "Length of each wall along the host", 40.0),
        Parameter("Height", "length", "height", "Height h of the walls at the design state", 30.0),
        Parameter(
            "WallAngle",
            "angle",
            "wall_angle",
            "Angle α between each wall and the host's hinge",
            45.0,
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
