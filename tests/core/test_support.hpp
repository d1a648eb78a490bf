#pragma once
// Scaffold builders with known answers and the invariant checkers every core test reuses.
#include <vector>

#include "popup/model/scaffold.hpp"
#include "popup/simulation/simulate_fold.hpp"

namespace popup::fixtures {

constexpr double kPi = 3.14159265358979323846;
inline double deg(double degrees)
{
    return degrees * kPi / 180.0;
}

/// A card: ground (id 0) x in [0, depth], backdrop (id 1) x in [-depth, 0], y in [0, width],
/// z = 0, design angle 180°.
Scaffold make_card(double width = 200.0, double depth = 140.0);

/// The same card built open at fold angle `theta` (radians): its design angle.
Scaffold make_card_at(double width, double depth, double theta);

/// The core's own card (popup::make_card) for the mechanism generators: base pair "central fold".
Scaffold generator_card(double width, double depth = 140.0);

/// Next free patch id.
int next_patch_id(const Scaffold& scaffold);

/// Symmetric tent fold over y in [y0, y0 + width]: feet hinged on ground/backdrop at distance
/// `foot` from the central fold, slopes of length `slope` meeting at the apex, built at the
/// scaffold's design angle. Returns the ids of the two slopes.
std::vector<int> add_tent_fold(Scaffold& scaffold, double y0, double width, double foot,
                               double slope);

/// Parallelogram step fold over y in [y0, y0 + width], flat at 180°: riser hinged on the ground
/// at x = a (length b), tread hinged on the backdrop at x = -b (length a), meeting at x = a - b.
/// Fold directions are set so the step rises. Returns {riser id, tread id}.
std::vector<int> add_step_fold(Scaffold& scaffold, double y0, double width, double a, double b);

/// V-fold standing at 180°: triangles O-A-P (hinged on the ground along O-A) and O-B-P (on the
/// backdrop along O-B), meeting along O-P. O = (0, y0, 0), A = (r sin α, y0 + r cos α, 0),
/// B mirrored, P = (0, y0 + L cos γ, L sin γ). Returns the two patch ids.
std::vector<int> add_v_fold(Scaffold& scaffold, double y0, double r, double alpha, double length,
                            double gamma);

/// Adds a quad patch (counter-clockwise as given) and returns its id.
int add_quad(Scaffold& scaffold, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
             PatchRole role = PatchRole::support);
void add_hinge(Scaffold& scaffold, int a, int b, const Vec3& from, const Vec3& to,
               FoldDirection direction = FoldDirection::unspecified);

/// Evenly spaced angles (radians) from `from_deg` to `to_deg` inclusive.
std::vector<double> angle_range(double from_deg, double to_deg, int count);

/// Largest hinge residual and edge strain over a sweep.
double max_residual(const FoldSweep& sweep);
double max_strain(const FoldSweep& sweep);

/// World position of a design-state point of patch `id` in `state`.
Vec3 world_point(const Scaffold& scaffold, const FoldState& state, int id, const Vec3& x);

} // namespace popup::fixtures
