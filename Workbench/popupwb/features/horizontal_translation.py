"""HorizontalTranslation: a parallelogram step fold and a patch M hinged at the host's hinge that
passes through a slit along the step's nose; M's far end slides out and back as the card opens
and closes (thesis §4.3.1; docs/MATH.md, Horizontal translation).

Stored in .FCStd files as popupwb.features.horizontal_translation.HorizontalTranslation: never
rename.
"""

from popupwb.features.mechanism_feature import MechanismFeature


class HorizontalTranslation(MechanismFeature):
    KIND = "horizontal_translation"

    @classmethod
    def fitted_parameters(cls, pair):
        depth = min(pair.ground_depth, pair.backdrop_depth)
        return {
            "Offset": 0.3 * pair.length,
            "Width": 0.25 * pair.length,
            "RunGround": 0.3 * depth,
            "RunBackdrop": 0.15 * depth,
            "Reach": 0.5 * depth,
        }
