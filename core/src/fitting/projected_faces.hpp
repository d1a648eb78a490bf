#pragma once
// Internal: a model's triangles seen along a patch's normal, and the exact union of such
// projections: what silhouettes and depth layers are made of.
#include <optional>
#include <string>
#include <vector>

#include "popup/fitting/silhouette_types.hpp"
#include "popup/input/model_mesh.hpp"
#include "popup/model/profile.hpp"

namespace popup {

struct ProjectedFace {
    Loop2 polygon;      ///< in the profile frame (a triangle, or up to 5 corners once cut)
    double depth = 0.0; ///< of its centroid, mm along the patch normal
    double area = 0.0;  ///< projected area, mm²
};

/// The frame carried by a rigid motion (the patch posed), or itself.
ProfileFrame posed(const ProfileFrame& frame, const std::optional<Pose>& pose);

/// Every triangle cut to the depth window [near, far] and projected into the frame; faces whose
/// projection has no area (seen edge-on) are left out. `facing_only` keeps the triangles whose
/// normal has a positive component along the frame's normal.
std::vector<ProjectedFace> project_faces(const ModelMesh& model, const ProfileFrame& frame,
                                         std::optional<double> near, std::optional<double> far,
                                         bool facing_only);

/// The union of the faces' polygons (Clipper, non-zero fill), its largest piece as the profile.
Silhouette unite_faces(const std::vector<const ProjectedFace*>& faces, const std::string& name);

} // namespace popup
