#include "dense_least_squares.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/SVD>

#include "damped_least_squares.hpp"
#include "joint_block.hpp"

namespace popup {

namespace {

/// Where one joint's blocks go in a dense system: its sides 0 and 1 (its two bodies) have their
/// unknowns from column[0] and column[1].
template <class Matrix, class Vector> struct DenseAssembly {
    Matrix& A;
    Vector& g;
    int column[2];

    void add(int i, int j, const Mat6& block)
    {
        A.template block<6, 6>(column[i], column[j]) += block;
    }
    void add(int i, const Vec6& v) { g.template segment<6>(column[i]) += v; }
};

template <class Matrix, class Vector>
void linearize_into(const FoldEquations& equations, int c, const Configuration& q,
                    const std::vector<BranchHint>* hints, Matrix& A, Vector& g)
{
    const BodyGraph& graph = equations.graph();
    const int n = int(6 * graph.components[c].size());
    A.setZero();
    g.setZero();
    // Each hinge or slit end touches at most two bodies: assemble JᵀJ and Jᵀr from 6x6 blocks.
    for (int j : graph.component_joints[c]) {
        const Joint& joint = graph.joints[j];
        const bool free_a = !graph.is_base(joint.body_a);
        const bool free_b = !graph.is_base(joint.body_b);
        DenseAssembly<Matrix, Vector> to{
            A, g, {equations.column_of_body(joint.body_a), equations.column_of_body(joint.body_b)}};
        for (const Vec3& x : joint.ends)
            add_normal_terms(hinge_end_rows(joint, x, q, graph, equations.size()), free_a, free_b,
                             to);
    }
    for (int k : graph.component_slits[c]) {
        const SlitJoint& sl = graph.slits[k];
        const bool free_t = !graph.is_base(sl.body_through);
        const bool free_c = !graph.is_base(sl.body_cut);
        DenseAssembly<Matrix, Vector> to{
            A,
            g,
            {equations.column_of_body(sl.body_through), equations.column_of_body(sl.body_cut)}};
        for (int e = 0; e < 2; ++e)
            add_normal_terms(slit_row(sl, e, q, graph, equations.size()), free_t, free_c, to);
    }
    if (!hints)
        return;
    // Hint rows by differences: used once per design state, so speed does not matter here.
    for (const BranchHint& hint : *hints) {
        const double f = equations.hint_residual(hint, q);
        Eigen::VectorXd row(n);
        equations.hint_gradient(c, hint, q, f, 0, n, row);
        A += row * row.transpose();
        g += row * f;
    }
}

template <int N>
bool least_squares_sized(const FoldEquations& equations, int c, Configuration& q,
                         const std::vector<BranchHint>* hints, int max_iterations,
                         bool to_round_off)
{
    using Matrix = Eigen::Matrix<double, N, N>;
    using Vector = Eigen::Matrix<double, N, 1>;
    const int n = int(6 * equations.graph().components[c].size());
    // Buffers reused across iterations and, per thread, across calls: a sweep runs this
    // thousands of times, and a large component's normal matrix (270 x 270 for 45 bodies, half a
    // megabyte) allocated afresh each time cost more in page faults than the factorisation.
    thread_local Matrix A, M;
    thread_local Vector g, d;
    thread_local Eigen::LLT<Matrix> llt;
    A.resize(n, n);
    M.resize(n, n);
    g.resize(n);
    d.resize(n);
    int iterations = 0;
    return *damped_least_squares(
        equations, c, q, hints, max_iterations, to_round_off, iterations,
        [&] {
            linearize_into(equations, c, q, hints, A, g);
            return true;
        },
        [&](double lambda) {
            M = A;
            M.diagonal().array() += lambda * A.diagonal().array() + 1e-14;
            llt.compute(M);
            d.noalias() = llt.solve(g);
            d = -d;
            equations.apply_step(c, q, d);
            return true;
        });
}

/// True when the symmetric N x N matrix A certainly passes rigid_sized's pivot test: its
/// Cholesky factor L (no pivoting) exists and λmin(A) ≥ 1 / trace(A⁻¹) = 1 / ‖L⁻¹‖²_F exceeds
/// 2e-9 of the largest diagonal entry. Every pivot of the pivoted LDLᵀ lies between λmin and
/// that entry, so it then clears 1e-12 of the largest pivot by a factor of 2000, far beyond
/// round-off (docs/MATH.md, "A certificate for the stability test"). False means "not sure": the
/// LDLᵀ decides. Straight loops on a fixed size: Eigen's pivoted LDLᵀ of a 12 x 12 matrix goes
/// through dynamic-size blocks and cost a validity check over a tenth of its time.
template <int N> bool clearly_positive_definite(const Eigen::Matrix<double, N, N>& A)
{
    double L[N][N];       // lower triangle only
    double inverse_of[N]; // 1 / L_jj: a bound needs no correctly rounded division
    double largest = 1.0;
    for (int i = 0; i < N; ++i)
        largest = std::max(largest, std::abs(A(i, i)));
    for (int j = 0; j < N; ++j) {
        double d = A(j, j);
        for (int k = 0; k < j; ++k)
            d -= L[j][k] * L[j][k];
        if (!(d > 0.0))
            return false;
        L[j][j] = std::sqrt(d);
        inverse_of[j] = 1.0 / L[j][j];
        for (int i = j + 1; i < N; ++i) {
            double sum = A(i, j);
            for (int k = 0; k < j; ++k)
                sum -= L[i][k] * L[j][k];
            L[i][j] = sum * inverse_of[j];
        }
    }
    double trace_of_inverse = 0.0; // ‖L⁻¹‖²_F, column by column: L x = e_j
    for (int j = 0; j < N; ++j) {
        double x[N];
        x[j] = inverse_of[j];
        double column = x[j] * x[j];
        for (int i = j + 1; i < N; ++i) {
            double sum = 0.0;
            for (int k = j; k < i; ++k)
                sum -= L[i][k] * x[k];
            x[i] = sum * inverse_of[i];
            column += x[i] * x[i];
        }
        trace_of_inverse += column;
    }
    return std::isfinite(trace_of_inverse) && 1.0 / trace_of_inverse > 2e-9 * largest;
}

template <int N> bool rigid_sized(const FoldEquations& equations, int c, const Configuration& q)
{
    const int n = int(6 * equations.graph().components[c].size());
    Eigen::Matrix<double, N, N> A(n, n);
    Eigen::Matrix<double, N, 1> g(n);
    linearize_into(equations, c, q, nullptr, A, g);
    if constexpr (N != Eigen::Dynamic)
        if (clearly_positive_definite<N>(A))
            return true;
    const Eigen::Matrix<double, N, 1> pivots = A.ldlt().vectorD();
    const double scale = std::max(pivots.cwiseAbs().maxCoeff(), 1.0);
    return (pivots.array() > 1e-12 * scale).all();
}

/// Jacobian of component c's hinge and slit constraints with respect to its bodies' motions
/// (rotation columns scaled by the model size so every column is in mm).
Eigen::MatrixXd constraint_jacobian(const FoldEquations& equations, int c, const Configuration& q)
{
    const BodyGraph& graph = equations.graph();
    const auto& joints = graph.component_joints[c];
    const auto& slits = graph.component_slits[c];
    const int n = int(6 * graph.components[c].size());
    const int hinge_rows = int(6 * joints.size());
    Eigen::MatrixXd J;
    J.setZero(hinge_rows + 2 * slits.size(), n);
    for (size_t k = 0; k < slits.size(); ++k) {
        const SlitJoint& sl = graph.slits[slits[k]];
        for (int e = 0; e < 2; ++e) {
            const int rowi = hinge_rows + int(2 * k) + e;
            const SlitRow row = slit_row(sl, e, q, graph, equations.size());
            if (!graph.is_base(sl.body_through))
                J.block<1, 6>(rowi, equations.column_of_body(sl.body_through)) =
                    row.through.transpose();
            if (!graph.is_base(sl.body_cut))
                J.block<1, 6>(rowi, equations.column_of_body(sl.body_cut)) += row.cut.transpose();
        }
    }
    for (size_t k = 0; k < joints.size(); ++k) {
        const Joint& joint = graph.joints[joints[k]];
        for (int e = 0; e < 2; ++e) {
            const int row = int(6 * k + 3 * e);
            const HingeEndRows rows =
                hinge_end_rows(joint, joint.ends[e], q, graph, equations.size());
            if (!graph.is_base(joint.body_a))
                J.block<3, 6>(row, equations.column_of_body(joint.body_a)) = rows.jacobian_a();
            if (!graph.is_base(joint.body_b))
                J.block<3, 6>(row, equations.column_of_body(joint.body_b)) = rows.jacobian_b();
        }
    }
    return J;
}

} // namespace

void linearize_dense(const FoldEquations& equations, int c, const Configuration& q,
                     const std::vector<BranchHint>* hints, Eigen::MatrixXd& A, Eigen::VectorXd& g)
{
    const int n = int(6 * equations.graph().components[c].size());
    A.resize(n, n);
    g.resize(n);
    linearize_into(equations, c, q, hints, A, g);
}

bool least_squares_dense(const FoldEquations& equations, int c, Configuration& q,
                         const std::vector<BranchHint>* hints, int max_iterations,
                         bool to_round_off)
{
    // Most mechanisms are one or two free bodies: fixed-size algebra avoids heap traffic there.
    switch (equations.graph().components[c].size()) {
    case 0:
        return true;
    case 1:
        return least_squares_sized<6>(equations, c, q, hints, max_iterations, to_round_off);
    case 2:
        return least_squares_sized<12>(equations, c, q, hints, max_iterations, to_round_off);
    default:
        return least_squares_sized<Eigen::Dynamic>(equations, c, q, hints, max_iterations,
                                                   to_round_off);
    }
}

bool rigid_dense(const FoldEquations& equations, int c, const Configuration& q)
{
    switch (equations.graph().components[c].size()) {
    case 0:
        return true;
    case 1:
        return rigid_sized<6>(equations, c, q);
    case 2:
        return rigid_sized<12>(equations, c, q);
    default:
        return rigid_sized<Eigen::Dynamic>(equations, c, q);
    }
}

bool singular_dense(const FoldEquations& equations, int c, const Configuration& q)
{
    const Eigen::MatrixXd J = constraint_jacobian(equations, c, q);
    if (J.cols() == 0)
        return false;
    if (J.rows() == 0) // no constraint at all: every motion is free
        return true;
    const Eigen::VectorXd s = Eigen::JacobiSVD<Eigen::MatrixXd>(J).singularValues();
    return s.minCoeff() <= 1e-6 * std::max(s.maxCoeff(), 1.0);
}

} // namespace popup
