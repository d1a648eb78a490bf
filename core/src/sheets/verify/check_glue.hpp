#pragma once
// Phase 3 of verify_sheets, the tabs and glue areas: creases, codes and the joints they hold.
#include "verification.hpp"

namespace popup::sheets {

/// The glue tabs and areas against the design's joints between pieces: every drawn line that is
/// no fold is a tab's crease on a design joint, drawn on the right layer, whose code names one
/// glue area on the patch the design joins it to; every area carries a tab's code and every joint
/// between pieces has its tab. Fills the drawn tabs and, by code, the areas they go onto.
void check_glue(Verification& v);

} // namespace popup::sheets
