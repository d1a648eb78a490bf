#pragma once
#include "popup/model/scaffold.hpp"

namespace popup::fixtures {

/// A valid card with about `patch_count` patches: base plus alternating tent and step folds side
/// by side along the central fold (benchmarks and scaling tests).
Scaffold generated_scaffold(int patch_count);

/// `depth` box folds each standing on the top of the one below (issue 10): one connected
/// mechanism of 9 bodies per box.
Scaffold nested_boxes(int depth);

/// A box whose ends are made of `panel_pairs` stacked strips (issue 10): one mechanism whose
/// bodies grow with the pairs.
Scaffold box_with_panel_pairs(int panel_pairs);

} // namespace popup::fixtures
