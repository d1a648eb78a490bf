#pragma once
#include "popup/motion/design_motion.hpp"

namespace popup::motion {

/// design_motion after the input stage: everything from the chains' target paths on (mapping,
/// parameters, annealing, repair, build, validity, report). `result.targets` is `targets`.
/// Separate so the design can be tested on hand-made paths.
Result<MotionResult> design_from_targets(const MotionTargets& targets, const MotionOptions& options,
                                         const CancelFlag* cancel = nullptr,
                                         std::atomic<double>* progress = nullptr);

/// h_max of the floating layers: options.layer_height_max, or 25 mm on an A4 card (210 × 148.5
/// mm per page pair) scaled by √(card area / A4's).
double layer_height_max(const MotionOptions& options);

} // namespace popup::motion
