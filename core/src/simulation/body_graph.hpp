#pragma once
// Internal: patches merged into rigid bodies (glue), hinges between bodies as joints, and the
// independent groups of free bodies that can be solved apart once the base is driven.
#include <vector>

#include "popup/model/result.hpp"
#include "popup/model/scaffold.hpp"

namespace popup {

struct Joint {
    int hinge = 0;  ///< index into Scaffold::hinges
    int body_a = 0; ///< body of hinge.patch_a
    int body_b = 0; ///< body of hinge.patch_b
    Vec3 ends[2];   ///< hinge end points, design state
};

/// A slit between two bodies: both ends must stay in the plane of the body passing through.
struct SlitJoint {
    int slit = 0;                      ///< index into Scaffold::slits
    int body_cut = 0;                  ///< body of the patch the slit is cut in
    int body_through = 0;              ///< body of the patch passing through
    Vec3 ends[2];                      ///< design state
    Vec3 plane_point = Vec3::Zero();   ///< a point of the through patch, design state
    Vec3 plane_normal = Vec3::UnitZ(); ///< its normal, design state
};

struct BodyGraph {
    std::vector<int> body_of_patch; ///< by patch index
    int body_count = 0;
    int ground = -1;                                ///< body index of the ground base patch
    int backdrop = -1;                              ///< body index of the backdrop base patch
    std::vector<Vec3> center;                       ///< design-state centre of each body's vertices
    std::vector<Joint> joints;                      ///< hinges between two bodies, not both base
    std::vector<SlitJoint> slits;                   ///< slits between two bodies, not both base
    std::vector<std::vector<int>> components;       ///< free bodies solved together
    std::vector<std::vector<int>> component_joints; ///< joints touching each component
    std::vector<std::vector<int>> component_slits;  ///< slits touching each component
    std::vector<int> component_of_body;             ///< -1 for base bodies

    bool is_base(int body) const { return body == ground || body == backdrop; }
};

/// Fails when the ground and the backdrop are glued into one body (nothing could fold).
Result<BodyGraph> build_body_graph(const Scaffold& scaffold);

} // namespace popup
