#pragma once
#include <string>
#include <vector>

#include "motion_mechanism.hpp"
#include "popup/mechanisms/designed_card.hpp"
#include "popup/mechanisms/mechanism.hpp"

namespace popup::motion {

/// Builds the mechanism on the card's central fold with the library's generators; appends its
/// FittedMechanism rows (host before what it carries). Names: `name` (and `name`_step for the
/// diagonal's step fold).
Result<std::vector<MechanismParts>> build_mechanism(Scaffold& scaffold, const BasePatchPair& host,
                                                    const MotionMechanism& m,
                                                    const std::string& name,
                                                    std::vector<FittedMechanism>& rows);

} // namespace popup::motion
