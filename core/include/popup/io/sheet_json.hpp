#pragma once
#include <string>

#include "popup/sheets/sheet_layout.hpp"

namespace popup {

/// The sheet set as the JSON document of docs/SHEET_FORMAT.md.
std::string sheet_set_to_json(const SheetSet& sheets);

} // namespace popup
