#pragma once
// Internal: what build_until_valid tries on the mechanism a trial names before dropping it, in
// the order a maker would (thesis §4.2.2: make the mechanisms fit rather than lose them):
// 1. shrunk about its place, in a few steps, no part below min_part_mm;
// 2. trimmed along its hinge away from the mechanism it runs into, or to its host's length;
// 3. re-hosted on another pair at the same place along the hinge (where its dropped host
//    stood, the central fold, another box's top), when its host is gone or it collides there.
// A plan whose host is gone can only be re-hosted.
#include <map>
#include <string>
#include <vector>

#include "design_trial.hpp"

namespace popup {

/// One repair to try: the whole design with it, and what it changes in a maker's words.
struct RepairAttempt {
    std::vector<MechanismPlan> plans;
    std::string action; ///< "shrunk", "trimmed", "re-hosted"
    std::string what;   ///< "shrunk to 90 % about its middle"
    std::string change; ///< `what` with the fields it changes: "... (Width 40 → 36 mm, ...)"
    std::vector<int> carried; ///< plans standing on it that changed with it
};

struct RepairLimits {
    double min_part = 0.0; ///< no length at least this (mm) is shrunk or trimmed below it
    double margin = 0.0;   ///< how far inside a host's ends and depths a repair keeps (mm)
};

/// The repairs for `trial.culprit`, in the order above. `seen` holds every pair any trial built
/// (a dropped host's place).
std::vector<RepairAttempt> repair_attempts(const std::vector<MechanismPlan>& plans,
                                           const DesignTrial& trial,
                                           const std::map<std::string, BasePatchPair>& seen,
                                           const RepairLimits& limits);

} // namespace popup
