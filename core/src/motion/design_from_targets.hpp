#pragma once
#include <atomic>

#include "popup/model/cancel_flag.hpp"
#include "popup/motion/motion_types.hpp"

namespace popup::motion {

/// design_motion after the input stage: everything from the chains' target paths on (mapping,
/// parameters, annealing, repair, build, validity, report). `result.targets` is `targets`.
/// Separate so the design can be tested on hand-made paths.
Result<MotionResult> design_from_targets(const MotionTargets& targets, const MotionOptions& options,
                                         const CancelFlag* cancel = nullptr,
                                         std::atomic<double>* progress = nullptr);

} // namespace popup::motion
