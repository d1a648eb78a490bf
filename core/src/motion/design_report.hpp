#pragma once
#include "design_types.hpp"
#include "popup/motion/motion_types.hpp"

namespace popup::motion {

/// The report: eq 6.6 per chain (over all its samples), the vertex-weighted totals, each
/// chain's mapping, status and reason, the reach floors, r.cost (eq 6.5); a warning when the
/// design failed the full simulator's check.
void report_design(const MotionDesign& design, MotionResult& r);

} // namespace popup::motion
