#pragma once
// Internal: rigid-body kinematics of a scaffold. Every free body has a pose x -> R (x - c) + p
// (c its design-state centre); hinges are point-coincidence constraints at both hinge ends; the
// base bodies are driven by the fold angle. Solved per component by damped Gauss-Newton: dense
// normal equations for small components, a sparse factorisation from kSparseFromBodies bodies.
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include <tbb/enumerable_thread_specific.h>

#include "body_graph.hpp"
#include "popup/simulation/simulate_fold.hpp"

namespace popup {

struct BodyPose {
    Mat3 rotation = Mat3::Identity();
    Vec3 position = Vec3::Zero();
};
using Configuration = std::vector<BodyPose>;

/// A fold that is flat at the design state and carries an intended direction: during the first
/// step away from the design state it pulls the solution onto the intended branch.
struct BranchHint {
    int patch_a = 0; ///< patch indices
    int patch_b = 0;
    int hinge = 0;
    double sign = 1.0; ///< +1 valley, -1 mountain
};

/// Components of this many free bodies or more are solved with sparse normal equations (unless
/// SimulationOptions::dense_linear_algebra): below it the dense Cholesky is as fast.
constexpr int kSparseFromBodies = 6;

/// Not thread-safe: a solver keeps per-component factorisation workspaces between calls (every
/// caller builds its own solver).
class FoldSolver {
public:
    FoldSolver(const Scaffold& scaffold, const BodyGraph& graph, const SimulationOptions& options);
    ~FoldSolver();
    FoldSolver(const FoldSolver&) = delete;
    FoldSolver& operator=(const FoldSolver&) = delete;

    const Scaffold& scaffold() const { return scaffold_; }
    const BodyGraph& graph() const { return graph_; }
    const SimulationOptions& options() const { return options_; }
    double tolerance() const { return tolerance_; }
    Configuration design_configuration() const;
    void drive_base(double theta, Configuration& q) const;

    /// Newton-corrects the bodies of component c at the base state already in q. With hints,
    /// first settles on the hinted side of each flat fold, then corrects without them.
    /// `to_round_off` keeps iterating past the tolerance while the residual still drops.
    bool correct(int c, Configuration& q, const std::vector<BranchHint>& hints, int max_iterations,
                 bool to_round_off = false) const;

    /// Signed opening of a fold: sine of the angle by which patch b leaves patch a's plane,
    /// positive toward a's normal (valley side).
    double fold_sine(const BranchHint& hint, const Configuration& q) const;
    /// Branch hints of component c (flat directed folds at the design state).
    const std::vector<BranchHint>& hints(int c) const { return hints_[c]; }
    /// Flat folds without a direction in component c (the branch is then arbitrary).
    const std::vector<int>& undirected_flat_hinges(int c) const { return undirected_[c]; }

    FoldState state(double theta, const Configuration& q) const;
    Configuration configuration(const FoldState& state) const;

    /// Jacobian of component c's hinge constraints with respect to its bodies' motions
    /// (rotation columns scaled by the model size so every column is in mm).
    Eigen::MatrixXd jacobian(int c, const Configuration& q) const;
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
    struct SparseSystem; // fold_solver.cpp

    void constraint_system(int c, const Configuration& q, Eigen::VectorXd& r,
                           Eigen::MatrixXd& J) const;
    bool least_squares(int c, Configuration& q, const std::vector<BranchHint>* hints,
                       int max_iterations, bool to_round_off) const;
    template <int N> bool rigid_sized(int c, const Configuration& q) const;
    /// Levenberg–Marquardt on component c, whatever the linear algebra: linearize() builds the
    /// normal equations at q (false: it cannot, and nullopt is returned after `iterations`);
    /// solve_and_apply(λ) solves the damped system and moves q by the step (false: the
    /// factorisation failed, which counts as a rejected step). True when converged.
    template <class Linearize, class SolveAndApply>
    std::optional<bool>
    damped_least_squares(int c, Configuration& q, const std::vector<BranchHint>* hints,
                         int max_iterations, bool to_round_off, int& iterations,
                         Linearize&& linearize, SolveAndApply&& solve_and_apply) const;
    template <int N>
    bool least_squares_sized(int c, Configuration& q, const std::vector<BranchHint>* hints,
                             int max_iterations, bool to_round_off) const;
    template <class Vector> void apply_step(int c, Configuration& q, const Vector& d) const;
    template <class Matrix, class Vector>
    void linearize_into(int c, const Configuration& q, const std::vector<BranchHint>* hints,
                        Matrix& A, Vector& g) const;
    /// Finite-difference gradient of a hint's residual over the unknowns of component c: its
    /// columns `from`..`to`; apply_step moves nothing else, so the others are exactly zero.
    template <class Row>
    void hint_gradient(int c, const BranchHint& hint, const Configuration& q, double f, int from,
                       int to, Row& row) const;
    SparseSystem& sparse_system(int c) const;
    /// Normal equations of component c into its sparse system (same sums as linearize_into);
    /// false when a hint couples two bodies outside the system's pattern.
    bool linearize_sparse(int c, const Configuration& q, const std::vector<BranchHint>* hints,
                          SparseSystem& s) const;
    bool least_squares_sparse(int c, Configuration& q, const std::vector<BranchHint>* hints,
                              int max_iterations, bool to_round_off) const;
    /// Sparse rank test: JᵀJ has an eigenvalue at or below 1e-12 max(λmax, 1) (inertia of the
    /// shifted matrix, Sylvester's law).
    bool small_eigenvalue(int c, const Configuration& q) const;
    double hint_residual(const BranchHint& hint, const Configuration& q) const;
    /// Sum of squared residuals (hinge ends, and hints when given); `worst` gets the largest
    /// hinge coordinate mismatch.
    double cost(int c, const Configuration& q, const std::vector<BranchHint>* hints,
                double* worst) const;

    const Scaffold& scaffold_;
    const BodyGraph& graph_;
    SimulationOptions options_;
    double size_ = 1.0;
    double tolerance_ = 1e-11;
    std::vector<std::vector<BranchHint>> hints_;
    std::vector<std::vector<int>> undirected_;
    std::vector<int> column_of_body_; ///< first unknown of each free body within its component
    std::vector<std::array<int, 2>> hinge_patches_; ///< patch indices of each hinge
    /// Per thread and component, built on first use by sparse_system(): the validity check
    /// solves on all cores, and a system holds the factorisation it is working on.
    mutable tbb::enumerable_thread_specific<std::vector<std::unique_ptr<SparseSystem>>> sparse_;
};

/// simulate_fold on a scaffold already validated, with its body graph and solver (the validity
/// check builds those once for the sweep and the checks after it). The angles must be in 0..π.
Result<FoldSweep> simulate_validated(const FoldSolver& solver, const std::vector<double>& angles);

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
