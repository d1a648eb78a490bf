#pragma once
// The simulator's data: a fold state, a sweep of them and the options that drive it. Below
// simulate_fold (its driver) so that the solver and the checks need not include the driver.
#include <vector>

#include "popup/model/cancel_flag.hpp"
#include "popup/model/scaffold.hpp"

namespace popup {

/// Poses of every patch at one fold angle.
struct FoldState {
    double angle = 0.0;          ///< radians
    std::vector<Pose> poses;     ///< one per scaffold patch, in scaffold order
    double hinge_residual = 0.0; ///< largest hinge end mismatch or slit end off-plane (mm)
    double edge_strain = 0.0;    ///< largest relative change of a patch edge length
};

struct FoldSweep {
    std::vector<FoldState> states; ///< one per requested angle, in the order requested
    bool complete = false;         ///< every requested angle was reached
    double locked_at = -1.0;       ///< angle (radians) where the motion stopped, if it did
};

struct SimulationOptions {
    double max_step = 0.0174532925199432958; ///< largest continuation step (1°)
    double min_step = 1e-7;                  ///< below this the motion is declared locked
    int max_newton_iterations = 60;
    const CancelFlag* cancel = nullptr; ///< checked before each continuation run (throws Cancelled)
    /// Solve every connected mechanism with dense normal equations (a dense Cholesky per Newton
    /// step, an SVD or pivoted LDLᵀ rank test), as before the sparse solver. By default a
    /// mechanism of 6 free bodies or more is solved with a sparse factorisation instead: the
    /// same Levenberg–Marquardt steps and tolerances (docs/MATH.md, Solver). Kept as the
    /// benchmarks' same-process baseline and for comparing the two.
    bool dense_linear_algebra = false;
};

} // namespace popup
