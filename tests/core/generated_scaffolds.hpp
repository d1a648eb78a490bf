#pragma once
#include "popup/model/scaffold.hpp"

namespace popup::fixtures {

/// A valid card with about `patch_count` patches: base plus alternating tent and step folds side
/// by side along the central fold (benchmarks and scaling tests).
Scaffold generated_scaffold(int patch_count);

} // namespace popup::fixtures
