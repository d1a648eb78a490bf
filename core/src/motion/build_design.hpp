#pragma once
#include "design_types.hpp"
#include "popup/model/cancel_flag.hpp"
#include "popup/motion/motion_types.hpp"

namespace popup::motion {

/// Build with the library's generators and run the full simulator; a mechanism the
/// generators refuse or that crosses another is made stationary, then taken out.
/// Writes r.scaffold, r.mechanisms, r.valid (and, invalid, the simulator's diagnostics to
/// r.diagnostics) and design.slot_mechanisms. Its value: the seconds the validity checks took;
/// its warnings: the mechanisms dropped. Fails only when the card itself cannot be made.
Result<double> build_design(MotionDesign& design, MotionResult& r, const CancelFlag* cancel);

} // namespace popup::motion
