#pragma once
// Internal: the fold solver's sparse path, for components of many free bodies. Their normal
// equations as a sparse matrix of 6x6 blocks with a fixed pattern, ordered and analysed once per
// component; each Levenberg–Marquardt step only refactorises (docs/MATH.md, Solver).
#include <memory>
#include <vector>

#include <tbb/enumerable_thread_specific.h>

#include "fold_equations.hpp"

namespace popup {

/// Each thread keeps its own factorisation workspace per component between calls (the validity
/// check solves on all cores): calls from different threads share none.
class SparseLeastSquares {
public:
    explicit SparseLeastSquares(const FoldEquations& equations);
    ~SparseLeastSquares();
    SparseLeastSquares(const SparseLeastSquares&) = delete;
    SparseLeastSquares& operator=(const SparseLeastSquares&) = delete;

    /// Levenberg–Marquardt on component c with sparse normal equations; true when converged.
    /// Hints that couple bodies outside the pattern (from elsewhere than hints(c)) make it
    /// finish with dense ones.
    bool least_squares(int c, Configuration& q, const std::vector<BranchHint>* hints,
                       int max_iterations, bool to_round_off) const;
    /// Sparse rank test: JᵀJ has an eigenvalue at or below 1e-12 max(λmax, 1) (inertia of the
    /// shifted matrix, Sylvester's law).
    bool small_eigenvalue(int c, const Configuration& q) const;

private:
    struct System;

    System& system(int c) const;
    /// Normal equations of component c into its system (same sums as the dense ones); false
    /// when a hint couples two bodies outside the system's pattern.
    bool linearize(int c, const Configuration& q, const std::vector<BranchHint>* hints,
                   System& s) const;

    const FoldEquations& equations_;
    /// Per thread and component, built on first use by system(): a system holds the
    /// factorisation it is working on.
    mutable tbb::enumerable_thread_specific<std::vector<std::unique_ptr<System>>> systems_;
};

} // namespace popup
