#pragma once
// Internal: the three ways a repair changes a planned mechanism (thesis §4.2.2: make it fit
// rather than lose it), each carried through what stands on it: scaled about its place, cut
// along its host's hinge, moved to another pair at the same place along the hinge. Each returns
// the whole design with the change, or nothing when the change does not apply.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "popup/fitting/mechanism_mapping.hpp"

namespace popup {

/// A changed design and the plans standing on the changed one that changed with it.
struct PlanEdit {
    std::vector<MechanismPlan> plans;
    std::vector<int> carried;
};

/// Plan `i` scaled by `factor` about the middle of its extent along the hinge (its place) and the
/// hinge itself: every length but its offset. What stands on it scales with it, offsets too.
/// Nothing when a length at least `min_part` (mm) would fall below it.
std::optional<PlanEdit> scale_about_place(const std::vector<MechanismPlan>& plans, size_t i,
                                          double factor, double min_part);

/// Plan `i` (a kind with a width) cut to [lo, hi] along its host's hinge (mm from the host's
/// origin). Plans standing on it keep their place along the hinge and lose what lies past its
/// new ends, unless that leaves them shorter than `min_part` (then they keep their width, and
/// their own repair sees to them). Nothing when `i` would be shorter than `min_part`.
std::optional<PlanEdit> cut_along_hinge(const std::vector<MechanismPlan>& plans, size_t i,
                                        double lo, double hi, double min_part, double margin);

/// Plan `i` moved from pair `from` to pair `to` at the same place along the hinge, standing on
/// plan `new_parent` (-1 for the card). Nothing unless the two hinges are parallel, `to` opens
/// as `from` does, and the plan fits on `to` as it is (within `margin` of its ends and depths).
std::optional<PlanEdit> move_to_pair(const std::vector<MechanismPlan>& plans, size_t i,
                                     const BasePatchPair& from, const BasePatchPair& to,
                                     int new_parent, double margin);

/// The plans standing on plan `i`, directly or not, in plan order.
std::vector<int> standing_on(const std::vector<MechanismPlan>& plans, size_t i);

/// The fields of a plan that differ in `after`, by their FreeCAD property:
/// "Width 40 → 30 mm, Front yes → no".
std::string describe_changes(const MechanismPlan& before, const MechanismPlan& after);

} // namespace popup
