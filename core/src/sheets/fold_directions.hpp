#pragma once
// Mountain or valley: which way a fold bends, seen from the printed side. A fold may be flat at
// the design state (a box's front V at 180°), so the card is sampled on its way closed too.
#include <vector>

#include "local_piece.hpp"
#include "popup/simulation/simulate_fold.hpp"

namespace popup::sheets {

/// From the design angle to closed in `count` even steps, plus 150°, 90° and 30° where they fall
/// between: every fold shows its bend in one of them.
std::vector<double> sweep_angles(const Scaffold& s, int count);

/// Patch poses (scaffold order) at the design state and at a few fold angles toward closed.
struct BendSamples {
    std::vector<std::vector<Pose>> states;
};

/// The design state plus every state of a sweep of the design toward closed.
BendSamples sample_bends(const Scaffold& s, const std::vector<FoldState>& sweep);

/// Which way patch b turns away from patch a about a hinge through `on_hinge` (design state),
/// seen from `normal_a`, a's printed side: valley when b comes toward that side. `bent` is false
/// when the two stay flat in every sample (then the result is a valley).
FoldDirection bend_direction(const Scaffold& s, const BendSamples& samples, int a,
                             const Vec3& normal_a, int b, const Vec3& on_hinge, bool& bent);

/// Which way a glue tab's crease folds, seen from the printed side of the carrier patch: the tab
/// turns off the carrier onto the target patch and lies there on the side of the joint where its
/// glue area is. `glue_point` is a point of that area in the target piece's flat frame. A joint
/// inside the target's paper leaves room on both sides of it, so the target's centre (which
/// bend_direction looks at) cannot tell. `bent` is false when carrier and target stay in one
/// plane throughout (then a valley).
FoldDirection tab_direction(const Scaffold& s, const BendSamples& samples, const Hinge& h,
                            const LocalPiece& carrier, int carrier_patch, const LocalPiece& target,
                            int target_patch, const Vec2& glue_point, bool& bent);

/// The direction a fold line of hinge h is drawn with on a's piece, seen from `printed_a` (a's
/// printed side): how b bends away from a on the way closed or, for a fold that never bends, the
/// design's own word turned to the printed side. `unspecified` is set when neither says (then a
/// valley).
FoldDirection drawn_direction(const Scaffold& s, const BendSamples& samples, const Hinge& h,
                              const Vec3& printed_a, bool& unspecified);

} // namespace popup::sheets
