#pragma once
#include <atomic>

#include "popup/model/cancel_flag.hpp"
#include "popup/motion/motion_types.hpp"

namespace popup {

/// The automatic animated pop-up of thesis ch. 6: chains and target paths, mapping (Table 6.1,
/// lowest eq 6.6 error), parameter estimation, simulated annealing with collision volumes,
/// merging, stationary fallback, outlines, and the full validity check. Deterministic for a
/// seed. `progress`, when given, rises from 0 to 1; `cancel` stops it with Cancelled.
Result<MotionResult> design_motion(const Animation& animation, const MotionOptions& options,
                                   const CancelFlag* cancel = nullptr,
                                   std::atomic<double>* progress = nullptr);

} // namespace popup
