#include "component_track.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace popup {

ComponentTrack::ComponentTrack(const FoldSolver& solver, int component, double angle,
                               const Configuration& start, bool at_design)
    : solver_(solver), component_(component), theta_(angle), current_(start), previous_(start),
      guess_(start), step_(solver.options().max_step), at_design_(at_design)
{
    solver.drive_base(theta_, current_);
}

bool ComponentTrack::advance_to(double target)
{
    const SimulationOptions& options = solver_.options();
    while (theta_ != target) {
        const double gap = target - theta_;
        const double next = std::abs(gap) <= step_ ? target : theta_ + std::copysign(step_, gap);
        if (try_step(next)) {
            step_ = std::min(step_ * 1.5, options.max_step);
            if (theta_ == target && (target == 0.0 || target == M_PI) &&
                solver_.singular(component_, current_))
                take_limit_at_end();
        } else {
            step_ *= 0.5;
            if (step_ < options.min_step) {
                locked_ = theta_;
                return false;
            }
        }
    }
    return true;
}

void ComponentTrack::take_limit_at_end()
{
    if (previous_step_ == 0.0)
        return;
    // Cubic extrapolation from four states 1e-3 rad apart on the branch (error ~ h⁴ L).
    const double h = 1e-3;
    const double weights[4] = {4.0, -6.0, 4.0, -1.0};
    const auto& bodies = solver_.graph().components[component_];
    std::vector<Configuration> nodes;
    for (int k = 1; k <= 4; ++k) {
        const double t = k * h / std::abs(previous_step_); // fraction of the way back
        Configuration q = current_;
        for (int b : bodies) {
            const Mat3 turn = previous_[b].rotation * current_[b].rotation.transpose();
            q[b].rotation = rotation_exp(t * rotation_log(turn)) * current_[b].rotation;
            q[b].position += t * (previous_[b].position - current_[b].position);
        }
        solver_.drive_base(theta_ - std::copysign(k * h, previous_step_), q);
        if (!solver_.correct(component_, q, {}, solver_.options().max_newton_iterations, true))
            return;
        nodes.push_back(std::move(q));
    }
    for (int b : bodies) {
        Vec3 turn = Vec3::Zero(), position = Vec3::Zero();
        for (int k = 0; k < 4; ++k) {
            turn +=
                weights[k] * rotation_log(nodes[k][b].rotation * nodes[0][b].rotation.transpose());
            position += weights[k] * nodes[k][b].position;
        }
        current_[b].rotation = rotation_exp(turn) * nodes[0][b].rotation;
        current_[b].position = position;
    }
}

bool ComponentTrack::try_step(double next)
{
    const double h = next - theta_;
    const auto& bodies = solver_.graph().components[component_];
    // Only this component's bodies and the base matter: copy those, not the whole card.
    Configuration& guess = guess_;
    for (int b : bodies)
        guess[b] = current_[b];
    solver_.drive_base(next, guess);
    if (!at_design_ && previous_step_ != 0.0) {
        // Secant predictor along the branch already followed.
        const double s = h / previous_step_;
        for (int b : bodies) {
            const Mat3 turn = current_[b].rotation * previous_[b].rotation.transpose();
            guess[b].rotation = rotation_exp(s * rotation_log(turn)) * current_[b].rotation;
            guess[b].position =
                current_[b].position + s * (current_[b].position - previous_[b].position);
        }
    }
    static const std::vector<BranchHint> none;
    const auto& hints = at_design_ ? solver_.hints(component_) : none;
    if (!solver_.correct(component_, guess, hints, solver_.options().max_newton_iterations))
        return false;
    for (int b : bodies) {
        const Mat3 turn = guess[b].rotation * current_[b].rotation.transpose();
        if (Eigen::AngleAxisd(turn).angle() > 0.5)
            return false; // a jump this large in one step means another branch
    }
    if (at_design_)
        for (const BranchHint& hint : hints)
            if (hint.sign * solver_.fold_sine(hint, guess) <= 0.0)
                branch_ok_ = false;
    previous_.swap(current_);
    current_.swap(guess_);
    previous_step_ = h;
    theta_ = next;
    at_design_ = false;
    return true;
}

} // namespace popup
