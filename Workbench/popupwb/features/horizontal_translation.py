"""HorizontalTranslation: a parallelogram step fold and a patch M hinged at the host's hinge that
passes through a slit along the step's nose; M's far end slides out and back as the card opens
and closes (thesis §4.3.1; docs/MATH.md, Horizontal translation).

Stored in .FCStd files as popupwb.features.horizontal_translation.HorizontalTranslation: never
rename.
"""

from popupwb.features.mechanism_feature import MechanismFeature, Parameter


class HorizontalTranslation(MechanismFeature):
    TYPE = "PopUp::HorizontalTranslation"
    GROUP = "Horizontal translation"
    PARAMS = "HorizontalTranslationParams"
    GENERATOR = "add_horizontal_translation"
    PARAMETERS = (
        Parameter("Offset", "length", "offset", "Start along the host's hinge", 20.0),
        Parameter("Width", "length", "width", "Extent along the host's hinge", 40.0),
        Parameter("RunGround", "length", "run_ground", "Step's riser foot from the hinge", 40.0),
        Parameter("RunBackdrop", "length", "run_backdrop", "Step's tread foot, < RunGround", 20.0),
        Parameter("Reach", "length", "reach", "Length r of M from the hinge to its end P", 60.0),
    )

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
