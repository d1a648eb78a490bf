#pragma once
#include <string>
#include <vector>

#include "popup/input/model_mesh.hpp"
#include "popup/motion/animation.hpp"
#include "popup/motion/motion_types.hpp"

namespace popup {

/// One piece of the character as the card prints it (thesis §6.4, Fig 6.9): a limb on the
/// moving patches of the mechanism that carries its chains, or the body on every other patch.
struct PrintedPart {
    std::string mechanism;           ///< the mechanism carrying the limb; "" for the body
    std::vector<std::string> parts;  ///< that mechanism's parts it is printed on (patch names
                                     ///< "<mechanism>.<part>"); empty for the body
    std::vector<std::string> chains; ///< the chains it shows; empty for the body
    ModelMesh mesh;                  ///< its triangles, posed at the last frame, in card mm
};

/// The parts of a mechanism kind that carry its body part's outline and artwork: the patch that
/// moves with the end effector (rotation_arm wing_arm, vertical_translation TG and TB,
/// horizontal_translation M, the diagonal's step_fold tread) or the floating layer's platform
/// (TG and TB). Empty for the diagonal's v_fold, which only carries the step.
std::vector<std::string> outlined_parts(MechanismKind kind);

/// The character split as the card prints it: first the body (every triangle of the mesh posed
/// at `result.targets.last_frame` not in a limb), then one limb per mechanism with outlined
/// parts that carries chains (a mechanism hosting another stands under the part: the hosted one
/// takes it), made of the triangles whose three corners are skinned to those chains
/// (LinkageChain::vertices). Placed on the card by targets.animation_to_card, faces kept
/// outward. A limb no triangle belongs to alone keeps an empty mesh (its chains' triangles stay
/// in the body) so the outlines can say so.
/// Empty when the animation has no skinned mesh.
std::vector<PrintedPart> printed_parts(const Animation& animation, const MotionResult& result);

} // namespace popup
