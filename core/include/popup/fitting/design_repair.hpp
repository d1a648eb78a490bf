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
    Scaffold scaffold;              ///< the card and the kept mechanisms at the design state
    std::vector<bool> kept;         ///< per plan: built and kept
    std::vector<FitRepair> repairs; ///< one "dropped" per plan left out, saying why
    Diagnostics warnings;           ///< one mechanism_dropped warning per plan left out
    ValidityReport report;          ///< the last full check (default when nothing was checked)
    bool valid = false;             ///< something was kept and the last full check passed
    /// The base patch pairs of `scaffold` by name: the central fold and every pair the kept
    /// mechanisms offer (what a mechanism added later stands on).
    std::map<std::string, BasePatchPair> pairs;
};

/// Builds the card and the plans in host order (each on the pair its host offered), then
/// repeats until the full check_validity passes or nothing is left: a plan its generator refuses,
/// one whose host is gone, one of two whose sweeps along a hinge overlap (§4.2.2, the later), or
/// the one the failed check's error diagnostics point at (the most nested owner of a named
/// patch, else the last plan) is dropped, with everything standing on it.
RepairOutcome build_until_valid(const CardParams& card, const std::vector<MechanismPlan>& plans,
                                const CancelFlag* cancel = nullptr);

} // namespace popup
