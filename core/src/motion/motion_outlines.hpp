#pragma once
#include "popup/model/cancel_flag.hpp"
#include "popup/motion/motion_types.hpp"
#include "popup/motion/printed_parts.hpp"

namespace popup::motion {

/// Thesis §6.4 (Patches): each mechanism's outlined parts take the orthographic projection of its
/// limb (printed_parts: the mesh triangles skinned to the chains it carries, at the last frame,
/// the card open flat, placed by targets.animation_to_card); a profile
/// is kept only while check_validity still passes (fit_outlines_of). Updates result.scaffold and
/// result.profiles; what was dropped, or that the animation has no mesh, goes into the
/// result's diagnostics as warnings.
void outline_motion(const Animation& animation, MotionResult& result,
                    const CancelFlag* cancel = nullptr);

} // namespace popup::motion
