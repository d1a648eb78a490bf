#pragma once
// Internal: continuation of one component of free bodies along the fold angle, from the design
// state or a state already on the branch: predictor steps, Newton correction, step halving
// until the motion locks, and the branch's limit at a closed or fully open end.
#include "fold_solver.hpp"

namespace popup {

/// Continuation of one component from the design state toward a sequence of angles.
class ComponentTrack {
public:
    /// Starts at `start` (every body's pose at `angle`); `at_design` when that is the design
    /// state, where flat folds take their hinted branch on the first step.
    ComponentTrack(const FoldSolver& solver, int component, double angle,
                   const Configuration& start, bool at_design);
    /// Advances to `target`; false when the motion locks before it (locked_angle() says where).
    bool advance_to(double target);
    const Configuration& configuration() const { return current_; }
    double angle() const { return theta_; }
    double locked_angle() const { return locked_; }
    bool branch_followed() const { return branch_ok_; }

private:
    bool try_step(double next);
    /// At a closed or fully open end where the hinges line up the constraints are tangent and
    /// pin the pose only to the square root of round-off; take the branch's limit instead.
    void take_limit_at_end();

    const FoldSolver& solver_;
    int component_;
    double theta_;
    Configuration current_;
    Configuration previous_;
    Configuration guess_;
    double previous_step_ = 0.0;
    double step_;
    bool at_design_ = true;
    bool branch_ok_ = true;
    double locked_ = -1.0;
};

} // namespace popup
