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

/// Per bone: the distance from its parent's origin to its own at the first frame (0 for a root).
std::vector<double> bone_lengths(const Animation& animation)
{
    const std::vector<Eigen::Isometry3d> global = forward_kinematics(animation, 0.0);
    std::vector<double> length(animation.bones.size(), 0.0);
    for (size_t b = 0; b < animation.bones.size(); ++b)
        if (animation.bones[b].parent >= 0)
            length[b] =
                (global[b].translation() - global[animation.bones[b].parent].translation()).norm();
    return length;
}

struct Working {
    std::vector<int> bones;
    int parent = -1;
    std::vector<int> children;
    std::vector<int> vertices;
    double amount = 0.0; ///< vertices, or bone length without a mesh
    std::vector<std::string> pruned;
    bool alive = true;
};

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
    const std::vector<double> length = skinned ? std::vector<double>(n) : bone_lengths(animation);
    auto amount_of = [&](int b) { return skinned ? double(by_bone[b].size()) : length[b]; };

    // A chain starts at a root or at a child of a branching bone, and runs down while its bone
    // has exactly one child.
    std::vector<Working> chains;
    std::vector<int> chain_of(n, -1);
    for (int b = 0; b < n; ++b) {
        const int parent = animation.bones[b].parent;
        const bool starts = parent < 0 || children[parent].size() != 1;
        if (!starts)
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
            chain.amount += amount_of(bone);
        }
        if (chain.parent >= 0)
            chains[chain.parent].children.push_back(int(chains.size()));
        chains.push_back(std::move(chain));
    }
    // Bones are in parent-first order, so a chain's parent was made before it.

    // Prune: a leaf chain below τp × the mean bone amount goes into its parent, repeatedly
    // (a parent whose children were all pruned may become a small leaf itself); the last chain
    // made is looked at first, so the order is the bones' and the outcome deterministic.
    double total = 0.0;
    for (int b = 0; b < n; ++b)
        total += amount_of(b);
    const double threshold = options.prune_fraction * total / n;
    for (bool changed = true; changed;) {
        changed = false;
        for (int c = int(chains.size()) - 1; c >= 0; --c) {
            Working& chain = chains[c];
            if (!chain.alive || chain.parent < 0 || !chain.children.empty() ||
                !(chain.amount < threshold))
                continue;
            Working& parent = chains[chain.parent];
            parent.vertices.insert(parent.vertices.end(), chain.vertices.begin(),
                                   chain.vertices.end());
            parent.amount += chain.amount;
            parent.pruned.push_back(animation.bones[chain.bones.back()].name);
            parent.pruned.insert(parent.pruned.end(), chain.pruned.begin(), chain.pruned.end());
            parent.children.erase(std::find(parent.children.begin(), parent.children.end(), c));
            chain.alive = false;
            changed = true;
        }
    }
    // A chain left with one child chain no longer branches there: the two are one chain.
    for (int c = 0; c < int(chains.size()); ++c) {
        Working& chain = chains[c];
        while (chain.alive && chain.children.size() == 1) {
            Working& child = chains[chain.children[0]];
            chain.bones.insert(chain.bones.end(), child.bones.begin(), child.bones.end());
            chain.vertices.insert(chain.vertices.end(), child.vertices.begin(),
                                  child.vertices.end());
            chain.amount += child.amount;
            chain.pruned.insert(chain.pruned.end(), child.pruned.begin(), child.pruned.end());
            chain.children = child.children;
            for (int grandchild : chain.children)
                chains[grandchild].parent = c;
            child.alive = false;
        }
    }

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

} // namespace popup
