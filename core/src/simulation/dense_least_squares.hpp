#pragma once
// Internal: the fold solver's dense path. A component's normal equations JᵀJ, Jᵀr as a dense
// matrix (fixed-size for one or two free bodies, where most mechanisms are), a Cholesky per
// Levenberg–Marquardt step, and the rank tests by pivoted LDLᵀ and by SVD.
#include <vector>

#include <Eigen/Core>

#include "fold_equations.hpp"

namespace popup {

/// Normal equations JᵀJ and Jᵀr of component c's least-squares problem (hinge ends, slit ends,
/// plus hints when given), with rotation columns scaled by the model size.
void linearize_dense(const FoldEquations& equations, int c, const Configuration& q,
                     const std::vector<BranchHint>* hints, Eigen::MatrixXd& A, Eigen::VectorXd& g);

/// Levenberg–Marquardt on component c with dense normal equations; true when converged.
bool least_squares_dense(const FoldEquations& equations, int c, Configuration& q,
                         const std::vector<BranchHint>* hints, int max_iterations,
                         bool to_round_off);

/// No free motion of component c at q with the base held still: the pivoted LDLᵀ of JᵀJ has no
/// pivot below 1e-12 of the largest (columns are in mm, so pivots are O(1)).
bool rigid_dense(const FoldEquations& equations, int c, const Configuration& q);

/// The constraints of component c lose rank at q: a singular value of their Jacobian J at or
/// below 1e-6 max(σmax, 1), by SVD.
bool singular_dense(const FoldEquations& equations, int c, const Configuration& q);

} // namespace popup
