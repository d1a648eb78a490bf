#pragma once
#include "motion_mechanism.hpp"

// The search steps a mechanism's parameters by index: the annealing's moves and crossover, the
// Nelder–Mead polish, the finite check. Index k is the k-th row of its kind's table of named
// fields (parameter_table.cpp), in this order, the search's (another order makes other designs):
// - vertical:   offset, side, height, wall_angle
// - diagonal:   the v-fold's offset, run, hinge_angle, spine; its step's offset (step_offset),
//               width (step_width), run_ground, run_backdrop
// - horizontal: offset, width, run_ground, run_backdrop, reach
// - rotation:   offset, spine, run, arm, hinge
// - stationary: offset, width, height, support, overhang, anchor
// Everything else reads and writes the parameters by name.

namespace popup::motion {

int parameter_count(MotionKind kind);
/// The name and role of parameter `index` (in [0, parameter_count(kind))) of the kind.
ParameterInfo parameter_info(MotionKind kind, int index);
/// The parameters that shape this mechanism: a rotation on the central fold (hinge 0) has no
/// layer, so its hinge is not stepped (a small hinge is no layer either: it is infeasible).
int active_parameter_count(const MotionMechanism& m);

/// Parameter `index` (in [0, parameter_count(m.kind()))) of m: the named field
/// parameter_info(m.kind(), index).name of its kind's params.
double& parameter(MotionMechanism& m, int index);
double parameter(const MotionMechanism& m, int index);

} // namespace popup::motion
