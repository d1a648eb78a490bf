#pragma once
#include <map>
#include <string>

#include "popup/model/cancel_flag.hpp"
#include "popup/sheets/sheet_set.hpp"

namespace popup {

/// How to verify cutting files against their design.
struct VerifyOptions {
    std::map<std::string, PrintedSide> printed_sides; ///< as the sheets were written with
    int angles = 13; ///< fold angles sampled from the design angle to closed, ≥ 2
    const CancelFlag* cancel = nullptr; ///< set from another thread: verify throws Cancelled
};

} // namespace popup
