#pragma once
#include <string>

#include "popup/model/result.hpp"
#include "popup/sheets/sheet_layout.hpp"

namespace popup {

/// The sheet set as the JSON document of docs/SHEET_FORMAT.md.
std::string sheet_set_to_json(const SheetSet& sheets);

/// The sheet set a JSON document of docs/SHEET_FORMAT.md holds (what sheet_set_to_json wrote, a
/// CuttingSheet's stored layout, a sheets.json), checked as it is read: a missing or malformed
/// field gives ok == false and one bad_field diagnostic naming its key path ("sheet set:
/// pieces[2].cut missing"), bad JSON a bad_json one. Writing the result gives the same text.
/// Fields that the drawings do not need, or that later versions added, may be absent and take
/// their defaults (docs/SHEET_FORMAT.md, "Reading a sheet set"); a patch without `to_sheet`
/// (written before it existed) has FlatPatch::has_to_sheet() false.
Result<SheetSet> sheet_set_from_json(const std::string& text);

} // namespace popup
