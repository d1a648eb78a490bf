#include "sparse_least_squares.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "damped_least_squares.hpp"
#include "dense_least_squares.hpp"
#include "joint_block.hpp"

namespace popup {

/// Normal equations of one component as a sparse matrix with a fixed pattern: a 6x6 block for
/// each body and for each pair of bodies a hinge, a slit or a branch hint couples, both
/// triangles stored. The pattern's fill-reducing ordering and elimination tree are computed once
/// (analyzePattern); each Newton step only refactorises.
struct SparseLeastSquares::System {
    using Matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
    /// Where a 6x6 block's values live: entry (r, k) at values[first + k * stride + r].
    struct Slot {
        int first = -1;
        int stride = 0;
    };

    Matrix A; ///< JᵀJ (plus hint rows), bodies in fill-reducing order
    Matrix M; ///< A damped or shifted: same pattern, so the analysed factorisation applies
    Eigen::VectorXd g;
    std::vector<int> column;                    ///< first row and column of each body in A
    std::vector<int> diagonal;                  ///< value index of each diagonal entry
    std::map<std::pair<int, int>, Slot> blocks; ///< by (row, column) body of the component
    std::vector<std::array<Slot, 4>> joints;    ///< per component joint: aa, bb, ab, ba (-1: base)
    std::vector<std::array<Slot, 4>> slits;     ///< per component slit: tt, cc, tc, ct
    /// Reads the upper triangle of M in place (the bodies are ordered already).
    Eigen::SimplicialLDLT<Matrix, Eigen::Upper, Eigen::NaturalOrdering<int>> ldlt;

    Slot slot(int row_body, int column_body) const
    {
        const auto it = blocks.find({row_body, column_body});
        return it == blocks.end() ? Slot{} : it->second;
    }
    void add(const Slot& s, const Mat6& m)
    {
        double* v = A.valuePtr() + s.first;
        for (int k = 0; k < 6; ++k)
            for (int r = 0; r < 6; ++r)
                v[k * s.stride + r] += m(r, k);
    }
    /// M = A with `scale` A_ii + `shift` added to each diagonal entry.
    void set_diagonal(double scale, double shift)
    {
        std::copy(A.valuePtr(), A.valuePtr() + A.nonZeros(), M.valuePtr());
        for (int i : diagonal)
            M.valuePtr()[i] += scale * A.valuePtr()[i] + shift;
    }
    /// Factorises M; false unless every pivot is positive (M positive definite).
    bool factorize_positive()
    {
        ldlt.factorize(M);
        return ldlt.info() == Eigen::Success && (ldlt.vectorD().array() > 0.0).all();
    }

    /// Where one joint's blocks go (add_normal_terms): its slots, and the first rows of its two
    /// bodies' unknowns.
    struct JointAssembly {
        System& s;
        const std::array<Slot, 4>& slots; ///< aa, bb, ab, ba
        int column[2];

