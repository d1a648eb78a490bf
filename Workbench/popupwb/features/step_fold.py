"""StepFold: a parallelogram step, riser on the host's ground and tread on its backdrop (thesis
Fig 4.1, D2).

Stored in .FCStd files as popupwb.features.step_fold.StepFold: never rename.
"""

from popupwb.features.mechanism_feature import MechanismFeature, Parameter


class StepFold(MechanismFeature):
    TYPE = "PopUp::StepFold"
    GROUP = "Step fold"
    PARAMS = "StepFoldParams"
    GENERATOR = "add_step_fold"
    PARAMETERS = (
        Parameter("Offset", "length", "offset", "Start of the step along the host's hinge", 20.0),
        Parameter("Width", "length", "width", "Extent of the step along the host's hinge", 40.0),
        Parameter(
            "RunGround",
            "length",
            "run_ground",
            "Distance of the riser's fold on the host's ground from the hinge (= tread depth)",
            30.0,
        ),
        Parameter(
            "RunBackdrop",
            "length",
            "run_backdrop",
            "Distance of the tread's fold on the host's backdrop from the hinge (= riser height)",
            20.0,
        ),
    )

    @classmethod
    def fitted_parameters(cls, pair):
        depth = min(pair.ground_depth, pair.backdrop_depth)
        return {
            "Offset": 0.3 * pair.length,
            "Width": 0.4 * pair.length,
            "RunGround": 0.3 * depth,
            "RunBackdrop": 0.3 * depth,
        }
