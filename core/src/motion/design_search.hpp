#pragma once
#include <atomic>

#include "design_types.hpp"
#include "popup/model/cancel_flag.hpp"
#include "popup/motion/motion_types.hpp"

namespace popup::motion {

/// Simulated annealing from design.state: options.search_chains independent searches on their
/// own threads, the best kept (least collision, then least eq 6.5); then each single chain
/// takes its own fit back where that costs no more, and a moving part that follows its path no
/// closer than printed is printed. Progress 0.2 to 0.85. Returns the iterations run (all
/// searches).
long search_design(MotionDesign& design, const MotionOptions& options, const CancelFlag* cancel,
                   std::atomic<double>* progress);

} // namespace popup::motion
