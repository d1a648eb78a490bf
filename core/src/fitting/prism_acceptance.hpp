#pragma once
// Internal: the rules a candidate prism must meet to be accepted: what its host can carry,
// thick enough for glue tabs, inside the model's height, sharing no volume with an accepted one.
#include <vector>

#include <Eigen/Geometry>

#include "popup/fitting/prism_types.hpp"

namespace popup::prism_search {

/// Keeps a prism inside what its host can carry and at least `min_part` thick; false if it
/// cannot.
bool fit_host(const PrismHost& h, Prism& m, double eps, double min_part);

/// True when a corner of the prism stands above the highest sample by more than ε: a prism
/// lies inside the model (a tent fitted to two near-parallel slopes would otherwise put its
/// apex far above it). Only the height: across and along, a box grown to the thinnest part
/// may reach past a thin model.
bool outside_model(const Prism& m, const PrismHost& h, const Eigen::AlignedBox3d& model,
                   double eps);

/// True when the prism's box overlaps one of `taken` by more than ε along every axis: two
/// primitives may touch (one stands on the other) but not share volume, or their mechanisms
/// would.
bool overlaps(const Prism& m, const PrismHost& h, const std::vector<Eigen::AlignedBox3d>& taken,
              double eps);

/// Shortens a prism grown along its hinge back to the accepted ones it reached: each of `taken`
/// it overlaps wholly before `seed_a0` or wholly after `seed_a1` (the stretch its drawn samples
/// span) ends it there. Past an accepted box the same top and sides belong to that box's
/// part (a low block whose front lines up with a taller one's); growing into it would make
/// the candidate overlap and be lost.
void stop_at_taken(Prism& m, const PrismHost& h, const std::vector<Eigen::AlignedBox3d>& taken,
                   double seed_a0, double seed_a1, double eps);

} // namespace popup::prism_search
