#pragma once
// The fitting pipeline's driver: the stages in order (fit_design.cpp); its data in fit_types.hpp.
#include "popup/fitting/fit_types.hpp"
#include "popup/input/model_mesh.hpp"
#include "popup/model/cancel_flag.hpp"
#include "popup/model/option_field.hpp"
#include "popup/model/result.hpp"

namespace popup {

/// FitOptions' fields in declaration order: name, doc, unit, default (FitOptions{}'s) and the
/// range fit_design accepts (fit_options.cpp); the workbench builds `popup fit`'s flags and the
/// From-model panel from them.
const std::vector<OptionField>& fit_option_fields();

/// The ranges fit_design accepts (fit_option_fields(), and min_part_mm at most a quarter of the
/// card's smaller side); one bad_option error per option outside them, naming it and its range.
Diagnostics check_fit_options(const FitOptions& options);

/// The automatic design of thesis §5.1: align the model, spread pseudo-vertices, fit prisms on
/// base patch pairs by RANSAC, map each to the mechanism of lowest coverage error, refit, and
/// repair or drop what the simulator refuses. Deterministic for a given seed. Bad options give
/// errors naming the option and its range; `cancel` stops it with Cancelled.
Result<FitResult> fit_design(const ModelMesh& model, const FitOptions& options,
                             const CancelFlag* cancel = nullptr);

} // namespace popup
