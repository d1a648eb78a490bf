"""FloatingLayer: a platform floating parallel to its host on two supports, kept from shearing by
end panels (thesis §2.3, §4.3.5). It offers its platform and both supports as base patch pairs.

Stored in .FCStd files as popupwb.features.floating_layer.FloatingLayer: never rename.
"""

from popupwb.features.mechanism_feature import MechanismFeature


class FloatingLayer(MechanismFeature):
    KIND = "floating_layer"

    @classmethod
    def fitted_parameters(cls, pair):
        depth = min(pair.ground_depth, pair.backdrop_depth)
        return {
            "Offset": 0.3 * pair.length,
            "Width": 0.4 * pair.length,
            "Height": 0.25 * depth,
            "Support": 0.2 * depth,
            "Overhang": 0.1 * depth,
        }
