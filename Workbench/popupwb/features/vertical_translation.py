"""VerticalTranslation: two v-folds joined along the front spine (the front walls on the host, the
top halves on the walls); the top's front corner slides along the host's hinge as the card closes
(thesis §4.3.2; docs/MATH.md, Vertical translation).

Stored in .FCStd files as popupwb.features.vertical_translation.VerticalTranslation: never rename.
"""

from popupwb.features.mechanism_feature import MechanismFeature


class VerticalTranslation(MechanismFeature):
    KIND = "vertical_translation"

    @classmethod
    def fitted_parameters(cls, pair):
        depth = min(pair.ground_depth, pair.backdrop_depth)
        return {
            "Offset": 0.3 * pair.length,
            "Side": min(0.3 * depth, 0.25 * pair.length),
            "Height": 0.3 * depth,
        }
