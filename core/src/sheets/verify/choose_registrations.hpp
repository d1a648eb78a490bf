#pragma once
// Part of phase 2: a symmetric piece fits its drawing several ways; its codes tell which.
#include "verification.hpp"

namespace popup::sheets {

/// Of the ways each piece fits its drawing equally well (a symmetric piece), chooses for every
/// piece the one whose tab codes, glue areas and fold layers agree best with the design.
void choose_registrations(Verification& v);

} // namespace popup::sheets
