#pragma once
// Internal: fit_design's mechanism stage: the primitives mapped to mechanisms (Table 5.1),
// refitted (§4.2.2) and built until the simulator accepts them, or the model's bulk as one box
// fold instead; then what the result reports of them.
#include <vector>

#include "popup/fitting/design_repair.hpp"
#include "popup/fitting/fit_types.hpp"
#include "popup/fitting/mechanism_mapping.hpp"
#include "popup/fitting/prism_ransac.hpp"
#include "popup/fitting/surface_samples.hpp"
#include "stage_timer.hpp"

namespace popup {

/// What the mechanism stage made of the primitives.
struct BuiltMechanisms {
    RansacResult fit;                 ///< the primitives mapped: the search's, or the bulk box
    std::vector<MechanismPlan> plans; ///< one per mapped primitive, as repaired
    RepairOutcome outcome;            ///< what was kept of them, and the last validity check
};

/// Table 5.1 mapping by coverage error, the §4.2.2 refit, then validity: build, check
/// everything, repair or drop what the simulator refuses, check again (build_until_valid). The
/// model's bulk as one box fold (bulk_prism.hpp) replaces that design when it stands up from the
/// page (the samples lie half as far from it as from the page alone): instead of nothing when
/// nothing the search found survives, and instead of a valid design the samples lie twice as far
/// from on average (docs/DESIGN.md). Repairs and warnings go to `r`; laps "map".
BuiltMechanisms build_mechanisms(RansacResult fit, const SurfaceSamples& samples,
                                 const FitOptions& options, const CancelFlag* cancel,
                                 StageTimer& timer, FitResult& r);

/// The built design into `r`: its scaffold, validity, the kept mechanisms and their coverage
/// error.
void record_mechanisms(const BuiltMechanisms& built, FitResult& r);

/// Primitives for previews, named by the pairs their mechanisms offer where mapped.
std::vector<FittedPrimitive> preview_primitives(const RansacResult& fit,
                                                const std::vector<MechanismPlan>& plans);

} // namespace popup
