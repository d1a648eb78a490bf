#pragma once
// Internal: Levenberg–Marquardt on one component of the fold's equations, whatever the linear
// algebra (dense or sparse normal equations; docs/MATH.md, Solver).
#include <algorithm>
#include <optional>
#include <vector>

#include "fold_equations.hpp"

namespace popup {

/// Damped Gauss-Newton on component c from q: linearize() builds the normal equations at q
/// (false: it cannot, and nullopt is returned after `iterations`); solve_and_apply(λ) solves
/// the damped system and moves q by the step (false: the factorisation failed, which counts as
/// a rejected step). True when converged. With hints the pass only positions the guess.
/// `to_round_off` keeps iterating past the tolerance while the cost still drops.
template <class Linearize, class SolveAndApply>
std::optional<bool> damped_least_squares(const FoldEquations& equations, int c, Configuration& q,
                                         const std::vector<BranchHint>* hints, int max_iterations,
                                         bool to_round_off, int& iterations, Linearize&& linearize,
                                         SolveAndApply&& solve_and_apply)
{
    const auto& bodies = equations.graph().components[c];
    thread_local std::vector<BodyPose> saved; // once per thread, not per correction
    saved.resize(bodies.size());
    double worst = 0.0;
    double current = equations.cost(c, q, hints, &worst);
    double lambda = 1e-6;
    for (iterations = 0; iterations < max_iterations; ++iterations) {
        if (!hints && !to_round_off && worst <= equations.tolerance())
            return true;
        if (!linearize())
            return std::nullopt;
        bool improved = false;
        while (lambda < 1e10) {
            // Try the step in place; only this component's bodies are saved for a rollback.
            for (size_t k = 0; k < bodies.size(); ++k)
                saved[k] = q[bodies[k]];
            // A failed factorisation (round-off on a singular A) is a rejected step.
            if (!solve_and_apply(lambda)) {
                lambda *= 8.0;
                continue;
            }
            double worst2 = 0.0;
            const double trial = equations.cost(c, q, hints, &worst2);
            if (trial < current || (trial == 0.0 && current == 0.0)) {
                improved = current - trial > 1e-30 * equations.size() * equations.size();
                current = trial;
                worst = worst2;
                lambda = std::max(lambda * 0.25, 1e-12);
                break;
            }
            for (size_t k = 0; k < bodies.size(); ++k)
                q[bodies[k]] = saved[k];
            lambda *= 8.0;
        }
        if (!improved)
            break;
    }
    if (hints)
        return true; // the hinted pass only positions the guess; the plain pass must converge
    return worst <= equations.tolerance();
}

} // namespace popup
