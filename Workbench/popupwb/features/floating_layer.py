"""FloatingLayer: a platform floating parallel to its host on two supports, kept from shearing by
end panels (thesis §2.3, §4.3.5). It offers its platform and both supports as base patch pairs.

Stored in .FCStd files as popupwb.features.floating_layer.FloatingLayer: never rename.
"""

from popupwb.features.mechanism_feature import MechanismFeature, Parameter


class FloatingLayer(MechanismFeature):
    TYPE = "PopUp::FloatingLayer"
    GROUP = "Floating layer"
    PARAMS = "FloatingLayerParams"
    GENERATOR = "add_floating_layer"
    PARAMETERS = (
        Parameter("Offset", "length", "offset", "Start of the layer along the host's hinge", 20.0),
        Parameter("Width", "length", "width", "Extent of the layer along the host's hinge", 40.0),
        Parameter("Height", "length", "height", "Height of the platform over the host", 25.0),
        Parameter("Support", "length", "support", "Distance of each support from the hinge", 20.0),
        Parameter("Overhang", "length", "overhang", "Platform beyond each support", 15.0),
    )
    # popupcore's add_floating_layer offers [platform, both supports] under the box's part names.
    OFFERS = ("top", "side_ground", "side_backdrop")

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
