#pragma once
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "popup/model/base_patch_pair.hpp"
#include "popup/model/result.hpp"
#include "popup/model/scaffold.hpp"

namespace popup {

/// What a mechanism added to a scaffold: its patches (ids, in order) and the base patch pairs it
/// offers for nesting further mechanisms.
struct MechanismParts {
    std::string name;
    std::vector<int> patches;
    std::vector<BasePatchPair> offered;
    std::string host;        ///< name of the base patch pair it stands on
    double sweep_from = 0.0; ///< interval along the host hinge it occupies at any fold angle
    double sweep_to = 0.0;   ///< (mm from the host's origin; thesis §4.2.2)
};

/// The thesis's sufficient placement condition (§4.2.2) as a fast pre-check: two mechanisms on
/// the same host whose swept intervals along its hinge overlap may collide. Returns the pairs
/// of mechanism names that do. The simulator has the last word.
std::vector<std::pair<std::string, std::string>>
placement_conflicts(const std::vector<MechanismParts>& mechanisms);

/// Placement shared by every mechanism: where along the host hinge it starts and how wide it is.
struct Placement1D {
    double offset = 0.0; ///< from the host pair's origin along its hinge (mm)
    double width = 40.0; ///< extent along the hinge (mm)
};

/// Checks that [offset, offset + width] fits the host hinge; adds a named error otherwise.
void check_placement(const std::string& mechanism, const BasePatchPair& host, const Placement1D& p,
                     Diagnostics& errors);

/// Adds a named error unless the host is open flat (180°) at the design state.
void check_flat_host(const std::string& mechanism, const BasePatchPair& host,
                     const std::string& kind, Diagnostics& errors);

/// Adds a named error unless 0 < value < limit (value <= limit when `inclusive`), where limit is
/// the depth of the host's `side` ("ground" or "backdrop").
void check_run(Diagnostics& errors, const std::string& mechanism, const std::string& parameter,
               double value, double limit, const std::string& side, bool inclusive = false);

/// Adds a named error for each positive length (parameter name, mm) below shortest_fold: a part
/// that small passes its own range but vanishes (nested mechanisms whose fitted defaults shrink
/// with each host).
void check_part_sizes(const Scaffold& scaffold, const std::string& mechanism,
                      std::initializer_list<std::pair<const char*, double>> lengths,
                      Diagnostics& errors);

} // namespace popup
