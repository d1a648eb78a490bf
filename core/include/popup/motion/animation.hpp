#pragma once
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "popup/input/model_mesh.hpp"
#include "popup/model/result.hpp"

namespace popup {

/// One joint of a skeleton: its node in the file. A bone's position is the origin of its global
/// transform; a chain's end effector is the origin of its last bone (end sites included).
struct Bone {
    std::string name;
    int parent = -1; ///< index of the parent bone, -1 for a root; parents come before children
};

/// An animated character (thesis ch. 6 input), in the file's units and axes.
struct Animation {
    std::string source; ///< file or object name, for messages
    std::vector<Bone> bones;
    std::vector<double> frame_times_s; ///< one per frame, strictly ascending
    /// local[f][b]: bone b's transform to its parent's frame (a root's: to the file's world) at
    /// frame f. Keyframes are sampled at every frame; missing channels keep the rest pose.
    std::vector<std::vector<Eigen::Isometry3d>> local;
    /// Skinned mesh in its bind pose (empty for BVH and trajectory JSON).
    ModelMesh mesh;
    /// Per bone: mesh space to the bone's space at bind time (assimp's offset matrix); identity
    /// without a mesh.
    std::vector<Eigen::Isometry3d> bind_inverse;
    /// Per mesh vertex: (bone, weight) with weights summing to 1; empty without a mesh. A vertex no
    /// bone weighs follows the bone of its mesh's node.
    std::vector<std::vector<std::pair<int, double>>> skin;

    int frames() const { return static_cast<int>(frame_times_s.size()); }
};

struct LoadAnimationOptions {
    double timeout_s = 120.0; ///< assimp runs in a child process stopped after this long
};

/// Reads an animated character through assimp (BVH, FBX, glTF/GLB with skins, Collada, and what
/// else assimp reads with an animation), in a child process as load_model does. The first
/// animation is taken; every node it animates, and every node on the way to the root, is a bone.
/// Errors (named, with the path): unreadable_model, then check_animation's.
Result<Animation> load_animation(const std::string& path, const LoadAnimationOptions& options = {});

/// Reads the plain JSON of named end-effector trajectories (docs/ANIMATION_INPUT.md): each
/// effector becomes a two-bone chain, "<name>.root" at its root track and "<name>" at its points.
Result<Animation> load_trajectories(const std::string& path);

/// Refuses an animation nothing can be made of, naming what is wrong: no bones, a parent index
/// that is out of range or leads back to the bone (a cycle, naming the bones on it), no
/// animation, a single frame, times not ascending, a NaN or infinite transform or skin weight.
Result<Animation> check_animation(Animation animation);

/// Forward kinematics: every bone's global transform (bone to the file's world) at a frame,
/// fractional frames interpolated between their neighbours (slerp rotations, lerp the rest).
std::vector<Eigen::Isometry3d> forward_kinematics(const Animation& animation, double frame);

/// The skinned mesh at a frame (linear blend skinning), for outlines and artwork.
ModelMesh posed_mesh(const Animation& animation, double frame);

/// The character's own root bone: the first root, or, for a skinned character, below it while a
/// bone skins no vertex, stands still over the take and has one child (the armature node glTF
/// and FBX exports put above the hips, at the file's origin). Its travel is the character's; the
/// still bones above it are not the character. A skeleton alone (BVH, trajectories) is all
/// character: 0.
int character_root(const Animation& animation);

/// Per bone: whether it is one of the still bones above character_root.
std::vector<bool> above_character(const Animation& animation);

} // namespace popup
