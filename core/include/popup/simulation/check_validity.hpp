#pragma once
#include <vector>

#include "popup/model/result.hpp"
#include "popup/model/scaffold.hpp"
#include "popup/simulation/free_motion.hpp"
#include "popup/simulation/simulate_fold.hpp"

namespace popup {

struct ValidityOptions {
    int samples = 181;      ///< fold angles sampled evenly over 0..180°
    double clearance = 0.0; ///< extra gap (mm) two patches must keep, e.g. the paper thickness
    int refine_depth = 6;   ///< bisection levels between samples when two patches come close
    const CancelFlag* cancel = nullptr; ///< set from another thread: the check throws Cancelled
    bool dense_linear_algebra = false;  ///< SimulationOptions::dense_linear_algebra (a baseline)
};

/// A pair of patches passing through each other at one state.
struct Crossing {
    int patch_a = 0;
    int patch_b = 0;
    double angle = 0.0; ///< radians
    double depth = 0.0; ///< mm, how far the shallower patch pokes through the other's plane
};

/// The four verdicts of thesis §4 plus everything that explains them.
struct ValidityReport {
    bool foldable = false;
    bool stable = false;
    bool intersection_free = false;
    bool enclosed = false;
    bool valid() const { return foldable && stable && intersection_free && enclosed; }
    double max_hinge_residual = 0.0; ///< mm, over the sweep
    double max_edge_strain = 0.0;
    double flatness_at_zero = 0.0;   ///< largest |x| of any vertex when closed (mm)
    double locked_at = -1.0;         ///< radians, -1 when the motion reaches 0°
    double model_size = 0.0;         ///< mm
    std::vector<Crossing> crossings; ///< per pair: onset angle and deepest crossing
    Diagnostics diagnostics;
};

ValidityReport check_validity(const Scaffold& scaffold, const ValidityOptions& options = {});

/// Transversal cuts between patches at one state (stacked and hinge-sharing contact excluded).
/// Verdicts use exact predicates (CGAL Epick); `tolerance` (mm) separates touching from crossing.
std::vector<Crossing> find_crossings(const Scaffold& scaffold, const FoldState& state,
                                     double tolerance);

} // namespace popup
