#include "free_motion.hpp"

#include <algorithm>
#include <set>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

namespace popup {

FreeMotion free_motion_of(const Scaffold& scaffold, const FoldSolver& solver,
                          const Configuration& q)
{
    const BodyGraph& g = solver.graph();
    FreeMotion motion;
    std::set<int> moving_bodies;
    for (size_t c = 0; c < g.components.size(); ++c) {
        if (solver.rigid(int(c), q))
            continue;
        // Only a component that can move pays for the eigenvectors that say which bodies move.
        Eigen::MatrixXd A;
        Eigen::VectorXd gradient;
        solver.linearize(int(c), q, nullptr, A, gradient);
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(A);
        const Eigen::VectorXd& values = eig.eigenvalues(); // ascending
        const double largest = std::max(values.maxCoeff(), 1.0);
        // Columns are in mm per mm of motion, so singular values are O(1) for a rigid design.
        const double threshold = 1e-12 * largest;
        for (int k = 0; k < values.size() && values[k] <= threshold; ++k) {
            ++motion.dimension;
            const Eigen::VectorXd v = eig.eigenvectors().col(k);
            for (size_t b = 0; b < g.components[c].size(); ++b)
                if (v.segment<6>(6 * b).norm() > 1e-3)
                    moving_bodies.insert(g.components[c][b]);
        }
    }
    for (size_t i = 0; i < scaffold.patches.size(); ++i)
        if (moving_bodies.count(g.body_of_patch[i]))
            motion.moving_patches.push_back(scaffold.patches[i].id);
    return motion;
}

FreeMotion free_motion(const Scaffold& input, const FoldState& state)
{
    Result<Scaffold> checked = validate_scaffold(input);
    if (!checked.ok)
        throw std::invalid_argument("free_motion: invalid scaffold: " +
                                    checked.diagnostics.front().message);
    if (state.poses.size() != checked.value.patches.size())
        throw std::invalid_argument("free_motion: the state has " +
                                    std::to_string(state.poses.size()) + " poses for " +
                                    std::to_string(checked.value.patches.size()) + " patches");
    Result<BodyGraph> graph = build_body_graph(checked.value);
    if (!graph.ok)
        throw std::invalid_argument("free_motion: " + graph.diagnostics.front().message);
    const FoldSolver solver(checked.value, graph.value, SimulationOptions{});
    return free_motion_of(checked.value, solver, solver.configuration(state));
}

} // namespace popup
