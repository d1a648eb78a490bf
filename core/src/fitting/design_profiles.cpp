#include "design_profiles.hpp"

#include <algorithm>
#include <utility>

#include "popup/fitting/fit_depth_layers.hpp"
#include "popup/fitting/fit_outlines.hpp"

namespace popup {

std::optional<Diagnostics> profile_design(const ModelMesh& model, const FitOptions& options,
                                          const std::map<std::string, BasePatchPair>& pairs,
                                          const CancelFlag* cancel, StageTimer& timer, FitResult& r)
{
    OutlineOutcome outlined = fit_outlines_for(model, r.model_to_card, r.scaffold, r.mechanisms,
                                               cancel, options.min_part_mm);
    r.scaffold = std::move(outlined.scaffold);
    r.profiles = std::move(outlined.profiles);
    for (const FitRepair& repair : outlined.dropped)
        r.repairs.push_back(repair);
    timer.lap("outlines");
    // §5.1.3: box fronts and tops in depth layers, each kept only when it helps.
    if (options.depth_layers) {
        DepthLayerFitOptions lo;
        lo.min_part_mm = options.min_part_mm;
        lo.seed = options.seed;
        lo.range_margin = 1e-6 * std::max(options.card.width, options.card.depth);
        Result<DepthLayerOutcome> tried =
            fit_depth_layers(model, r.model_to_card, r.scaffold, r.mechanisms, pairs, lo, cancel);
        if (!tried.ok) // its options come from checked FitOptions: not expected
            return tried.diagnostics;
        for (const Diagnostic& d : tried.diagnostics)
            r.diagnostics.push_back(d);
        DepthLayerOutcome& layered = tried.value;
        r.scaffold = std::move(layered.scaffold);
        for (FittedMechanism& m : layered.mechanisms)
            r.mechanisms.push_back(std::move(m));
        for (FittedProfile& p : layered.profiles)
            r.profiles.push_back(std::move(p));
        for (FitRepair& repair : layered.repairs)
            r.repairs.push_back(std::move(repair));
        r.depth_layers = std::move(layered.layers);
        timer.lap("depth_layers");
    }
    return std::nullopt;
}

} // namespace popup
