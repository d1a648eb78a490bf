#pragma once
#include <optional>
#include <vector>

#include "popup/geometry/pose.hpp"
#include "popup/motion/linkage_chains.hpp"

namespace popup {

/// How the character sits on the card (thesis ch. 6: the user's viewpoint and placement). The
/// card frame is the project's: y along the central fold, the card open flat in z = 0, ground
/// page x > 0. The viewer looks down from +z: the viewer's right (view × up) becomes +x, the
/// file's up +y. A character facing the eye has its own right hand at −x.
struct MotionView {
    Vec3 view = Vec3(0, 0, -1); ///< from the eye toward the character, in the file's axes
    Vec3 up = Vec3(0, 1, 0);    ///< the file's direction that becomes the card's +y
    /// Card mm per file unit; default: the projected bounding box (over the frame range) fits the
    /// card inside `margin`.
    std::optional<double> scale;
    /// Card (x, y) of the projected bounding box's centre; default (0, width / 2).
    std::optional<Vec2> centre;
    double margin = 0.1;       ///< free border, fraction of each card dimension
    double card_width = 210.0; ///< along the fold (mm)
    double card_depth = 148.0; ///< each page (mm)
    int first_frame = 0;
    int last_frame = -1;          ///< -1: the last
    double angle_tolerance = 2.0; ///< τangle (degrees) of the adaptive sampling (thesis §6.2)
    /// The adaptive sampling starts from this many equal intervals of s, so a straight path keeps
    /// samples along it and eq 6.6 sees its pace (adaptive_samples.hpp).
    int min_intervals = 8;
};

/// A chain's target motion on the card. s in [0, 1] is the frame parameter: s = 0 the first
/// frame, where the card is closed (θ = 0), s = 1 the last frame, the card open flat (θ = 180°);
/// θ = 180°·s (docs/MATH.md, Motion targets).
struct ChainPath {
    std::vector<double> s;      ///< adaptive samples (thesis §6.2, [dF95]), 0 and 1 included
    std::vector<Vec2> effector; ///< card (x, y) mm of the end effector at each s
    /// card (x, y) mm at each s of the joint the chain hangs from: its first bone's parent (the
    /// branching bone), or its first bone for a chain at the skeleton's root
    std::vector<Vec2> root;
    /// Normalised mean depth of its vertices toward the viewer at s = 1 (0 deepest .. 1 nearest),
    /// the thesis's D (eq 6.7).
    double depth = 0.0;
};

struct MotionTargets {
    Eigen::Matrix4d animation_to_card = Eigen::Matrix4d::Identity(); ///< file units to card mm
    std::vector<LinkageChain> chains;
    std::vector<ChainPath> paths; ///< one per chain
    double diagonal_mm = 0.0;     ///< the character's projected bounding-box diagonal on the card
    int first_frame = 0;
    int last_frame = 0;
};

/// Forward kinematics over the frame range, projection on the card, adaptive sampling. Errors
/// name the option and its range (bad_option) for a bad view, frame range or scale.
Result<MotionTargets> motion_targets(const Animation& animation, const MotionView& view,
                                     const ChainOptions& chains = {});

} // namespace popup
