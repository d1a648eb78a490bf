#include "fold_equations.hpp"

#include <algorithm>
#include <cmath>

#include "joint_block.hpp"

namespace popup {

FoldEquations::FoldEquations(const Scaffold& scaffold, const BodyGraph& graph)
    : scaffold_(scaffold), graph_(graph)
{
    size_ = std::max(scaffold.size(), 1e-3);
    tolerance_ = 1e-11 * size_;
    column_of_body_.assign(graph.body_count, -1);
    for (const auto& bodies : graph.components)
        for (size_t k = 0; k < bodies.size(); ++k)
            column_of_body_[bodies[k]] = int(6 * k);

    hints_.resize(graph.components.size());
    undirected_.resize(graph.components.size());
    const Configuration design = design_configuration();
    for (const Joint& joint : graph.joints) {
        const Hinge& h = scaffold.hinges[joint.hinge];
        BranchHint hint{scaffold.patch_index(h.patch_a), scaffold.patch_index(h.patch_b),
                        joint.hinge, h.direction == FoldDirection::mountain ? -1.0 : 1.0};
        if (std::abs(fold_sine(hint, design)) > 1e-9)
            continue; // not flat: the design state fixes the branch by itself
        const int free_body = graph.is_base(joint.body_a) ? joint.body_b : joint.body_a;
        const int c = graph.component_of_body[free_body];
        if (h.direction == FoldDirection::unspecified)
            undirected_[c].push_back(joint.hinge);
        else
            hints_[c].push_back(hint);
    }
}

Configuration FoldEquations::design_configuration() const
{
    Configuration q(graph_.body_count);
    for (int b = 0; b < graph_.body_count; ++b)
        q[b].position = graph_.center[b];
    return q;
}

double FoldEquations::fold_sine(const BranchHint& hint, const Configuration& q) const
{
    const Hinge& h = scaffold_.hinges[hint.hinge];
    const int a = graph_.body_of_patch[hint.patch_a];
    const int b = graph_.body_of_patch[hint.patch_b];
    const Patch& pa = scaffold_.patches[hint.patch_a];
    const Patch& pb = scaffold_.patches[hint.patch_b];
    const Vec3 normal = q[a].rotation * pa.normal;
    const Vec3 axis = (q[a].rotation * (h.to - h.from)).normalized();
    const Vec3 mid = place(q[a], graph_.center[a], 0.5 * (h.from + h.to));
    Vec3 away = place(q[b], graph_.center[b], pb.centroid()) - mid;
    away -= away.dot(axis) * axis;
    const double len = away.norm();
    return len > 0.0 ? normal.dot(away) / len : 0.0;
}

double FoldEquations::hint_residual(const BranchHint& hint, const Configuration& q) const
{
    const double weight = 0.1 * size_;
    const double target = 0.02; // sine of a small opening on the intended side
    return weight * (hint.sign * fold_sine(hint, q) - target);
}

double FoldEquations::cost(int c, const Configuration& q, const std::vector<BranchHint>* hints,
                           double* worst) const
{
    double total = 0.0, largest = 0.0;
    for (int j : graph_.component_joints[c]) {
        const Joint& joint = graph_.joints[j];
        for (const Vec3& x : joint.ends) {
            const Vec3 r = place(q[joint.body_a], graph_.center[joint.body_a], x) -
                           place(q[joint.body_b], graph_.center[joint.body_b], x);
            total += r.squaredNorm();
            largest = std::max(largest, r.cwiseAbs().maxCoeff());
        }
    }
    for (int k : graph_.component_slits[c])
        for (int e = 0; e < 2; ++e) {
            const double d = slit_row(graph_.slits[k], e, q, graph_, size_).distance;
            total += d * d;
            largest = std::max(largest, std::abs(d));
        }
    if (hints)
        for (const BranchHint& hint : *hints)
            total += std::pow(hint_residual(hint, q), 2);
    if (worst)
        *worst = largest;
    return total;
}

} // namespace popup
