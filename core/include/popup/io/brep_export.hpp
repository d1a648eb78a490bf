#pragma once
#include <string>
#include <vector>

#include "popup/model/scaffold.hpp"
#include "popup/simulation/simulate_fold.hpp"

namespace popup {

struct BrepOptions {
    double thickness = 0.0; ///< mm; > 0 makes thickened solids instead of faces
};

/// Planar OCCT faces (or thickened solids) of every patch at `state`, as one compound in BREP
/// text. Throws std::runtime_error when a face fails BRepCheck_Analyzer.
std::string patches_to_brep(const Scaffold& scaffold, const FoldState& state,
                            const BrepOptions& options = {});

/// The same for the design state.
std::string design_to_brep(const Scaffold& scaffold, const BrepOptions& options = {});

} // namespace popup
