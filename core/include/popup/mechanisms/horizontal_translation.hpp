#pragma once
#include "popup/mechanisms/step_fold.hpp"

namespace popup {

/// Horizontal translation (thesis §4.3.1): a parallelogram step fold and a patch M hinged at the
/// host's hinge that passes through a slit cut along the step's nose. M always points from the
/// hinge through the nose, so its far end P slides out and back as the card opens and closes.
struct HorizontalTranslationParams : StepFoldParams {
    double reach =
        60.0; ///< r: length of M from the host's hinge to P (mm), > run_ground − run_backdrop
};

/// Closed form: P in the host's section (x, z) at `opening`: r·C/|C| with C the step's nose,
/// |C| = √(a² + b² + 2ab cos φ) (docs/MATH.md, Horizontal translation; thesis eq 4.3 corrected).
Vec2 horizontal_translation_tip(const HorizontalTranslationParams& params, double opening);

Result<MechanismParts>
add_horizontal_translation(Scaffold& scaffold, const BasePatchPair& host,
                           const HorizontalTranslationParams& params,
                           const std::string& name = "HorizontalTranslation");

} // namespace popup
