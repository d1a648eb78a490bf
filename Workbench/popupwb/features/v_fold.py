"""VFold: a type-2 v-fold, two triangles hinged to the host's patches at HingeAngle to its hinge
and to each other along the spine (thesis Fig 4.3b, D1).

Stored in .FCStd files as popupwb.features.v_fold.VFold: never rename.
"""

from popupwb.features.mechanism_feature import MechanismFeature, Parameter


class VFold(MechanismFeature):
    TYPE = "PopUp::VFold"
    GROUP = "V-fold"
    PARAMS = "VFoldParams"
    GENERATOR = "add_v_fold"
    OFFERS = ("wings",)  # a step fold on the wings makes the diagonal translation (§4.3.3)
    PARAMETERS = (
        Parameter("Offset", "length", "offset", "Point O of the v along the host's hinge", 20.0),
        Parameter(
            "Run", "length", "run", "Length of each wing's fold on the host, |OA| = |OB|", 40.0
        ),
        Parameter(
            "HingeAngle",
            "angle",
            "hinge_angle",
            "Angle between each wing's fold on the host and the host's hinge",
            45.0,
        ),
        Parameter("Spine", "length", "spine", "Length of the spine O-P at the design state", 45.0),
        Parameter(
            "SpineAngle",
            "angle",
            "spine_angle",
            "Angle of the spine above the host's hinge at the design state",
            60.0,
        ),
    )

    @classmethod
    def fitted_parameters(cls, pair):
        size = min(pair.ground_depth, pair.backdrop_depth, pair.length)
        return {
            "Offset": 0.2 * pair.length,
            "Run": 0.3 * size,
            "Spine": 0.33 * size,
        }
