#pragma once
// Phase 5 of verify_sheets: the card made from the drawing folded against the design.
#include <map>

#include "verification.hpp"

namespace popup::sheets {

/// The card re-made from the drawing (every patch its drawn face, every hinge its drawn line,
/// placed by `from_sheet`) driven through the simulator and compared with the design, patch by
/// patch, at every angle checked. A card that does not simulate is an error, or a warning when
/// it follows from errors found before.
RoundTrip compare_round_trip(Verification& v, const std::map<int, Pose>& from_sheet);

} // namespace popup::sheets