        void add(int i, int j, const Mat6& block) { s.add(slots[i == j ? i : 2 + i], block); }
        void add(int i, const Vec6& v) { s.g.segment<6>(column[i]) += v; }
    };
};

SparseLeastSquares::SparseLeastSquares(const FoldEquations& equations) : equations_(equations) {}

SparseLeastSquares::~SparseLeastSquares() = default;

SparseLeastSquares::System& SparseLeastSquares::system(int c) const
{
    const BodyGraph& graph = equations_.graph();
    std::vector<std::unique_ptr<System>>& systems = systems_.local();
    if (systems.empty())
        systems.resize(graph.components.size());
    if (systems[c])
        return *systems[c];
    auto s = std::make_unique<System>();
    const int nb = int(graph.components[c].size());
    // Local body index of a body of this component, -1 for the base (no unknowns).
    auto local = [&](int body) {
        return graph.component_of_body[body] == c ? equations_.column_of_body(body) / 6 : -1;
    };
    std::vector<std::vector<int>> rows_of(nb); // block rows present in each block column
    for (int k = 0; k < nb; ++k)
        rows_of[k].push_back(k);
    auto couple = [&](int a, int b) {
        if (a < 0 || b < 0)
            return;
        rows_of[b].push_back(a);
        rows_of[a].push_back(b);
    };
    for (int j : graph.component_joints[c])
        couple(local(graph.joints[j].body_a), local(graph.joints[j].body_b));
    for (int k : graph.component_slits[c])
        couple(local(graph.slits[k].body_through), local(graph.slits[k].body_cut));
    for (const BranchHint& hint : equations_.hints(c))
        couple(local(graph.body_of_patch[hint.patch_a]), local(graph.body_of_patch[hint.patch_b]));
    // Fill-reducing order of the bodies (minimum degree on the body graph), so that the scalar
    // matrix is assembled already permuted and each factorisation reads it in place.
    Eigen::SparseMatrix<double, Eigen::ColMajor, int> body_pattern(nb, nb);
    std::vector<Eigen::Triplet<double, int>> links;
    for (int j = 0; j < nb; ++j) {
        auto& rows = rows_of[j];
        std::sort(rows.begin(), rows.end());
        rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
        for (int i : rows)
            links.emplace_back(i, j, 1.0);
    }
    body_pattern.setFromTriplets(links.begin(), links.end());
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order; // position -> body
    Eigen::AMDOrdering<int>()(body_pattern, order);
    std::vector<int> position(nb);
    for (int p = 0; p < nb; ++p)
        position[order.indices()[p]] = p;
    s->column.resize(nb);
    for (int k = 0; k < nb; ++k)
        s->column[k] = 6 * position[k];

    std::vector<int> outer(6 * nb + 1, 0);
    std::vector<int> inner;
    for (int p = 0; p < nb; ++p) {
        const int j = order.indices()[p];
        std::vector<int> rows; // block rows of column p, by position
        for (int i : rows_of[j])
            rows.push_back(position[i]);
        std::sort(rows.begin(), rows.end());
        const int stride = int(6 * rows.size());
        for (int k = 0; k < 6; ++k) {
            for (int i : rows)
                for (int r = 0; r < 6; ++r)
                    inner.push_back(6 * i + r);
            outer[6 * p + k + 1] = outer[6 * p + k] + stride;
        }
        for (size_t e = 0; e < rows.size(); ++e) {
            s->blocks[{order.indices()[rows[e]], j}] = {outer[6 * p] + int(6 * e), stride};
            if (rows[e] == p)
                for (int k = 0; k < 6; ++k)
                    s->diagonal.push_back(outer[6 * p + k] + int(6 * e) + k);
        }
    }
    const int n = 6 * nb;
    std::vector<double> zeros(inner.size(), 0.0);
    s->A = Eigen::Map<System::Matrix>(n, n, int(inner.size()), outer.data(), inner.data(),
                                      zeros.data());
    s->M = s->A;
    s->g.resize(n);
    for (int j : graph.component_joints[c]) {
        const int a = local(graph.joints[j].body_a), b = local(graph.joints[j].body_b);
        s->joints.push_back({s->slot(a, a), s->slot(b, b), s->slot(a, b), s->slot(b, a)});
    }
    for (int k : graph.component_slits[c]) {
        const int t = local(graph.slits[k].body_through), u = local(graph.slits[k].body_cut);
        s->slits.push_back({s->slot(t, t), s->slot(u, u), s->slot(t, u), s->slot(u, t)});
    }
    s->ldlt.analyzePattern(s->A);
    systems[c] = std::move(s);
    return *systems[c];
}

bool SparseLeastSquares::linearize(int c, const Configuration& q,
                                   const std::vector<BranchHint>* hints, System& s) const
{
    const BodyGraph& graph = equations_.graph();
    s.A.coeffs().setZero();
    s.g.setZero();
    // Where a free body's unknowns are in the system (its bodies are in their own order).
    auto at = [&](int body) { return s.column[equations_.column_of_body(body) / 6]; };
    // The blocks of the dense assembly, added in the same order (so the sums are the same).
    const auto& joints = graph.component_joints[c];
    for (size_t k = 0; k < joints.size(); ++k) {
        const Joint& joint = graph.joints[joints[k]];
        const bool free_a = !graph.is_base(joint.body_a);
        const bool free_b = !graph.is_base(joint.body_b);
        System::JointAssembly to{
            s, s.joints[k], {free_a ? at(joint.body_a) : -1, free_b ? at(joint.body_b) : -1}};
        for (const Vec3& x : joint.ends)
            add_normal_terms(hinge_end_rows(joint, x, q, graph, equations_.size()), free_a, free_b,
                             to);
    }
    const auto& slits = graph.component_slits[c];
    for (size_t k = 0; k < slits.size(); ++k) {
        const SlitJoint& sl = graph.slits[slits[k]];
        const bool free_t = !graph.is_base(sl.body_through);
        const bool free_c = !graph.is_base(sl.body_cut);
        System::JointAssembly to{
            s, s.slits[k], {free_t ? at(sl.body_through) : -1, free_c ? at(sl.body_cut) : -1}};
        for (int e = 0; e < 2; ++e)
            add_normal_terms(slit_row(sl, e, q, graph, equations_.size()), free_t, free_c, to);
    }
    if (!hints)
        return true;
    // A hint's residual depends on the poses of its two patches' bodies only: its row has at
    // most 12 non-zero columns, and the other differences are exactly zero.
    for (const BranchHint& hint : *hints) {
        int bodies[2], count = 0;
        for (int patch : {hint.patch_a, hint.patch_b}) {
            const int body = graph.body_of_patch[patch];
            if (graph.component_of_body[body] == c &&
                std::find(bodies, bodies + count, body) == bodies + count)
                bodies[count++] = body;
        }
        if (count == 0)
            continue;
        System::Slot slots[2][2];
        for (int i = 0; i < count; ++i)
            for (int j = 0; j < count; ++j) {
                slots[i][j] = s.slot(equations_.column_of_body(bodies[i]) / 6,
                                     equations_.column_of_body(bodies[j]) / 6);
                if (slots[i][j].first < 0)
                    return false;
            }
        const double f = equations_.hint_residual(hint, q);
        Vec6 row[2];
        for (int i = 0; i < count; ++i) {
            const int col = equations_.column_of_body(bodies[i]);
            equations_.hint_gradient(c, hint, q, f, col, col + 6, row[i]);
        }
        for (int i = 0; i < count; ++i) {
            for (int j = 0; j < count; ++j)
                s.add(slots[i][j], row[i] * row[j].transpose());
            s.g.segment<6>(at(bodies[i])) += row[i] * f;
        }
    }
    return true;
}

bool SparseLeastSquares::least_squares(int c, Configuration& q,
                                       const std::vector<BranchHint>* hints, int max_iterations,
                                       bool to_round_off) const
{
    System& s = system(c);
    const auto& bodies = equations_.graph().components[c];
    Eigen::VectorXd step, d(6 * bodies.size());
    int iterations = 0;
    const std::optional<bool> converged = damped_least_squares(
        equations_, c, q, hints, max_iterations, to_round_off, iterations,
        [&] { return linearize(c, q, hints, s); },
        [&](double lambda) {
            s.set_diagonal(lambda, 1e-14);
            if (!s.factorize_positive())
                return false;
            step = s.ldlt.solve(s.g);
            for (size_t k = 0; k < bodies.size(); ++k) // back to the component's order
                d.segment<6>(6 * k) = -step.segment<6>(s.column[k]);
            equations_.apply_step(c, q, d);
            return true;
        });
    if (converged)
        return *converged;
    // A hint couples bodies outside the sparse pattern (hints from elsewhere than hints(c)).
    return least_squares_dense(equations_, c, q, hints, max_iterations - iterations, to_round_off);
}

bool SparseLeastSquares::small_eigenvalue(int c, const Configuration& q) const
{
    System& s = system(c);
    linearize(c, q, nullptr, s);
    // A - τI has as many negative pivots as A has eigenvalues below τ (Sylvester's law of
    // inertia), whatever the elimination order: the rank test is one factorisation.
    auto below = [&](double largest) {
        s.set_diagonal(0.0, -1e-12 * std::max(largest, 1.0));
        return !s.factorize_positive();
    };
    // First against the largest absolute column sum, which bounds λmax from above: a
    // component that passes there passes (the usual case, rigid and regular).
    double bound = 0.0;
    for (int k = 0; k < s.A.outerSize(); ++k) {
        double sum = 0.0;
        for (int i = s.A.outerIndexPtr()[k]; i < s.A.outerIndexPtr()[k + 1]; ++i)
            sum += std::abs(s.A.valuePtr()[i]);
        bound = std::max(bound, sum);
    }
    if (!below(bound))
        return false;
    // Otherwise λmax itself, by power iteration (the Rayleigh quotient, from below, to 1e-4).
    Eigen::VectorXd v = Eigen::VectorXd::Ones(s.A.cols()).normalized(), w;
    double largest = 0.0;
    for (int it = 0; it < 200; ++it) {
        w.noalias() = s.A * v;
        const double rayleigh = v.dot(w);
        const double norm = w.norm();
        const bool settled = std::abs(rayleigh - largest) <= 1e-4 * rayleigh;
        largest = rayleigh;
        if (settled || !(norm > 0.0))
            break;
        v = w / norm;
    }
    return below(largest);
}

} // namespace popup
