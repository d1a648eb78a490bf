#pragma once
// Internal: fit_design's outline stages (§5.1.3) on a valid design: the principal parts cut to
// the model's silhouette, then box fronts and tops in depth layers.
#include <map>
#include <optional>
#include <string>

#include "popup/fitting/fit_types.hpp"
#include "popup/input/model_mesh.hpp"
#include "popup/model/base_patch_pair.hpp"
#include "popup/model/cancel_flag.hpp"
#include "stage_timer.hpp"

namespace popup {

/// fit_outlines_for on `r`'s valid design, then (options.depth_layers) fit_depth_layers on the
/// pairs the built mechanisms offer; what they keep and report goes into `r`; laps "outlines"
/// and "depth_layers". The depth-layer stage's findings when it refuses (its options come from
/// checked FitOptions: not expected).
std::optional<Diagnostics> profile_design(const ModelMesh& model, const FitOptions& options,
                                          const std::map<std::string, BasePatchPair>& pairs,
                                          const CancelFlag* cancel, StageTimer& timer,
                                          FitResult& r);

} // namespace popup
