#pragma once
#include "design_types.hpp"

namespace popup::motion {

/// The search's start (thesis §6.4): each chain on its own mapping's mechanism (a chain no
/// mechanism fits is left out, with its reason); the moving chains' mechanisms first, then a still
/// chain's floating layer only where it takes no room from them, else its part starts printed on
/// the page (the search may still lift it). Sets design.state.
void start_layout(MotionDesign& design);

} // namespace popup::motion
