"""BoxFold: a parallel box fold with top, sides, backbone and front and back panels (thesis
Fig 4.4). It offers its top and both sides as base patch pairs for nesting.

Stored in .FCStd files as popupwb.features.box_fold.BoxFold: never rename.
"""

from popupwb.features.mechanism_feature import MechanismFeature


class BoxFold(MechanismFeature):
    KIND = "box_fold"

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
