#pragma once
#include <string>
#include <vector>

#include "popup/motion/animation.hpp"

namespace popup {

struct ChainOptions {
    /// τp (thesis §6.1): a leaf chain weighing less than this fraction of the mean bone weight
    /// (skinned vertices per bone; bone length without a mesh) is pruned into its parent.
    double prune_fraction = 0.09;
    /// A leaf chain reaching less than this fraction of the character's size (the largest side
    /// of its first frame's joints' box) is part of the chain it hangs from: fingers, thumbs,
    /// face bones, ears (docs/MATH.md, "Chains a person would name"); unless such chains are
    /// all that moves. 0 keeps them (the thesis's τp alone).
    double min_chain_size = 0.15;
};

/// A single chain of the bone tree (thesis §6.1): bones from the one after a branching (or the
/// root) to the next branching or leaf.
struct LinkageChain {
    std::string name;       ///< its last bone's name (the end effector)
    std::vector<int> bones; ///< root to tip
    int parent_chain = -1;  ///< the chain its first bone hangs from
    /// Mesh vertices assigned to it (largest weight), with those of chains pruned into it.
    std::vector<int> vertices;
    double weight = 0.0; ///< v_j: its share of the vertices (of bone length without a mesh); Σ = 1
    std::vector<std::string> pruned; ///< names of the chains merged into it by pruning
    double reach = 0.0; ///< its bones' lengths, with the longest chain pruned into it (file units)
};

/// Splits the skeleton into chains and prunes small leaf chains, deterministically (bone order).
std::vector<LinkageChain> linkage_chains(const Animation& animation,
                                         const ChainOptions& options = {});

} // namespace popup
