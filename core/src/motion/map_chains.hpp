#pragma once
#include <atomic>

#include "design_types.hpp"
#include "popup/model/cancel_flag.hpp"
#include "popup/motion/motion_types.hpp"

namespace popup::motion {

/// h_max of the floating layers: options.layer_height_max, or 25 mm on an A4 card (210 × 148.5
/// mm per page pair) scaled by √(card area / A4's).
double layer_height_max(const MotionOptions& options);

/// Mapping and parameter estimation (thesis §6.2–6.3): the search's problem on `card`, each
/// chain's candidates (fit_candidates) and its own mapping (best_mapping). Progress to 0.2.
MotionDesign map_chains(const MotionTargets& targets, const MotionOptions& options,
                        const CardParams& card, const CancelFlag* cancel,
                        std::atomic<double>* progress);

} // namespace popup::motion
