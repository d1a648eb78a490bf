#pragma once
// Internal: patches merged into rigid bodies (glue), hinges between bodies as joints, and the
// independent groups of free bodies that can be solved apart once the base is driven.
#include <vector>

#include "popup/result.hpp"
#include "popup/scaffold.hpp"

namespace popup {

struct Joint {
    int hinge = 0;  ///< index into Scaffold::hinges
    int body_a = 0; ///< body of hinge.patch_a
    int body_b = 0; ///< body of hinge.patch_b
    Vec3 ends[2];   ///< hinge end points, design state
};

struct BodyGraph {
    std::vector<int> body_of_patch; ///< by patch index
    int body_count = 0;
    int ground = -1;                                ///< body index of the ground base patch
    int backdrop = -1;                              ///< body index of the backdrop base patch
    std::vector<Vec3> center;                       ///< design-state centre of each body's vertices
    std::vector<Joint> joints;                      ///< hinges between two bodies, not both base
    std::vector<std::vector<int>> components;       ///< free bodies solved together
    std::vector<std::vector<int>> component_joints; ///< joints touching each component
    std::vector<int> component_of_body;             ///< -1 for base bodies

    bool is_base(int body) const { return body == ground || body == backdrop; }
};

/// Fails when the ground and the backdrop are glued into one body (nothing could fold).
Result<BodyGraph> build_body_graph(const Scaffold& scaffold);

} // namespace popup
