#pragma once
// Internal: the least-squares problem of a scaffold's free bodies, one component at a time:
// hinge ends coincide, slit ends stay in their planes, and at the design state flat folds with a
// direction get a branch hint. Its residuals, their cost, and how a step of a component's
// unknowns moves its bodies; the dense and the sparse solver both work on it.
#include <vector>

#include <Eigen/Core>

#include "body_graph.hpp"
#include "body_pose.hpp"

namespace popup {

/// A fold that is flat at the design state and carries an intended direction: during the first
/// step away from the design state it pulls the solution onto the intended branch.
struct BranchHint {
    int patch_a = 0; ///< patch indices
    int patch_b = 0;
    int hinge = 0;
    double sign = 1.0; ///< +1 valley, -1 mountain
};

class FoldEquations {
public:
    FoldEquations(const Scaffold& scaffold, const BodyGraph& graph);

    const Scaffold& scaffold() const { return scaffold_; }
    const BodyGraph& graph() const { return graph_; }
    /// The model size (mm), by which rotation unknowns are scaled so every column is in mm.
    double size() const { return size_; }
    double tolerance() const { return tolerance_; }
    /// First unknown of a free body within its component: 6 per body, rotation then position.
    int column_of_body(int body) const { return column_of_body_[body]; }
    Configuration design_configuration() const;

    /// Signed opening of a fold: sine of the angle by which patch b leaves patch a's plane,
    /// positive toward a's normal (valley side).
    double fold_sine(const BranchHint& hint, const Configuration& q) const;
    /// Branch hints of component c (flat directed folds at the design state).
    const std::vector<BranchHint>& hints(int c) const { return hints_[c]; }
    /// Flat folds without a direction in component c (the branch is then arbitrary).
    const std::vector<int>& undirected_flat_hinges(int c) const { return undirected_[c]; }

    double hint_residual(const BranchHint& hint, const Configuration& q) const;
    /// Finite-difference gradient of a hint's residual over the unknowns of component c: its
    /// columns `from`..`to`; apply_step moves nothing else, so the others are exactly zero.
    template <class Row>
    void hint_gradient(int c, const BranchHint& hint, const Configuration& q, double f, int from,
                       int to, Row& row) const;
    /// Moves the bodies of component c by the step d of its unknowns.
    template <class Vector> void apply_step(int c, Configuration& q, const Vector& d) const;
    /// Sum of squared residuals (hinge ends, and hints when given); `worst` gets the largest
    /// hinge coordinate mismatch.
    double cost(int c, const Configuration& q, const std::vector<BranchHint>* hints,
                double* worst) const;

private:
    const Scaffold& scaffold_;
    const BodyGraph& graph_;
    double size_ = 1.0;
    double tolerance_ = 1e-11;
    std::vector<std::vector<BranchHint>> hints_;
    std::vector<std::vector<int>> undirected_;
    std::vector<int> column_of_body_;
};

template <class Vector>
void FoldEquations::apply_step(int c, Configuration& q, const Vector& d) const
{
    const auto& bodies = graph_.components[c];
    for (size_t k = 0; k < bodies.size(); ++k) {
        BodyPose& p = q[bodies[k]];
        p.rotation = rotation_exp(d.template segment<3>(6 * k) / size_) * p.rotation;
        p.position += d.template segment<3>(6 * k + 3);
    }
}

template <class Row>
void FoldEquations::hint_gradient(int c, const BranchHint& hint, const Configuration& q, double f,
                                  int from, int to, Row& row) const
{
    const int n = int(6 * graph_.components[c].size());
    // One copy of the card per call, not per column: apply_step moves only this component's
    // bodies, so restoring those after each column gives q again (a sweep over a 100-patch card
    // spent a twentieth of its time copying configurations here).
    thread_local Configuration moved;
    thread_local Eigen::VectorXd d;
    moved.assign(q.begin(), q.end());
    d.setZero(n);
    const auto& bodies = graph_.components[c];
    for (int col = from; col < to; ++col) {
        d[col] = 1e-7 * size_;
        apply_step(c, moved, d);
        row[col - from] = (hint_residual(hint, moved) - f) / d[col];
        d[col] = 0.0;
        for (int b : bodies)
            moved[b] = q[b];
    }
}

} // namespace popup
