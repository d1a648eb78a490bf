"""VFold: a type-2 v-fold, two triangles hinged to the host's patches at HingeAngle to its hinge
and to each other along the spine (thesis Fig 4.3b, D1).

Stored in .FCStd files as popupwb.features.v_fold.VFold: never rename.
"""

from popupwb.features.mechanism_feature import MechanismFeature


class VFold(MechanismFeature):
    KIND = "v_fold"

    @classmethod
    def fitted_parameters(cls, pair):
        size = min(pair.ground_depth, pair.backdrop_depth, pair.length)
        return {
            "Offset": 0.2 * pair.length,
            "Run": 0.3 * size,
            "Spine": 0.33 * size,
        }
