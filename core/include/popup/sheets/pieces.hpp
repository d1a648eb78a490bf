#pragma once
#include <vector>

#include "popup/model/scaffold.hpp"

namespace popup {

/// The sheets of paper a scaffold is made of: patches joined by folds (JointKind::fold) share a
/// piece; tab joints and glue join different pieces. Patch ids, in scaffold order within each
/// piece; pieces ordered by their first patch (the card first).
std::vector<std::vector<int>> cut_pieces(const Scaffold& scaffold);

} // namespace popup
