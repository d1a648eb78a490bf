#pragma once
#include <map>
#include <string>
#include <vector>

#include "popup/fitting/mechanism_mapping.hpp"
#include "popup/mechanisms/designed_card.hpp"
#include "popup/model/card.hpp"
#include "popup/model/scaffold.hpp"
#include "popup/simulation/check_validity.hpp"

namespace popup {

/// What is left of a planned design after the simulator had its say.
struct RepairOutcome {
    Scaffold scaffold;                ///< the card and the kept mechanisms at the design state
    std::vector<MechanismPlan> plans; ///< the plans as repaired (shrunk, trimmed, re-hosted)
    std::vector<bool> kept;           ///< per plan: built and kept
    /// Per plan changed or left out, the last thing done to it: "shrunk", "trimmed",
    /// "re-hosted" or "dropped", saying what changed and why.
    std::vector<FitRepair> repairs;
    Diagnostics warnings;  ///< one mechanism_dropped warning per plan left out
    ValidityReport report; ///< the last full check (default when nothing was checked)
    bool valid = false;    ///< something was kept and the last full check passed
    /// The base patch pairs of `scaffold` by name: the central fold and every pair the kept
    /// mechanisms offer (what a mechanism added later stands on).
    std::map<std::string, BasePatchPair> pairs;
};

/// Builds the card and the plans in host order (each on the pair its host offered), then
/// repeats until the full check_validity passes or nothing is left. The culprit is the first
/// plan its generator refuses or whose host is gone, else the later of two whose sweeps along a
/// hinge overlap (§4.2.2), else the one the failed check's error diagnostics point at (the most
/// nested owner of a named patch, else the last plan). It is repaired before it is dropped
/// (mechanism_repairs.hpp): shrunk about its place (no length of at least `min_part` mm below
/// it), trimmed along its hinge away from what it runs into, re-hosted on another pair at the
/// same place along the hinge; the first that no longer implicates it is kept, with what stands
/// on it. Repairs are capped per design; what stood on a dropped plan is re-hosted or dropped in
/// turn.
RepairOutcome build_until_valid(const CardParams& card, std::vector<MechanismPlan> plans,
                                double min_part = 0.0, const CancelFlag* cancel = nullptr);

} // namespace popup
