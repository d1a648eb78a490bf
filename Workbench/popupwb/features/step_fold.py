"""StepFold: a parallelogram step, riser on the host's ground and tread on its backdrop (thesis
Fig 4.1, D2).

Stored in .FCStd files as popupwb.features.step_fold.StepFold: never rename.
"""

from popupwb.features.mechanism_feature import MechanismFeature


class StepFold(MechanismFeature):
    KIND = "step_fold"

    @classmethod
    def fitted_parameters(cls, pair):
        depth = min(pair.ground_depth, pair.backdrop_depth)
        return {
            "Offset": 0.3 * pair.length,
            "Width": 0.4 * pair.length,
            "RunGround": 0.3 * depth,
            "RunBackdrop": 0.3 * depth,
        }
