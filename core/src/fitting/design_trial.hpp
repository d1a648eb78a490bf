#pragma once
// Internal: one attempt at a planned design. The card and the plans are built in host order,
// then the first thing that keeps the design from being valid is named (a generator's refusal,
// two sweeps overlapping along a hinge, the simulator's errors) with the plans it implicates.
// build_until_valid repairs or drops what a trial names and tries again.
#include <map>
#include <string>
#include <vector>

#include "popup/fitting/mechanism_mapping.hpp"
#include "popup/model/card.hpp"
#include "popup/model/scaffold.hpp"
#include "popup/simulation/check_validity.hpp"

namespace popup {

/// The scaffold of some plans: card first, then each kept plan on the pair its host offered.
struct BuiltPlans {
    Scaffold scaffold;
    std::vector<MechanismParts> parts;          ///< per plan; empty name when not built
    std::vector<std::string> refused;           ///< per plan: why it was not built, or empty
    std::vector<bool> host_missing;             ///< per plan: refused because its host is not there
    std::map<std::string, BasePatchPair> pairs; ///< offered by the card and the built plans
};

BuiltPlans build_plans(const CardParams& card, const std::vector<MechanismPlan>& plans,
                       const std::vector<bool>& keep);

/// What keeps a trial's design from being valid, in the order it is looked for.
enum class TrialFailure {
    none,         ///< valid, or nothing was built
    host_missing, ///< a plan's host pair is not in the design (the plan offering it is gone)
    refused,      ///< a generator refused a plan's parameters
    swept_into,   ///< two plans on one hinge sweep into each other as the card closes (§4.2.2)
    invalid,      ///< the full check_validity failed
};

struct DesignTrial {
    BuiltPlans built;
    TrialFailure failure = TrialFailure::none;
    int culprit = -1; ///< the plan to repair or drop: the first refused, the later of the first
                      ///< two sweeping into each other, the most nested owner of a patch the
                      ///< check's errors name (else the last built)
    int other = -1;   ///< the plan it runs into, when one is named (-1: the card or nothing)
    std::string why;  ///< the failure in a maker's words
    /// Per plan: refused, in a pair sweeping into each other, or owning a patch an error of the
    /// full check names. A repair of the culprit holds when the next trial no longer implicates
    /// it.
    std::vector<bool> implicated;
    ValidityReport report; ///< the full check; default when it was not reached
    bool checked = false;  ///< the full check ran (nothing refused, no sweeps overlapping)
};

/// Builds the kept plans and looks for the first failure. The full check_validity runs only when
/// every kept plan was built and no two sweep into each other.
DesignTrial try_design(const CardParams& card, const std::vector<MechanismPlan>& plans,
                       const std::vector<bool>& keep, const CancelFlag* cancel);

} // namespace popup
