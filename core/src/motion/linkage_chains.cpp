// Linkage segmentation (thesis §6.1): single chains of the bone tree, small leaf chains pruned.
#include <algorithm>
#include <numeric>

#include "popup/motion/linkage_chains.hpp"

namespace popup {

namespace {

/// Per bone: the mesh vertices whose largest skin weight is that bone's (ties: the lower index).
std::vector<std::vector<int>> vertices_by_bone(const Animation& animation)
{
    std::vector<std::vector<int>> by_bone(animation.bones.size());
    for (size_t v = 0; v < animation.skin.size(); ++v) {
        int best = -1;
        double best_weight = -1.0;
        for (const auto& [bone, weight] : animation.skin[v])
            if (weight > best_weight || (weight == best_weight && bone < best)) {
                best = bone;
                best_weight = weight;
            }
        if (best >= 0 && best < int(by_bone.size()))
            by_bone[best].push_back(int(v));
    }
    return by_bone;
}

/// Per bone: the distance from its parent's origin to its own in the pose `global` (the first
/// frame; 0 for a root).
std::vector<double> bone_lengths(const Animation& animation,
                                 const std::vector<Eigen::Isometry3d>& global)
{
    std::vector<double> length(animation.bones.size(), 0.0);
    for (size_t b = 0; b < animation.bones.size(); ++b)
        if (animation.bones[b].parent >= 0)
            length[b] =
                (global[b].translation() - global[animation.bones[b].parent].translation()).norm();
    return length;
}

/// A chain moves when its tip travels this fraction of its reach against the bone it hangs
/// from: a curling finger (a third), not a suit's jitter on a still leg (under 2 %).
constexpr double kMoves = 0.1;

/// The largest side of the box of the character's joints (not the still nodes above it) in the
/// pose `global` (the first frame; file units).
double character_size(const Animation& animation, const std::vector<Eigen::Isometry3d>& global)
{
    const std::vector<bool> above = above_character(animation);
    Eigen::AlignedBox3d box;
    for (std::size_t b = 0; b < global.size(); ++b)
        if (!above[b])
            box.extend(global[b].translation());
    return box.isEmpty() ? 0.0 : box.sizes().maxCoeff();
}

struct Working {
    std::vector<int> bones;
    int parent = -1;
    std::vector<int> children;
    std::vector<int> vertices;
    double amount = 0.0; ///< vertices, or bone length without a mesh
    double length = 0.0; ///< its own bones' lengths
    double reach = 0.0;  ///< length, with the longest chain pruned into it
    std::vector<std::string> pruned;
    bool alive = true;
};

/// Chains start at a root or at a child of a branching bone and run down while their bone has
/// exactly one child. Bones are in parent-first order, so a chain's parent is made before it.
std::vector<Working> split_into_chains(const Animation& animation,
                                       const std::vector<std::vector<int>>& children,
                                       const std::vector<std::vector<int>>& by_bone,
                                       const std::vector<double>& amount,
                                       const std::vector<double>& length)
{
    std::vector<Working> chains;
    std::vector<int> chain_of(animation.bones.size(), -1);
    for (int b = 0; b < int(animation.bones.size()); ++b) {
        const int parent = animation.bones[b].parent;
        if (parent >= 0 && children[parent].size() == 1)
            continue;
        Working chain;
        chain.parent = parent >= 0 ? chain_of[parent] : -1;
        for (int at = b;;) {
            chain.bones.push_back(at);
            chain_of[at] = int(chains.size());
            if (children[at].size() != 1)
                break;
            at = children[at][0];
        }
        for (int bone : chain.bones) {
            chain.vertices.insert(chain.vertices.end(), by_bone[bone].begin(), by_bone[bone].end());
            chain.amount += amount[bone];
            chain.length += length[bone];
        }
        chain.reach = chain.length;
        if (chain.parent >= 0)
            chains[chain.parent].children.push_back(int(chains.size()));
        chains.push_back(std::move(chain));
    }
    return chains;
}

/// Leaf chain c becomes part of the chain it hangs from.
void prune_into_parent(std::vector<Working>& chains, int c, const Animation& animation)
{
    Working& chain = chains[c];
    Working& parent = chains[chain.parent];
    parent.vertices.insert(parent.vertices.end(), chain.vertices.begin(), chain.vertices.end());
    parent.amount += chain.amount;
    parent.reach = std::max(parent.reach, parent.length + chain.reach);
    parent.pruned.push_back(animation.bones[chain.bones.back()].name);
    parent.pruned.insert(parent.pruned.end(), chain.pruned.begin(), chain.pruned.end());
    parent.children.erase(std::find(parent.children.begin(), parent.children.end(), c));
    chain.alive = false;
}

/// A chain left with one child chain no longer branches there: the two are one chain.
void merge_lone_children(std::vector<Working>& chains)
{
    for (int c = 0; c < int(chains.size()); ++c) {
        Working& chain = chains[c];
        while (chain.alive && chain.children.size() == 1) {
            Working& child = chains[chain.children[0]];
            chain.bones.insert(chain.bones.end(), child.bones.begin(), child.bones.end());
            chain.vertices.insert(chain.vertices.end(), child.vertices.begin(),
                                  child.vertices.end());
            chain.amount += child.amount;
            chain.reach = std::max(chain.reach, chain.length + child.reach);
            chain.length += child.length;
            chain.pruned.insert(chain.pruned.end(), child.pruned.begin(), child.pruned.end());
            chain.children = child.children;
            for (int grandchild : chain.children)
                chains[grandchild].parent = c;
            child.alive = false;
        }
    }
}

/// Thesis τp: a leaf chain below `threshold` goes into its parent, repeatedly (a parent whose
/// children were all pruned may become a small leaf itself); the last chain made is looked at
/// first, so the order is the bones' and the outcome deterministic.
void prune_light(std::vector<Working>& chains, double threshold, const Animation& animation)
{
    for (bool changed = true; changed;) {
        changed = false;
        for (int c = int(chains.size()) - 1; c >= 0; --c) {
            const Working& chain = chains[c];
            if (chain.alive && chain.parent >= 0 && chain.children.empty() &&
                chain.amount < threshold) {
                prune_into_parent(chains, c, animation);
                changed = true;
            }
        }
    }
}

/// The shortest leaf chain reaching under `min_reach` (not `kept`) goes into its parent, one at
/// a time, so that a parent whose small children all went is measured with its longest one: a
/// head whose face bones and end went reaches as far as its end did. Then a chain left with one
/// child continues into it.
void prune_short(std::vector<Working>& chains, double min_reach, const std::vector<bool>& kept,
                 const Animation& animation)
{
    for (;;) {
        int shortest = -1;
        for (int c = 0; c < int(chains.size()); ++c) {
            const Working& chain = chains[c];
            if (chain.alive && chain.parent >= 0 && chain.children.empty() && !kept[c] &&
                chain.reach < min_reach && (shortest < 0 || chain.reach < chains[shortest].reach))
                shortest = c;
        }
        if (shortest < 0)
            break;
        prune_into_parent(chains, shortest, animation);
    }
    merge_lone_children(chains);
}

using Poses = std::vector<std::vector<Eigen::Isometry3d>>;

/// The skeleton at up to 200 frames spread over the take: enough to see what moves.
Poses sampled_poses(const Animation& animation)
{
    const int frames = animation.frames();
    const int step = std::max(1, frames / 200);
    Poses poses;
    for (int f = 0; f < frames; f += step)
        poses.push_back(forward_kinematics(animation, double(f)));
    return poses;
}

/// Per chain: whether its tip moves against the bone it hangs from by more than kMoves of its
/// reach over `poses` (sampled_poses); a root chain never does.
std::vector<bool> chains_moving(const Animation& animation, const Poses& poses,
                                const std::vector<Working>& chains)
{
    std::vector<bool> moving(chains.size(), false);
    for (size_t c = 0; c < chains.size(); ++c) {
        const int from = animation.bones[chains[c].bones.front()].parent;
        if (!chains[c].alive || from < 0)
            continue;
        const int tip = chains[c].bones.back();
        const Vec3 first = poses[0][from].inverse() * poses[0][tip].translation();
        for (const auto& pose : poses)
            if ((pose[from].inverse() * pose[tip].translation() - first).norm() >
                kMoves * chains[c].reach)
                moving[c] = true;
    }
    return moving;
}

/// The short-chain pass (ChainOptions::min_chain_size), unless it would leave nothing that
/// moves while short chains do (a take where only the fingers move): those are then kept.
void prune_short_unless_all_that_moves(std::vector<Working>& chains, double min_reach,
                                       const Animation& animation)
{
    const Poses poses = sampled_poses(animation);
    const std::vector<bool> moved = chains_moving(animation, poses, chains);
    std::vector<Working> pruned = chains;
    prune_short(pruned, min_reach, std::vector<bool>(chains.size(), false), animation);
    const std::vector<bool> still_moving = chains_moving(animation, poses, pruned);
    bool left_moving = false, lost_moving = false;
    for (size_t c = 0; c < chains.size(); ++c) {
        left_moving = left_moving || (pruned[c].alive && still_moving[c]);
        lost_moving = lost_moving || (moved[c] && !pruned[c].alive);
    }
    if (!left_moving && lost_moving) {
        pruned = chains;
        prune_short(pruned, min_reach, moved, animation);
    }
    chains = std::move(pruned);
}

std::vector<LinkageChain> finished(const std::vector<Working>& chains, const Animation& animation)
{
    std::vector<int> index(chains.size(), -1);
    std::vector<LinkageChain> out;
    for (size_t c = 0; c < chains.size(); ++c)
        if (chains[c].alive) {
            index[c] = int(out.size());
            LinkageChain chain;
            chain.name = animation.bones[chains[c].bones.back()].name;
            chain.bones = chains[c].bones;
            chain.parent_chain = chains[c].parent; // remapped below
            chain.vertices = chains[c].vertices;
            std::sort(chain.vertices.begin(), chain.vertices.end());
            chain.weight = chains[c].amount;
            chain.reach = chains[c].reach;
            chain.pruned = chains[c].pruned;
            out.push_back(std::move(chain));
        }
    for (LinkageChain& chain : out)
        if (chain.parent_chain >= 0)
            chain.parent_chain = index[chain.parent_chain];
    // Weights v_j share the whole; with nothing to share (no vertices, zero lengths), equally.
    double sum = 0.0;
    for (const LinkageChain& chain : out)
        sum += chain.weight;
    for (LinkageChain& chain : out)
        chain.weight = sum > 0.0 ? chain.weight / sum : 1.0 / double(out.size());
    return out;
}

} // namespace

std::vector<LinkageChain> linkage_chains(const Animation& animation, const ChainOptions& options)
{
    const int n = int(animation.bones.size());
    if (n == 0)
        return {};
    std::vector<std::vector<int>> children(n);
    for (int b = 0; b < n; ++b)
        if (animation.bones[b].parent >= 0)
            children[animation.bones[b].parent].push_back(b);

    const bool skinned = !animation.skin.empty();
    const std::vector<std::vector<int>> by_bone =
        skinned ? vertices_by_bone(animation) : std::vector<std::vector<int>>(n);
    const std::vector<Eigen::Isometry3d> first = forward_kinematics(animation, 0.0);
    const std::vector<double> length = bone_lengths(animation, first);
    std::vector<double> amount = length;
    if (skinned)
        for (int b = 0; b < n; ++b)
            amount[b] = double(by_bone[b].size());

    std::vector<Working> chains = split_into_chains(animation, children, by_bone, amount, length);
    double total = 0.0;
    for (int b = 0; b < n; ++b)
        total += amount[b];
    prune_light(chains, options.prune_fraction * total / n, animation);
    merge_lone_children(chains);
    if (options.min_chain_size > 0.0)
        prune_short_unless_all_that_moves(
            chains, options.min_chain_size * character_size(animation, first), animation);
    return finished(chains, animation);
}

} // namespace popup
