#include "popup/motion/animation.hpp"

namespace popup {

int character_root(const Animation& animation)
{
    const std::size_t n = animation.bones.size();
    if (n == 0 || animation.skin.empty())
        return 0; // a skeleton alone (BVH, trajectories): every bone is the character's
    std::vector<bool> skins(n, false); // whether any vertex is weighted to the bone
    for (const auto& weights : animation.skin)
        for (const auto& [bone, weight] : weights)
            if (weight > 0.0 && bone >= 0 && std::size_t(bone) < n)
                skins[std::size_t(bone)] = true;
    std::vector<int> children(n, 0), only_child(n, -1);
    for (std::size_t b = 0; b < n; ++b)
        if (const int p = animation.bones[b].parent; p >= 0) {
            ++children[p];
            only_child[p] = int(b);
        }
    // About 200 frames spread over the take: a node that moves at all moves in them.
    const int frames = animation.frames();
    const int step = std::max(1, frames / 200);
    std::vector<std::vector<Eigen::Isometry3d>> poses;
    for (int f = 0; f < frames; f += step)
        poses.push_back(forward_kinematics(animation, double(f)));
    auto still = [&](int b) {
        for (const auto& pose : poses)
            if (!pose[b].isApprox(poses[0][b], 1e-12))
                return false;
        return true;
    };
    int bone = 0;
    while (children[bone] == 1 && !skins[std::size_t(bone)] && still(bone))
        bone = only_child[bone];
    return bone;
}

std::vector<bool> above_character(const Animation& animation)
{
    std::vector<bool> above(animation.bones.size(), false);
    if (animation.bones.empty())
        return above;
    for (int p = animation.bones[character_root(animation)].parent; p >= 0;
         p = animation.bones[p].parent)
        above[p] = true;
    return above;
}

} // namespace popup
