#pragma once
// Internal: the model's large flat walls across a direction, where a fold may stand (docs/MATH.md,
// "Which way is up, and where the fold goes").
#include <vector>

#include "popup/input/model_mesh.hpp"

namespace popup {

/// Planes across `x` on which the model has a large flat wall inside its extent (not at either
/// end): where a box fold's backbone can stand on the model's own wall.
/// Returns their positions (x · point), largest wall first, at most `count`, each carrying at
/// least `min_area`.
std::vector<double> inner_walls(const ModelMesh& model, const Vec3& x, double min_area, int count);

/// Planes across `x` midway between a wall facing -x and a wall facing +x behind it, the two
/// overlapping along `y` (the fold) over half the shorter: the middle of a block of the model
/// that does not lie on the fold through the model's middle (the wing of an L, a tower behind
/// a lower block), where a box fold centred on it can stand. The whole model's middle is left
/// out (the fold is there already). Returns their positions (x · point), the pair whose
/// smaller wall is largest first, at most `count`, both walls carrying at least `min_area`.
std::vector<double> block_centres(const ModelMesh& model, const Vec3& x, const Vec3& y,
                                  double min_area, int count);

} // namespace popup
