#pragma once
#include "popup/model/result.hpp"
#include "popup/model/scaffold.hpp"
#include "popup/sheets/sheet_set.hpp"

namespace popup {

/// Unfolds the scaffold into pieces, adds glue tabs and their targets, classifies the folds,
/// labels everything, orders the assembly, nests the pieces onto sheets and re-folds the result
/// to check it. Fails (with named diagnostics) on bad options, a scaffold that does not validate
/// or simulate, a piece that cannot be flattened, or a piece larger than the paper.
Result<SheetSet> layout_sheets(const Scaffold& scaffold, const SheetOptions& options);

} // namespace popup
