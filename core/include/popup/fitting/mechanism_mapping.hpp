#pragma once
#include <string>
#include <vector>

#include "popup/fitting/prism_ransac.hpp"
#include "popup/fitting/surface_samples.hpp"
#include "popup/mechanisms/designed_mechanism.hpp"

namespace popup {

/// One primitive turned into a mechanism (thesis Table 5.1): a box, step, tent or v-fold named
/// B1, T1, S1, V1... per kind in host order, with what its generator needs.
struct MechanismPlan : DesignedMechanism {
    int prism = -1;              ///< index into the fitted prisms
    int parent = -1;             ///< index of the plan it stands on, -1 for the card
    double principal_area = 0.0; ///< faces of the prism its patches lie on (Fig 5.3)
    double face_area = 0.0;      ///< all faces of the prism
    int samples = 0;             ///< samples the search assigned to the prism (its inliers)
    double sample_distance = 0;  ///< their mean distance to its patches at the design state (mm)
    double coverage_error() const { return face_area > 0 ? 1.0 - principal_area / face_area : 1; }
};

/// What a prism may become on its host (Table 5.1 restricted to what the generators build:
/// a box fold and a tent need a flat host, a step is a prism only on a right-angle host).
std::vector<MechanismKind> mechanism_options(const Prism& prism, const PrismHost& host);

/// The mechanism of `kind` for `prism` on `host`: its parameters and covered areas.
MechanismPlan plan_mechanism(MechanismKind kind, const Prism& prism, const PrismHost& host);

/// Table 5.1 mapping, exhaustive over the combinations: every prism takes one of its options,
/// and a prism standing on another's top or side needs that one to be a box fold. The
/// combination whose patches at the design state lie nearest the prisms' own samples wins: the
/// lowest sum over every sample the search assigned to a prism (`fit.owner`) of its distance to
/// the nearest patch of that prism's mechanism (mechanism_patches.hpp); ties, as when no sample
/// is assigned, go to the lower coverage error (eq. 5.1, over all prisms) (docs/MATH.md,
/// "Mapping by distance"). Plans come in host order, named per type. Prisms whose host cannot
/// be a box in any combination are left out (their index is in `unmapped`).
/// `fit.owner` needs one entry per sample of `samples`, each -1 or a prism's index
/// (std::invalid_argument naming the count or the entry otherwise).
struct Mapping {
    std::vector<MechanismPlan> plans;
    double coverage_error = 1.0;
    double sample_distance = 0.0; ///< mean over the mapped prisms' samples (mm)
    std::vector<int> unmapped;
};
Mapping map_mechanisms(const RansacResult& fit, const SurfaceSamples& samples);

/// Eq. 5.1 over the given plans: 1 − Σ principal areas / Σ face areas.
double coverage_error(const std::vector<MechanismPlan>& plans);

/// §4.2.2 refit: box folds on one hinge whose swept intervals overlap lose the end panels that
/// face each other (trimmed), and, when their boxes themselves come too close, the later one is
/// shortened. Returns one line per change: (mechanism, what was done and why).
/// A box is not shortened below `min_part` (mm): it keeps the overlap, which the validity repair
/// then resolves by dropping one of the two.
std::vector<std::pair<std::string, std::string>>
refit_for_foldability(std::vector<MechanismPlan>& plans, double min_part = 0.0);

/// Moves every plan's parameters `margin` (mm) inside its generator's ranges: offset and width
/// inside the host's length, runs, feet and depths below the host's depths. The fitted values
/// otherwise land exactly on a bound (a step as long as its box), where a rebuild from rounded
/// values (FreeCAD's properties) falls outside. Plans must come hosts first.
void keep_inside_ranges(std::vector<MechanismPlan>& plans, double card_width, double card_depth,
                        double margin);

} // namespace popup
