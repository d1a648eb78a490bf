#pragma once
#include <optional>
#include <vector>

#include "popup/fitting/silhouette.hpp"

namespace popup {

struct DepthLayerOptions {
    /// Two faces belong to different layers when their depths differ by more than this (mm);
    /// <= 0: 2 % of the model's bounding-box diagonal.
    double min_gap = 0.0;
    int max_layers = 4;              ///< at most this many layers: the largest gaps split
    double min_area_fraction = 0.02; ///< layers with less of the facing area merge into the next
    std::optional<Pose> pose;        ///< the patch's pose, as SilhouetteOptions::pose
};

/// One layer of a patch's model faces: a silhouette at one depth.
struct DepthLayer {
    double depth_near = 0.0; ///< mm along the patch normal: the layer's faces span these depths
    double depth_far = 0.0;
    double depth = 0.0; ///< area-weighted mean depth of its faces (where to put its patch)
    Silhouette silhouette;
};

/// The faces of `model` that face patch `patch_id`'s printed side (a box fold's front or top),
/// clustered by depth along its normal, each cluster's silhouette in the profile frame; the
/// nearest to the viewer (largest depth) first. Method (docs/MATH.md, Depth layers): each face's
/// depth is its centroid's; sorted by depth, the sequence splits at every gap wider than
/// min_gap, at most max_layers - 1 splits (the widest); a layer with less than
/// min_area_fraction of the facing area joins its nearer neighbour in depth. 1-D gap clustering
/// is exact and deterministic (no seeds), and flat faces of a blocky model form tight groups.
Result<std::vector<DepthLayer>> depth_layers(const ModelMesh& model, const Scaffold& scaffold,
                                             int patch_id, const DepthLayerOptions& options = {});

} // namespace popup
