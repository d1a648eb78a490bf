#include "fold_solver.hpp"

#include <algorithm>
#include <cmath>

#include "dense_least_squares.hpp"
#include "joint_block.hpp"

namespace popup {

FoldSolver::FoldSolver(const Scaffold& scaffold, const BodyGraph& graph,
                       const SimulationOptions& options)
    : FoldEquations(scaffold, graph), options_(options), sparse_(*this)
{
    for (const Hinge& h : scaffold.hinges)
        hinge_patches_.push_back(
            {scaffold.patch_index(h.patch_a), scaffold.patch_index(h.patch_b)});
}

bool FoldSolver::uses_sparse(int c) const
{
    return !options_.dense_linear_algebra && int(graph().components[c].size()) >= kSparseFromBodies;
}

void FoldSolver::drive_base(double theta, Configuration& q) const
{
    const BodyGraph& g = graph();
    const Pose ground = ground_pose(scaffold(), theta);
    const Pose backdrop = backdrop_pose(scaffold(), theta);
    q[g.ground] = {ground.rotation, ground.apply(g.center[g.ground])};
    q[g.backdrop] = {backdrop.rotation, backdrop.apply(g.center[g.backdrop])};
}

bool FoldSolver::correct(int c, Configuration& q, const std::vector<BranchHint>& hints,
                         int max_iterations, bool to_round_off) const
{
    if (!hints.empty())
        least_squares(c, q, &hints, max_iterations, false);
    return least_squares(c, q, nullptr, max_iterations, to_round_off);
}

bool FoldSolver::least_squares(int c, Configuration& q, const std::vector<BranchHint>* hints,
                               int max_iterations, bool to_round_off) const
{
    if (uses_sparse(c))
        return sparse_.least_squares(c, q, hints, max_iterations, to_round_off);
    return least_squares_dense(*this, c, q, hints, max_iterations, to_round_off);
}

void FoldSolver::linearize(int c, const Configuration& q, const std::vector<BranchHint>* hints,
                           Eigen::MatrixXd& A, Eigen::VectorXd& g) const
{
    linearize_dense(*this, c, q, hints, A, g);
}

bool FoldSolver::rigid(int c, const Configuration& q) const
{
    if (uses_sparse(c))
        return !sparse_.small_eigenvalue(c, q);
    return rigid_dense(*this, c, q);
}

bool FoldSolver::singular(int c, const Configuration& q) const
{
    // σ² are the eigenvalues of JᵀJ when J has at least as many rows as columns.
    const BodyGraph& g = graph();
    const size_t rows = 6 * g.component_joints[c].size() + 2 * g.component_slits[c].size();
    if (uses_sparse(c) && rows >= 6 * g.components[c].size())
        return sparse_.small_eigenvalue(c, q);
    return singular_dense(*this, c, q);
}

FoldState FoldSolver::state(double theta, const Configuration& q) const
{
    FoldState s;
    s.angle = theta;
    s.poses.resize(scaffold().patches.size());
    for (size_t i = 0; i < scaffold().patches.size(); ++i) {
        const int b = graph().body_of_patch[i];
        s.poses[i].rotation = q[b].rotation;
        s.poses[i].translation = q[b].position - q[b].rotation * graph().center[b];
    }
    for (size_t k = 0; k < scaffold().hinges.size(); ++k) {
        const Hinge& h = scaffold().hinges[k];
        const Pose& a = s.poses[hinge_patches_[k][0]];
        const Pose& b = s.poses[hinge_patches_[k][1]];
        for (const Vec3& x : {h.from, h.to})
            s.hinge_residual = std::max(s.hinge_residual, (a.apply(x) - b.apply(x)).norm());
    }
    for (const SlitJoint& sl : graph().slits)
        for (int e = 0; e < 2; ++e)
            s.hinge_residual =
                std::max(s.hinge_residual, std::abs(slit_row(sl, e, q, graph(), size()).distance));
    for (size_t i = 0; i < scaffold().patches.size(); ++i) {
        const Loop3& loop = scaffold().patches[i].outer;
        for (size_t k = 0; k < loop.size(); ++k) {
            const Vec3& x = loop[k];
            const Vec3& y = loop[(k + 1) % loop.size()];
            const double before = (y - x).norm();
            const double after = (s.poses[i].apply(y) - s.poses[i].apply(x)).norm();
            s.edge_strain = std::max(s.edge_strain, std::abs(after - before) / before);
        }
    }
    return s;
}

Configuration FoldSolver::configuration(const FoldState& state) const
{
    Configuration q(graph().body_count);
    for (size_t i = 0; i < scaffold().patches.size(); ++i) {
        const int b = graph().body_of_patch[i];
        q[b].rotation = state.poses[i].rotation;
        q[b].position = state.poses[i].apply(graph().center[b]);
    }
    return q;
}

} // namespace popup
