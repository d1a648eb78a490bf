#pragma once
#include <string>

#include "popup/model/result.hpp"
#include "popup/model/scaffold.hpp"

namespace popup {

/// Version of the JSON design format written by `scaffold_to_json` (docs/DESIGN_FORMAT.md).
constexpr int kDesignFormatVersion = 1;

/// Parses a design file's text. Bad JSON or a bad field gives ok == false and a diagnostic that
/// names the field (for example `patches[2].outline[3]`).
Result<Scaffold> scaffold_from_json(const std::string& text);
std::string scaffold_to_json(const Scaffold& scaffold);

Result<Scaffold> load_scaffold(const std::string& path);
/// Throws std::runtime_error when the file cannot be written.
void save_scaffold(const Scaffold& scaffold, const std::string& path);

} // namespace popup
