#pragma once
#include "popup/model/cancel_flag.hpp"
#include "popup/motion/motion_types.hpp"

namespace popup::motion {

/// The parts of a motion mechanism (core type) that carry its body part's outline: the patch
/// that moves with the end effector (rotation_arm wing_arm, vertical_translation TG and TB,
/// horizontal_translation M, the diagonal's step_fold tread) or the floating layer's platform
/// (TG and TB). Empty for the diagonal's v_fold, which only carries the step.
std::vector<std::string> outlined_parts(MechanismKind kind);

/// Thesis §6.4 (Patches): each mechanism's outlined parts take the orthographic projection, at
/// the last frame (the card open flat), of the mesh triangles skinned to the chains it carries
/// (LinkageChain::vertices, all three corners), placed by targets.animation_to_card; a profile
/// is kept only while check_validity still passes (fit_outlines_of). Updates result.scaffold and
/// result.profiles; what was dropped, or that the animation has no mesh, goes into the
/// result's diagnostics as warnings.
void outline_motion(const Animation& animation, MotionResult& result,
                    const CancelFlag* cancel = nullptr);

} // namespace popup::motion
