#pragma once
#include <map>
#include <string>
#include <vector>

#include "popup/fitting/fit_types.hpp"
#include "popup/input/model_mesh.hpp"
#include "popup/model/base_patch_pair.hpp"
#include "popup/model/cancel_flag.hpp"

namespace popup {

/// What the depth-layer stage may build and how it judges a layer.
struct DepthLayerFitOptions {
    double min_part_mm = 0.0;  ///< narrowest glued part: runs, rises, widths and depths (mm)
    int metric_samples = 4000; ///< model samples for the mean distance (fit_metrics)
    std::uint64_t seed = 1;    ///< seeds those samples (the same for every comparison)
    /// Parameters stay this far inside their generator's ranges (mm), as keep_inside_ranges
    /// keeps the fitted plans; <= 0: a millionth of the model's diagonal on the card.
    double range_margin = 0.0;
};

/// What the depth-layer stage did.
struct DepthLayerOutcome {
    Scaffold scaffold;                       ///< the design with the kept layers built and cut
    std::vector<FittedMechanism> mechanisms; ///< the nested mechanisms kept, in build order
    std::vector<FittedProfile> profiles;     ///< their viewer-facing parts' outlines
    std::vector<FittedDepthLayer> layers;    ///< every layer standing proud of its face
    std::vector<FitRepair> repairs;          ///< one "layer kept" / "layer dropped" per layer
    double mean_before_mm = 0.0;             ///< model-to-pop-up mean distance without layers
    double mean_after_mm = 0.0;              ///< with the kept layers
};

/// Thesis §5.1.3, depth layers: the front (L, on the viewer's side), back (R) and top (TG and
/// TB) faces of every box fold in `mechanisms` are clustered by depth (depth_layers); every layer
/// standing proud of the box's face becomes a nested mechanism on the box, its part parallel to
/// the face cut to the layer's silhouette: a front or back layer a step fold on
/// "<box>.side_ground" / "<box>.side_backdrop" (run along the page = the layer's depth, rise up
/// the wall = its top), a top layer a box fold on "<box>.top" (its top at the layer's height).
/// Layers are tried nearest first, box by box; one is kept only while the design (`scaffold`,
/// valid at 180°, with its profiles applied) stays valid under the full check_validity and
/// fit_metrics' model-to-pop-up mean distance drops (docs/DESIGN.md, "Depth layers built as
/// nested mechanisms"). `pairs` are the base patch pairs the built mechanisms offer
/// (RepairOutcome::pairs). `model` is in model units, `model_to_card` places it. Bad options are
/// bad_option errors naming the option and its range; when the design cannot be measured
/// (fit_metrics refuses it) the design comes back unchanged with fit_metrics' findings as
/// warnings.
Result<DepthLayerOutcome>
fit_depth_layers(const ModelMesh& model, const Eigen::Matrix4d& model_to_card,
                 const Scaffold& scaffold, const std::vector<FittedMechanism>& mechanisms,
                 const std::map<std::string, BasePatchPair>& pairs,
                 const DepthLayerFitOptions& options, const CancelFlag* cancel = nullptr);

} // namespace popup
