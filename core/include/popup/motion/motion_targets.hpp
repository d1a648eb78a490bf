#pragma once
#include <optional>
#include <vector>

#include "popup/geometry/pose.hpp"
#include "popup/motion/frame_window.hpp"
#include "popup/motion/linkage_chains.hpp"
#include "popup/motion/motion_view.hpp"

namespace popup {

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
    /// How far the root travelled along the ground over the frame range and was taken out (card
    /// mm; 0 when kept: MotionView::keep_travel, or a single chain).
    double travel_removed_mm = 0.0;
    /// The travel was taken out: a picture posing the character at a frame moves it back by
    /// ground_travel(animation, view.up, last_frame, frame) to stand where the targets are.
    bool in_place = false;
    /// The frame window chosen (MotionView::auto_frames), or chosen == false: the given frames.
    FrameWindow window;
};

/// The character's travel along the ground (across `up`) from `last_frame` to `frame`, file
/// units: what motion_targets takes out of every pose when it keeps a character in place. The
/// first root travels, or below it the first bone that moves or branches (a glTF or FBX
/// armature node above the hips stands still).
Vec3 ground_travel(const Animation& animation, const Vec3& up, int last_frame, double frame);

/// A chain whose end effector stays within this fraction of the character's diagonal of its mean
/// point does not move on the card: the mapping holds it still (its floating layer).
constexpr double still_path_fraction = 0.01;

/// The farthest a path's point lies from the path's mean point (mm; 0 for no points).
double path_spread(const std::vector<Vec2>& points);

/// Whether a chain moves on the card: its end effector strays more than still_path_fraction of
/// `diagonal_mm` from its mean point (as the mapping decides; `popup animate --list-chains`).
bool path_moves(const ChainPath& path, double diagonal_mm);

/// Forward kinematics over the frame range, projection on the card, adaptive sampling. Errors
/// name the option and its range (bad_option) for a bad view, frame range or scale.
Result<MotionTargets> motion_targets(const Animation& animation, const MotionView& view,
                                     const ChainOptions& chains = {});

} // namespace popup
