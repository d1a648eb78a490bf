#include "free_motion.hpp"

#include <algorithm>
#include <set>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

namespace popup {

ComponentMotion component_free_motion(const FoldSolver& solver, int c, const Configuration& q)
{
    ComponentMotion motion;
    if (solver.rigid(c, q))
        return motion;
    // Only a component that can move pays for the eigenvectors that say which bodies move.
    const BodyGraph& g = solver.graph();
    Eigen::MatrixXd A;
    Eigen::VectorXd gradient;
    solver.linearize(c, q, nullptr, A, gradient);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(A);
    const Eigen::VectorXd& values = eig.eigenvalues(); // ascending
    const double largest = std::max(values.maxCoeff(), 1.0);
    // Columns are in mm per mm of motion, so singular values are O(1) for a rigid design.
    const double threshold = 1e-12 * largest;
    std::set<int> moving;
    for (int k = 0; k < values.size() && values[k] <= threshold; ++k) {
        ++motion.dimension;
        const Eigen::VectorXd v = eig.eigenvectors().col(k);
        for (size_t b = 0; b < g.components[c].size(); ++b)
            if (v.segment<6>(6 * b).norm() > 1e-3)
                moving.insert(g.components[c][b]);
    }
    motion.moving_bodies.assign(moving.begin(), moving.end());
    return motion;
}

std::vector<int> patches_of_bodies(const Scaffold& scaffold, const BodyGraph& graph,
                                   const std::vector<int>& bodies)
{
    std::vector<int> ids;
    for (size_t i = 0; i < scaffold.patches.size(); ++i)
        if (std::binary_search(bodies.begin(), bodies.end(), graph.body_of_patch[i]))
            ids.push_back(scaffold.patches[i].id);
    return ids;
}

FreeMotion free_motion_of(const Scaffold& scaffold, const FoldSolver& solver,
                          const Configuration& q)
{
    FreeMotion motion;
    std::vector<int> moving;
    for (size_t c = 0; c < solver.graph().components.size(); ++c) {
        const ComponentMotion m = component_free_motion(solver, int(c), q);
        motion.dimension += m.dimension;
        moving.insert(moving.end(), m.moving_bodies.begin(), m.moving_bodies.end());
    }
    std::sort(moving.begin(), moving.end());
    motion.moving_patches = patches_of_bodies(scaffold, solver.graph(), moving);
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
