"""RotationArm: a v-fold lying flat on its host whose ground wing carries an arm past the spine;
closing the card swings the arm's tip P (thesis §4.3.4, Fig 4.15; docs/MATH.md, Rotation). On a
floating layer's side pair (HostPair "<layer>.side_ground" or ".side_backdrop", open 90°) it is
built popped at that opening and turns about the support's foot, off the central fold (§4.3.4,
last paragraph; docs/MATH.md, "A rotation arm on a floating layer's side").

Stored in .FCStd files as popupwb.features.rotation_arm.RotationArm: never rename.
"""

from popupwb.features.mechanism_feature import MechanismFeature


class RotationArm(MechanismFeature):
    KIND = "rotation_arm"

    @classmethod
    def fitted_parameters(cls, pair):
        depth = min(pair.ground_depth, pair.backdrop_depth)
        spine = 0.25 * pair.length
        run = min(0.3 * depth, spine)
        return {
            "Offset": 0.3 * pair.length,
            "Spine": spine,
            "Run": run,
            "Arm": min(0.8 * spine * spine / run, 0.5 * depth),
        }
