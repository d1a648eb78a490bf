#pragma once
// The fitting pipeline's driver: the stages in order (fit_design.cpp); its data in fit_types.hpp.
#include "popup/fitting/fit_types.hpp"
#include "popup/input/model_mesh.hpp"
#include "popup/model/cancel_flag.hpp"
#include "popup/model/result.hpp"

namespace popup {

/// The ranges fit_design accepts; one bad_option error per option outside them, naming it.
Diagnostics check_fit_options(const FitOptions& options);

/// The automatic design of thesis §5.1: align the model, spread pseudo-vertices, fit prisms on
/// base patch pairs by RANSAC, map each to the mechanism of lowest coverage error, refit, and
/// repair or drop what the simulator refuses. Deterministic for a given seed. Bad options give
/// errors naming the option and its range; `cancel` stops it with Cancelled.
Result<FitResult> fit_design(const ModelMesh& model, const FitOptions& options,
                             const CancelFlag* cancel = nullptr);

} // namespace popup
