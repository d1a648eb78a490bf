#pragma once
#include <vector>

#include "popup/sheets/sheet_set.hpp"

namespace popup::sheets {

/// The order pieces are glued in: the card (the piece holding the ground) first, then outward
/// breadth-first over tab and glue joints, so that every piece is glued only to pieces placed
/// before it; ties keep the scaffold's order. Pieces not joined to the card come last, each with an
/// error.
std::vector<int> assembly_order(const Scaffold& s, const std::vector<std::vector<int>>& pieces,
                                Diagnostics& diagnostics);

} // namespace popup::sheets
