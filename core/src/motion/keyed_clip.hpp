#pragma once
// An animation's keyframes as assimp read them, and the per-frame transforms made from them.
// The reading child sends the keys (a quarter of the transforms' bytes on a long capture), and
// the caller makes the frames straight into Animation::local: the 48 MB of 4,500 frames are
// then written once, not made, copied to bytes, piped and copied back.
#include <string>
#include <vector>

#include <assimp/anim.h>

#include "../input/byte_message.hpp"
#include "popup/motion/animation.hpp"

namespace popup::motion {

/// One bone's channel (ticks), as assimp's aiNodeAnim holds it, and its rest transform.
struct BoneKeys {
    Eigen::Matrix4d rest = Eigen::Matrix4d::Identity(); ///< its node's transformation
    bool animated = false;                              ///< false: it keeps `rest` at every frame
    std::vector<aiVectorKey> positions, scalings;       ///< empty: the rest pose's
    std::vector<aiQuatKey> rotations;                   ///< empty: the rest pose's
};

/// The bones' keys (per bone, Animation::bones' order) and the frames' times in ticks.
struct KeyedClip {
    std::vector<BoneKeys> bones;
    std::vector<double> frame_ticks;
};

/// The keys of assimp's channel (nullptr: none) over the node's rest transform.
BoneKeys bone_keys(const aiNodeAnim* channel, const Eigen::Matrix4d& rest);

/// Every bone's global affine transform at tick `tick` into `global` (size: the bones').
void globals_at(const KeyedClip& clip, const std::vector<Bone>& bones, double tick,
                std::vector<Eigen::Matrix4d>& global);

/// Each frame's local transforms into animation.local (replaced): the rigid parts of the
/// bones' globals, relative to their parents' (a rig's uniform scale, as FBX's 0.01 armature,
/// goes into the bones' positions and the mesh, not their transforms).
void read_frames(const KeyedClip& clip, Animation& animation);

/// The rigid part of an affine transform whose linear part is a rotation times a uniform scale
/// (what animation rigs use): the rotation nearest to it, and its translation unchanged.
Eigen::Isometry3d rigid_part(const Eigen::Matrix4d& a);

void put_clip(ByteWriter& writer, const KeyedClip& clip);
/// Reads what put_clip wrote for `bone_count` bones (the reader's `fine` says whether it could).
void get_clip(ByteReader& reader, std::size_t bone_count, KeyedClip& clip);

} // namespace popup::motion
