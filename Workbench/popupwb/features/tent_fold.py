"""TentFold: two slopes standing on a base patch pair, meeting at an apex (thesis Fig 4.2).

Stored in .FCStd files as popupwb.features.tent_fold.TentFold: never rename.
"""

from popupwb.features.mechanism_feature import MechanismFeature


class TentFold(MechanismFeature):
    KIND = "tent_fold"
    OUTPUTS = (
        (
            "SlopeBackdrop",
            "Length of the backdrop-side slope, derived so the tent folds flat: "
            "Foot + Slope - FootBackdrop",
        ),
    )

    @classmethod
    def fitted_parameters(cls, pair):
        depth = min(pair.ground_depth, pair.backdrop_depth)
        return {
            "Offset": 0.3 * pair.length,
            "Width": 0.4 * pair.length,
            "Foot": 0.3 * depth,
            "FootBackdrop": 0.3 * depth,
            "Slope": 0.4 * depth,
        }

    def update_outputs(self, obj, built):
        from popupwb.core import popupcore

        value = popupcore.tent_backdrop_slope(self.parameters(obj))
        if abs(obj.SlopeBackdrop.Value - value) > 1e-12:
            obj.SlopeBackdrop = value
