"""VBoxFold: a type-1 v-fold (v-box), four walls on a rhombus across the host's hinge closed by a
two-triangle top (thesis Fig 4.3a). Needs a host open flat at the design state.

Stored in .FCStd files as popupwb.features.v_box_fold.VBoxFold: never rename.
"""

from popupwb.features.mechanism_feature import MechanismFeature


class VBoxFold(MechanismFeature):
    KIND = "v_box_fold"

    @classmethod
    def fitted_parameters(cls, pair):
        depth = min(pair.ground_depth, pair.backdrop_depth)
        return {
            "Offset": 0.3 * pair.length,
            "Side": min(0.3 * depth, 0.25 * pair.length),
            "Height": 0.3 * depth,
        }
