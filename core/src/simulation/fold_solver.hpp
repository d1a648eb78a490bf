#pragma once
// Internal: rigid-body kinematics of a scaffold. Every free body has a pose x -> R (x - c) + p
// (c its design-state centre); hinges are point-coincidence constraints at both hinge ends; the
// base bodies are driven by the fold angle. Solved per component by damped Gauss-Newton on the
// equations of fold_equations.hpp: dense normal equations (dense_least_squares) for small
// components, a sparse factorisation (sparse_least_squares) from kSparseFromBodies bodies.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "fold_equations.hpp"
#include "popup/simulation/fold_state.hpp"
#include "sparse_least_squares.hpp"

namespace popup {

/// Components of this many free bodies or more are solved with sparse normal equations (unless
/// SimulationOptions::dense_linear_algebra): below it the dense Cholesky is as fast.
constexpr int kSparseFromBodies = 6;

/// Not thread-safe: a solver keeps per-component factorisation workspaces between calls (every
/// caller builds its own solver).
class FoldSolver : public FoldEquations {
public:
    FoldSolver(const Scaffold& scaffold, const BodyGraph& graph, const SimulationOptions& options);
    FoldSolver(const FoldSolver&) = delete;
    FoldSolver& operator=(const FoldSolver&) = delete;

    const SimulationOptions& options() const { return options_; }
    void drive_base(double theta, Configuration& q) const;

    /// Newton-corrects the bodies of component c at the base state already in q. With hints,
    /// first settles on the hinted side of each flat fold, then corrects without them.
    /// `to_round_off` keeps iterating past the tolerance while the residual still drops.
    bool correct(int c, Configuration& q, const std::vector<BranchHint>& hints, int max_iterations,
                 bool to_round_off = false) const;

    FoldState state(double theta, const Configuration& q) const;
    Configuration configuration(const FoldState& state) const;

    /// No free motion of component c at q with the base held still: the pivoted LDLᵀ of JᵀJ
    /// has no pivot below 1e-12 of the largest (columns are in mm, so pivots are O(1)). Sparse
    /// components: no eigenvalue of JᵀJ at or below 1e-12 max(λmax, 1) (docs/MATH.md, Solver).
    bool rigid(int c, const Configuration& q) const;
    /// The component's constraints lose rank at q (a branch point or a free motion): a singular
    /// value of J at or below 1e-6 max(σmax, 1), by SVD, or for sparse components by the same
    /// test on the eigenvalues of JᵀJ.
    bool singular(int c, const Configuration& q) const;
    /// Whether component c is solved with sparse normal equations.
    bool uses_sparse(int c) const;

    /// Normal equations JᵀJ and Jᵀr of component c's least-squares problem (hinge ends, plus
    /// hints when given), with rotation columns scaled by the model size.
    void linearize(int c, const Configuration& q, const std::vector<BranchHint>* hints,
                   Eigen::MatrixXd& A, Eigen::VectorXd& g) const;

private:
    bool least_squares(int c, Configuration& q, const std::vector<BranchHint>* hints,
                       int max_iterations, bool to_round_off) const;

    SimulationOptions options_;
    std::vector<std::array<int, 2>> hinge_patches_; ///< patch indices of each hinge
    SparseLeastSquares sparse_;
};

} // namespace popup
