#pragma once
#include <array>
#include <string>
#include <vector>

#include "popup/mechanisms/floating_layer.hpp"
#include "popup/mechanisms/mechanism.hpp"
#include "popup/model/card.hpp"
#include "popup/model/designed_card.hpp"

namespace popup::motion {

/// The mappings of thesis Table 6.1, plus the floating layer for a chain that does not move.
enum class MotionKind { vertical, diagonal, horizontal, rotation, stationary };
constexpr int motion_kind_count = 5;
const char* to_string(MotionKind kind); ///< "vertical", ..., "stationary" (ChainReport::mapping)

/// How the annealing steps a parameter (thesis §6.4.3): angles by 10°, lengths by 1/20 of the
/// character's diagonal, positions (the anchor along the fold and across it) by 1/50.
enum class ParameterRole { angle, length, position };

struct ParameterInfo {
    const char* name; ///< the library's params-struct field
    ParameterRole role;
};

constexpr int max_parameters = 8;

/// One motion mechanism on the card's central fold, its parameters in a flat array so the
/// annealing can step any of them. Layouts (the library's params fields, mm and radians):
/// - vertical   (add_vertical_translation): offset, side, height, wall_angle
/// - diagonal   (add_v_fold, spine standing, + add_step_fold on its wings): offset, run,
///               hinge_angle, spine, step_offset, step_width, run_ground, run_backdrop
/// - horizontal (add_horizontal_translation): offset, width, run_ground, run_backdrop, reach
/// - rotation   (add_rotation_arm): offset, spine, run, arm, hinge — hinge 0: on the central
///               fold; ±s: on the side pair (+ ground, − backdrop) of a floating layer with
///               supports s from the fold, as wide as the spine, from offset, its height
///               rotation_layer_height (thesis §4.3.4, last paragraph: a rotation off the fold)
/// - stationary (add_floating_layer): offset, width, height, support, overhang, anchor (the
///               platform point, across the fold, that carries the part)
struct MotionMechanism {
    MotionKind kind = MotionKind::stationary;
    std::array<double, max_parameters> p{};
};

int parameter_count(MotionKind kind);
ParameterInfo parameter_info(MotionKind kind, int index);
/// The parameters that shape this mechanism: a rotation on the central fold (hinge 0) has no
/// layer, so its hinge is not stepped (a small hinge is no layer either: it is infeasible).
int active_parameter_count(const MotionMechanism& m);

/// A rotation standing on a floating layer's side pair (hinge != 0).
bool rotation_off_fold(const MotionMechanism& m);
/// The floating layer an off-fold rotation stands on: supports |hinge|, width spine, from
/// offset, no overhang, height rotation_layer_height.
FloatingLayerParams rotation_layer(const MotionMechanism& m);
/// The layer's height: the lowest the arm's checks allow (Run < height, Arm <= height) with
/// 1 mm to spare, at least the shortest glued crease. The tip's path does not depend on it.
double rotation_layer_height(double run, double arm);

/// The mechanism's moving point (the end effector it carries) in the card frame when the card
/// is open at theta: the rotation arm's tip, the v-box's front top corner, the extruding patch's
/// far edge (middle), the step's nose on the v-fold's wings (middle), a platform point. Closed
/// forms of the library (rotation_arm_tip, v_box_front_corner, horizontal_translation_tip,
/// v_fold_wings + step_nose); its (x, y) is what the viewer sees (thesis §6: the projection on
/// the card plane).
Vec3 mechanism_point(const MotionMechanism& m, double theta);

/// Where a rotation arm carries a part placed at `open` (card x, y) on its arm's wing when the
/// card is open: the point of the wing's plane there, moved rigidly with the wing O-S-P to fold
/// angle theta (a merged arm carries each chain's part in its own place; docs/DESIGN.md). At the
/// tip's open point it is mechanism_point.
Vec3 rotation_carried_point(const MotionMechanism& m, const Vec2& open, double theta);

/// One rigid convex piece of a mechanism's paper at some fold angle: every point of the piece
/// is a convex combination of `vertices` (a patch, or the part of a patch on one side of a
/// crease line through it), listed along its outline (the vertical's top halves end with both
/// roots of their back corner). `side` says which side of the card's bisecting plane x = 0 the
/// piece keeps to at every fold angle (derived per kind in docs/MATH.md, "Tight collision
/// volumes"): +1 never at x < 0 (the ground's half), −1 never at x > 0, 0 either. Pieces on
/// opposite sides can touch only on that plane, so they never cross.
struct MechanismPart {
    std::vector<Vec3> vertices;
    int side = 0;
};

/// The mechanism's patches at theta in closed form, one entry per piece, in an order and count
/// that do not depend on theta (for the collision volumes). The vertical's top halves carry both
/// roots of their back corner (conservative).
std::vector<MechanismPart> mechanism_parts(const MotionMechanism& m, double theta);
/// The same into `out`, reusing its storage (no allocation once it has held them).
void mechanism_parts(const MotionMechanism& m, double theta, std::vector<MechanismPart>& out);

/// Every patch vertex of the mechanism at theta, in closed form: the pieces' vertices together
/// (a vertex shared by two pieces appears once per piece).
std::vector<Vec3> mechanism_vertices(const MotionMechanism& m, double theta);

/// Height of the mechanism's carrying patch above the card at 180° (mm): H of eq 6.7.
double mechanism_height(const MotionMechanism& m);

/// The shortest crease the default cutting sheets can glue (their narrowest tab, ≈ 11.1 mm), as
/// FitOptions::min_part_mm: infeasibility refuses a mechanism with a shorter glued crease, which
/// nobody could assemble (popup animate's sheets failed on such designs).
double shortest_crease();

/// Empty when the generators accept the parameters on `card`; otherwise why not (the first
/// failed range). Mirrors the add_* checks, with a margin so the simulator's build succeeds, and
/// refuses glued creases shorter than shortest_crease().
std::string infeasibility(const MotionMechanism& m, const CardParams& card);

/// infeasibility(m, card).empty(), without writing the reason (the search asks per move).
bool feasible(const MotionMechanism& m, const CardParams& card);

/// False for a diagonal whose v-fold wings, one piece unfolded about their spine with a glue
/// tab on each side, do not fit the card's open sheet (W × 2D, which PopUp sizes to the paper);
/// true for every other kind.
bool diagonal_wings_fit(const MotionMechanism& m, const CardParams& card);

/// Builds the mechanism on the card's central fold with the library's generators; appends its
/// FittedMechanism rows (host before what it carries). Names: `name` (and `name`_step for the
/// diagonal's step fold).
Result<std::vector<MechanismParts>> build_mechanism(Scaffold& scaffold, const BasePatchPair& host,
                                                    const MotionMechanism& m,
                                                    const std::string& name,
                                                    std::vector<FittedMechanism>& rows);

} // namespace popup::motion
