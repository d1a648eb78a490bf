#include "fold_solver.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/SVD>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace popup {

namespace {

Mat3 skew(const Vec3& v)
{
    Mat3 m;
    m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
    return m;
}

Vec3 place(const BodyPose& pose, const Vec3& center, const Vec3& x)
{
    return pose.rotation * (x - center) + pose.position;
}

// Signed distance of a slit end from the plane of the body passing through, and its gradient
// with respect to both bodies' motions (rotation parts scaled by `size`; docs/MATH.md, Slits).
struct SlitRow {
    double distance;
    Eigen::Matrix<double, 6, 1> through;
    Eigen::Matrix<double, 6, 1> cut;
};

SlitRow slit_row(const SlitJoint& sl, int e, const Configuration& q, const BodyGraph& g,
                 double size)
{
    const BodyPose& t = q[sl.body_through];
    const BodyPose& c = q[sl.body_cut];
    const Vec3 n = t.rotation * sl.plane_normal;
    const Vec3 on_plane = place(t, g.center[sl.body_through], sl.plane_point);
    const Vec3 arm = c.rotation * (sl.ends[e] - g.center[sl.body_cut]);
    const Vec3 end = arm + c.position;
    SlitRow r;
    r.distance = n.dot(end - on_plane);
    r.through << n.cross(end - t.position) / size, -n;
    r.cut << arm.cross(n) / size, n;
    return r;
}

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;

} // namespace

/// Normal equations of one component as a sparse matrix with a fixed pattern: a 6x6 block for
/// each body and for each pair of bodies a hinge, a slit or a branch hint couples, both
/// triangles stored. The pattern's fill-reducing ordering and elimination tree are computed once
/// (analyzePattern); each Newton step only refactorises.
struct FoldSolver::SparseSystem {
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
};

FoldSolver::~FoldSolver() = default;

bool FoldSolver::uses_sparse(int c) const
{
    return !options_.dense_linear_algebra && int(graph_.components[c].size()) >= kSparseFromBodies;
}

FoldSolver::SparseSystem& FoldSolver::sparse_system(int c) const
{
    std::vector<std::unique_ptr<SparseSystem>>& systems = sparse_.local();
    if (systems.empty())
        systems.resize(graph_.components.size());
    if (systems[c])
        return *systems[c];
    auto s = std::make_unique<SparseSystem>();
    const int nb = int(graph_.components[c].size());
    // Local body index of a body of this component, -1 for the base (no unknowns).
    auto local = [&](int body) {
        return graph_.component_of_body[body] == c ? column_of_body_[body] / 6 : -1;
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
    for (int j : graph_.component_joints[c])
        couple(local(graph_.joints[j].body_a), local(graph_.joints[j].body_b));
    for (int k : graph_.component_slits[c])
        couple(local(graph_.slits[k].body_through), local(graph_.slits[k].body_cut));
    for (const BranchHint& hint : hints_[c])
        couple(local(graph_.body_of_patch[hint.patch_a]),
               local(graph_.body_of_patch[hint.patch_b]));
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
    s->A = Eigen::Map<SparseSystem::Matrix>(n, n, int(inner.size()), outer.data(), inner.data(),
                                            zeros.data());
    s->M = s->A;
    s->g.resize(n);
    for (int j : graph_.component_joints[c]) {
        const int a = local(graph_.joints[j].body_a), b = local(graph_.joints[j].body_b);
        s->joints.push_back({s->slot(a, a), s->slot(b, b), s->slot(a, b), s->slot(b, a)});
    }
    for (int k : graph_.component_slits[c]) {
        const int t = local(graph_.slits[k].body_through), u = local(graph_.slits[k].body_cut);
        s->slits.push_back({s->slot(t, t), s->slot(u, u), s->slot(t, u), s->slot(u, t)});
    }
    s->ldlt.analyzePattern(s->A);
    systems[c] = std::move(s);
    return *systems[c];
}

FoldSolver::FoldSolver(const Scaffold& scaffold, const BodyGraph& graph,
                       const SimulationOptions& options)
    : scaffold_(scaffold), graph_(graph), options_(options)
{
    size_ = std::max(scaffold.size(), 1e-3);
    tolerance_ = 1e-11 * size_;
    column_of_body_.assign(graph.body_count, -1);
    for (const auto& bodies : graph.components)
        for (size_t k = 0; k < bodies.size(); ++k)
            column_of_body_[bodies[k]] = int(6 * k);

    for (const Hinge& h : scaffold.hinges)
        hinge_patches_.push_back(
            {scaffold.patch_index(h.patch_a), scaffold.patch_index(h.patch_b)});
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

Configuration FoldSolver::design_configuration() const
{
    Configuration q(graph_.body_count);
    for (int b = 0; b < graph_.body_count; ++b)
        q[b].position = graph_.center[b];
    return q;
}

void FoldSolver::drive_base(double theta, Configuration& q) const
{
    const Pose g = ground_pose(scaffold_, theta);
    const Pose b = backdrop_pose(scaffold_, theta);
    q[graph_.ground] = {g.rotation, g.apply(graph_.center[graph_.ground])};
    q[graph_.backdrop] = {b.rotation, b.apply(graph_.center[graph_.backdrop])};
}

void FoldSolver::constraint_system(int c, const Configuration& q, Eigen::VectorXd& r,
                                   Eigen::MatrixXd& J) const
{
    const auto& joints = graph_.component_joints[c];
    const auto& slits = graph_.component_slits[c];
    const int n = int(6 * graph_.components[c].size());
    const int hinge_rows = int(6 * joints.size());
    r.resize(hinge_rows + 2 * slits.size());
    J.setZero(hinge_rows + 2 * slits.size(), n);
    for (size_t k = 0; k < slits.size(); ++k) {
        const SlitJoint& sl = graph_.slits[slits[k]];
        for (int e = 0; e < 2; ++e) {
            const int rowi = hinge_rows + int(2 * k) + e;
            const SlitRow row = slit_row(sl, e, q, graph_, size_);
            r[rowi] = row.distance;
            if (!graph_.is_base(sl.body_through))
                J.block<1, 6>(rowi, column_of_body_[sl.body_through]) = row.through.transpose();
            if (!graph_.is_base(sl.body_cut))
                J.block<1, 6>(rowi, column_of_body_[sl.body_cut]) += row.cut.transpose();
        }
    }
    for (size_t k = 0; k < joints.size(); ++k) {
        const Joint& joint = graph_.joints[joints[k]];
        for (int e = 0; e < 2; ++e) {
            const int row = int(6 * k + 3 * e);
            const Vec3& x = joint.ends[e];
            const Vec3 arm_a = q[joint.body_a].rotation * (x - graph_.center[joint.body_a]);
            const Vec3 arm_b = q[joint.body_b].rotation * (x - graph_.center[joint.body_b]);
            r.segment<3>(row) =
                (arm_a + q[joint.body_a].position) - (arm_b + q[joint.body_b].position);
            const int ca = column_of_body_[joint.body_a];
            const int cb = column_of_body_[joint.body_b];
            if (!graph_.is_base(joint.body_a)) {
                J.block<3, 3>(row, ca) = -skew(arm_a) / size_;
                J.block<3, 3>(row, ca + 3) = Mat3::Identity();
            }
            if (!graph_.is_base(joint.body_b)) {
                J.block<3, 3>(row, cb) = skew(arm_b) / size_;
                J.block<3, 3>(row, cb + 3) = -Mat3::Identity();
            }
        }
    }
}

Eigen::MatrixXd FoldSolver::jacobian(int c, const Configuration& q) const
{
    Eigen::VectorXd r;
    Eigen::MatrixXd J;
    constraint_system(c, q, r, J);
    return J;
}

double FoldSolver::fold_sine(const BranchHint& hint, const Configuration& q) const
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

template <class Vector> void FoldSolver::apply_step(int c, Configuration& q, const Vector& d) const
{
    const auto& bodies = graph_.components[c];
    for (size_t k = 0; k < bodies.size(); ++k) {
        BodyPose& p = q[bodies[k]];
        p.rotation = rotation_exp(d.template segment<3>(6 * k) / size_) * p.rotation;
        p.position += d.template segment<3>(6 * k + 3);
    }
}

double FoldSolver::hint_residual(const BranchHint& hint, const Configuration& q) const
{
    const double weight = 0.1 * size_;
    const double target = 0.02; // sine of a small opening on the intended side
    return weight * (hint.sign * fold_sine(hint, q) - target);
}

double FoldSolver::cost(int c, const Configuration& q, const std::vector<BranchHint>* hints,
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

template <class Matrix, class Vector>
void FoldSolver::linearize_into(int c, const Configuration& q, const std::vector<BranchHint>* hints,
                                Matrix& A, Vector& g) const
{
    const int n = int(6 * graph_.components[c].size());
    A.setZero();
    g.setZero();
    // Each hinge end touches at most two bodies: assemble JᵀJ and Jᵀr from 3x6 blocks.
    for (int j : graph_.component_joints[c]) {
        const Joint& joint = graph_.joints[j];
        const bool free_a = !graph_.is_base(joint.body_a);
        const bool free_b = !graph_.is_base(joint.body_b);
        const int ca = column_of_body_[joint.body_a];
        const int cb = column_of_body_[joint.body_b];
        for (const Vec3& x : joint.ends) {
            const Vec3 arm_a = q[joint.body_a].rotation * (x - graph_.center[joint.body_a]);
            const Vec3 arm_b = q[joint.body_b].rotation * (x - graph_.center[joint.body_b]);
            const Vec3 r = (arm_a + q[joint.body_a].position) - (arm_b + q[joint.body_b].position);
            // With a = arm_a/size, b = arm_b/size the blocks are Ja = [-[a]x, I] and
            // Jb = [[b]x, -I]; their products reduce to 3x3 terms (docs/MATH.md, Solver).
            const Vec3 a = arm_a / size_;
            const Vec3 b = arm_b / size_;
            const Mat3 I = Mat3::Identity();
            if (free_a) {
                const Mat3 Sa = -skew(a);
                A.template block<3, 3>(ca, ca) += a.squaredNorm() * I - a * a.transpose();
                A.template block<3, 3>(ca, ca + 3) += Sa.transpose();
                A.template block<3, 3>(ca + 3, ca) += Sa;
                A.template block<3, 3>(ca + 3, ca + 3) += I;
                g.template segment<3>(ca) += a.cross(r);
                g.template segment<3>(ca + 3) += r;
            }
            if (free_b) {
                const Mat3 Sb = skew(b);
                A.template block<3, 3>(cb, cb) += b.squaredNorm() * I - b * b.transpose();
                A.template block<3, 3>(cb, cb + 3) -= Sb.transpose();
                A.template block<3, 3>(cb + 3, cb) -= Sb;
                A.template block<3, 3>(cb + 3, cb + 3) += I;
                g.template segment<3>(cb) -= b.cross(r);
                g.template segment<3>(cb + 3) -= r;
            }
            if (free_a && free_b) {
                // Jaᵀ Jb = [[a]x[b]x, -[a]x; [b]x, -I] and its transpose.
                Eigen::Matrix<double, 6, 6> ab;
                ab << skew(a) * skew(b), -skew(a), skew(b), -I;
                A.template block<6, 6>(ca, cb) += ab;
                A.template block<6, 6>(cb, ca) += ab.transpose();
            }
        }
    }
    for (int k : graph_.component_slits[c]) {
        const SlitJoint& sl = graph_.slits[k];
        const bool free_t = !graph_.is_base(sl.body_through);
        const bool free_c = !graph_.is_base(sl.body_cut);
        const int ct = column_of_body_[sl.body_through];
        const int cc = column_of_body_[sl.body_cut];
        for (int e = 0; e < 2; ++e) {
            const SlitRow row = slit_row(sl, e, q, graph_, size_);
            if (free_t) {
                const Eigen::Matrix<double, 6, 6> tt = row.through * row.through.transpose();
                A.template block<6, 6>(ct, ct) += tt;
                g.template segment<6>(ct) += row.through * row.distance;
            }
            if (free_c) {
                const Eigen::Matrix<double, 6, 6> cc_block = row.cut * row.cut.transpose();
                A.template block<6, 6>(cc, cc) += cc_block;
                g.template segment<6>(cc) += row.cut * row.distance;
            }
            if (free_t && free_c) {
                const Eigen::Matrix<double, 6, 6> tc = row.through * row.cut.transpose();
                A.template block<6, 6>(ct, cc) += tc;
                A.template block<6, 6>(cc, ct) += tc.transpose();
            }
        }
    }
    if (!hints)
        return;
    // Hint rows by differences: used once per design state, so speed does not matter here.
    for (const BranchHint& hint : *hints) {
        const double f = hint_residual(hint, q);
        Eigen::VectorXd row(n);
        hint_gradient(c, hint, q, f, 0, n, row);
        A += row * row.transpose();
        g += row * f;
    }
}

template <class Row>
void FoldSolver::hint_gradient(int c, const BranchHint& hint, const Configuration& q, double f,
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

bool FoldSolver::linearize_sparse(int c, const Configuration& q,
                                  const std::vector<BranchHint>* hints, SparseSystem& s) const
{
    s.A.coeffs().setZero();
    s.g.setZero();
    const Mat3 I = Mat3::Identity();
    // Where a free body's unknowns are in the system (its bodies are in their own order).
    auto at = [&](int body) { return s.column[column_of_body_[body] / 6]; };
    // The blocks of linearize_into, added in the same order (so the sums are the same).
    const auto& joints = graph_.component_joints[c];
    for (size_t k = 0; k < joints.size(); ++k) {
        const Joint& joint = graph_.joints[joints[k]];
        const bool free_a = !graph_.is_base(joint.body_a);
        const bool free_b = !graph_.is_base(joint.body_b);
        const int ca = free_a ? at(joint.body_a) : -1;
        const int cb = free_b ? at(joint.body_b) : -1;
        const auto& slot = s.joints[k];
        for (const Vec3& x : joint.ends) {
            const Vec3 arm_a = q[joint.body_a].rotation * (x - graph_.center[joint.body_a]);
            const Vec3 arm_b = q[joint.body_b].rotation * (x - graph_.center[joint.body_b]);
            const Vec3 r = (arm_a + q[joint.body_a].position) - (arm_b + q[joint.body_b].position);
            const Vec3 a = arm_a / size_;
            const Vec3 b = arm_b / size_;
            if (free_a) {
                const Mat3 Sa = -skew(a);
                Mat6 aa;
                aa << a.squaredNorm() * I - a * a.transpose(), Sa.transpose(), Sa, I;
                s.add(slot[0], aa);
                s.g.segment<3>(ca) += a.cross(r);
                s.g.segment<3>(ca + 3) += r;
            }
            if (free_b) {
                const Mat3 Sb = skew(b);
                Mat6 bb;
                bb << b.squaredNorm() * I - b * b.transpose(), -Sb.transpose(), -Sb, I;
                s.add(slot[1], bb);
                s.g.segment<3>(cb) -= b.cross(r);
                s.g.segment<3>(cb + 3) -= r;
            }
            if (free_a && free_b) {
                Mat6 ab;
                ab << skew(a) * skew(b), -skew(a), skew(b), -I;
                s.add(slot[2], ab);
                s.add(slot[3], ab.transpose());
            }
        }
    }
    const auto& slits = graph_.component_slits[c];
    for (size_t k = 0; k < slits.size(); ++k) {
        const SlitJoint& sl = graph_.slits[slits[k]];
        const bool free_t = !graph_.is_base(sl.body_through);
        const bool free_c = !graph_.is_base(sl.body_cut);
        const int ct = free_t ? at(sl.body_through) : -1;
        const int cc = free_c ? at(sl.body_cut) : -1;
        const auto& slot = s.slits[k];
        for (int e = 0; e < 2; ++e) {
            const SlitRow row = slit_row(sl, e, q, graph_, size_);
            if (free_t) {
                s.add(slot[0], row.through * row.through.transpose());
                s.g.segment<6>(ct) += row.through * row.distance;
            }
            if (free_c) {
                s.add(slot[1], row.cut * row.cut.transpose());
                s.g.segment<6>(cc) += row.cut * row.distance;
            }
            if (free_t && free_c) {
                const Mat6 tc = row.through * row.cut.transpose();
                s.add(slot[2], tc);
                s.add(slot[3], tc.transpose());
            }
        }
    }
    if (!hints)
        return true;
    // A hint's residual depends on the poses of its two patches' bodies only: its row has at
    // most 12 non-zero columns, and the other differences are exactly zero.
    for (const BranchHint& hint : *hints) {
        int bodies[2], count = 0;
        for (int patch : {hint.patch_a, hint.patch_b}) {
            const int body = graph_.body_of_patch[patch];
            if (graph_.component_of_body[body] == c &&
                std::find(bodies, bodies + count, body) == bodies + count)
                bodies[count++] = body;
        }
        if (count == 0)
            continue;
        SparseSystem::Slot slots[2][2];
        for (int i = 0; i < count; ++i)
            for (int j = 0; j < count; ++j) {
                slots[i][j] =
                    s.slot(column_of_body_[bodies[i]] / 6, column_of_body_[bodies[j]] / 6);
                if (slots[i][j].first < 0)
                    return false;
            }
        const double f = hint_residual(hint, q);
        Vec6 row[2];
        for (int i = 0; i < count; ++i) {
            const int col = column_of_body_[bodies[i]];
            hint_gradient(c, hint, q, f, col, col + 6, row[i]);
        }
        for (int i = 0; i < count; ++i) {
            for (int j = 0; j < count; ++j)
                s.add(slots[i][j], row[i] * row[j].transpose());
            s.g.segment<6>(at(bodies[i])) += row[i] * f;
        }
    }
    return true;
}

void FoldSolver::linearize(int c, const Configuration& q, const std::vector<BranchHint>* hints,
                           Eigen::MatrixXd& A, Eigen::VectorXd& g) const
{
    const int n = int(6 * graph_.components[c].size());
    A.resize(n, n);
    g.resize(n);
    linearize_into(c, q, hints, A, g);
}

template <class Linearize, class SolveAndApply>
std::optional<bool>
FoldSolver::damped_least_squares(int c, Configuration& q, const std::vector<BranchHint>* hints,
                                 int max_iterations, bool to_round_off, int& iterations,
                                 Linearize&& linearize, SolveAndApply&& solve_and_apply) const
{
    const auto& bodies = graph_.components[c];
    thread_local std::vector<BodyPose> saved; // once per thread, not per correction
    saved.resize(bodies.size());
    double worst = 0.0;
    double current = cost(c, q, hints, &worst);
    double lambda = 1e-6;
    for (iterations = 0; iterations < max_iterations; ++iterations) {
        if (!hints && !to_round_off && worst <= tolerance_)
            return true;
        if (!linearize())
            return std::nullopt;
        bool improved = false;
        while (lambda < 1e10) {
            // Try the step in place; only this component's bodies are saved for a rollback.
            for (size_t k = 0; k < bodies.size(); ++k)
                saved[k] = q[bodies[k]];
            // A failed factorisation (round-off on a singular A) is a rejected step.
            if (!solve_and_apply(lambda)) {
                lambda *= 8.0;
                continue;
            }
            double worst2 = 0.0;
            const double trial = cost(c, q, hints, &worst2);
            if (trial < current || (trial == 0.0 && current == 0.0)) {
                improved = current - trial > 1e-30 * size_ * size_;
                current = trial;
                worst = worst2;
                lambda = std::max(lambda * 0.25, 1e-12);
                break;
            }
            for (size_t k = 0; k < bodies.size(); ++k)
                q[bodies[k]] = saved[k];
            lambda *= 8.0;
        }
        if (!improved)
            break;
    }
    if (hints)
        return true; // the hinted pass only positions the guess; the plain pass must converge
    return worst <= tolerance_;
}

template <int N>
bool FoldSolver::least_squares_sized(int c, Configuration& q, const std::vector<BranchHint>* hints,
                                     int max_iterations, bool to_round_off) const
{
    using Matrix = Eigen::Matrix<double, N, N>;
    using Vector = Eigen::Matrix<double, N, 1>;
    const int n = int(6 * graph_.components[c].size());
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
        c, q, hints, max_iterations, to_round_off, iterations,
        [&] {
            linearize_into(c, q, hints, A, g);
            return true;
        },
        [&](double lambda) {
            M = A;
            M.diagonal().array() += lambda * A.diagonal().array() + 1e-14;
            llt.compute(M);
            d.noalias() = llt.solve(g);
            d = -d;
            apply_step(c, q, d);
            return true;
        });
}

bool FoldSolver::least_squares_sparse(int c, Configuration& q, const std::vector<BranchHint>* hints,
                                      int max_iterations, bool to_round_off) const
{
    SparseSystem& s = sparse_system(c);
    const auto& bodies = graph_.components[c];
    Eigen::VectorXd step, d(6 * bodies.size());
    int iterations = 0;
    const std::optional<bool> converged = damped_least_squares(
        c, q, hints, max_iterations, to_round_off, iterations,
        [&] { return linearize_sparse(c, q, hints, s); },
        [&](double lambda) {
            s.set_diagonal(lambda, 1e-14);
            if (!s.factorize_positive())
                return false;
            step = s.ldlt.solve(s.g);
            for (size_t k = 0; k < bodies.size(); ++k) // back to the component's order
                d.segment<6>(6 * k) = -step.segment<6>(s.column[k]);
            apply_step(c, q, d);
            return true;
        });
    if (converged)
        return *converged;
    // A hint couples bodies outside the sparse pattern (hints from elsewhere than hints(c)).
    return least_squares_sized<Eigen::Dynamic>(c, q, hints, max_iterations - iterations,
                                               to_round_off);
}

bool FoldSolver::small_eigenvalue(int c, const Configuration& q) const
{
    SparseSystem& s = sparse_system(c);
    linearize_sparse(c, q, nullptr, s);
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

bool FoldSolver::least_squares(int c, Configuration& q, const std::vector<BranchHint>* hints,
                               int max_iterations, bool to_round_off) const
{
    if (uses_sparse(c))
        return least_squares_sparse(c, q, hints, max_iterations, to_round_off);
    // Most mechanisms are one or two free bodies: fixed-size algebra avoids heap traffic there.
    switch (graph_.components[c].size()) {
    case 0:
        return true;
    case 1:
        return least_squares_sized<6>(c, q, hints, max_iterations, to_round_off);
    case 2:
        return least_squares_sized<12>(c, q, hints, max_iterations, to_round_off);
    default:
        return least_squares_sized<Eigen::Dynamic>(c, q, hints, max_iterations, to_round_off);
    }
}

namespace {

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

} // namespace

template <int N> bool FoldSolver::rigid_sized(int c, const Configuration& q) const
{
    const int n = int(6 * graph_.components[c].size());
    Eigen::Matrix<double, N, N> A(n, n);
    Eigen::Matrix<double, N, 1> g(n);
    linearize_into(c, q, nullptr, A, g);
    if constexpr (N != Eigen::Dynamic)
        if (clearly_positive_definite<N>(A))
            return true;
    const Eigen::Matrix<double, N, 1> pivots = A.ldlt().vectorD();
    const double scale = std::max(pivots.cwiseAbs().maxCoeff(), 1.0);
    return (pivots.array() > 1e-12 * scale).all();
}

bool FoldSolver::rigid(int c, const Configuration& q) const
{
    if (uses_sparse(c))
        return !small_eigenvalue(c, q);
    switch (graph_.components[c].size()) {
    case 0:
        return true;
    case 1:
        return rigid_sized<6>(c, q);
    case 2:
        return rigid_sized<12>(c, q);
    default:
        return rigid_sized<Eigen::Dynamic>(c, q);
    }
}

bool FoldSolver::correct(int c, Configuration& q, const std::vector<BranchHint>& hints,
                         int max_iterations, bool to_round_off) const
{
    if (!hints.empty())
        least_squares(c, q, &hints, max_iterations, false);
    return least_squares(c, q, nullptr, max_iterations, to_round_off);
}

FoldState FoldSolver::state(double theta, const Configuration& q) const
{
    FoldState s;
    s.angle = theta;
    s.poses.resize(scaffold_.patches.size());
    for (size_t i = 0; i < scaffold_.patches.size(); ++i) {
        const int b = graph_.body_of_patch[i];
        s.poses[i].rotation = q[b].rotation;
        s.poses[i].translation = q[b].position - q[b].rotation * graph_.center[b];
    }
    for (size_t k = 0; k < scaffold_.hinges.size(); ++k) {
        const Hinge& h = scaffold_.hinges[k];
        const Pose& a = s.poses[hinge_patches_[k][0]];
        const Pose& b = s.poses[hinge_patches_[k][1]];
        for (const Vec3& x : {h.from, h.to})
            s.hinge_residual = std::max(s.hinge_residual, (a.apply(x) - b.apply(x)).norm());
    }
    for (const SlitJoint& sl : graph_.slits)
        for (int e = 0; e < 2; ++e)
            s.hinge_residual =
                std::max(s.hinge_residual, std::abs(slit_row(sl, e, q, graph_, size_).distance));
    for (size_t i = 0; i < scaffold_.patches.size(); ++i) {
        const Loop3& loop = scaffold_.patches[i].outer;
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
    Configuration q(graph_.body_count);
    for (size_t i = 0; i < scaffold_.patches.size(); ++i) {
        const int b = graph_.body_of_patch[i];
        q[b].rotation = state.poses[i].rotation;
        q[b].position = state.poses[i].apply(graph_.center[b]);
    }
    return q;
}

ComponentTrack::ComponentTrack(const FoldSolver& solver, int component, double angle,
                               const Configuration& start, bool at_design)
    : solver_(solver), component_(component), theta_(angle), current_(start), previous_(start),
      guess_(start), step_(solver.options().max_step), at_design_(at_design)
{
    solver.drive_base(theta_, current_);
}

bool ComponentTrack::advance_to(double target)
{
    const SimulationOptions& options = solver_.options();
    while (theta_ != target) {
        const double gap = target - theta_;
        const double next = std::abs(gap) <= step_ ? target : theta_ + std::copysign(step_, gap);
        if (try_step(next)) {
            step_ = std::min(step_ * 1.5, options.max_step);
            if (theta_ == target && (target == 0.0 || target == M_PI) &&
                solver_.singular(component_, current_))
                take_limit_at_end();
        } else {
            step_ *= 0.5;
            if (step_ < options.min_step) {
                locked_ = theta_;
                return false;
            }
        }
    }
    return true;
}

bool FoldSolver::singular(int c, const Configuration& q) const
{
    // σ² are the eigenvalues of JᵀJ when J has at least as many rows as columns.
    const size_t rows =
        6 * graph_.component_joints[c].size() + 2 * graph_.component_slits[c].size();
    if (uses_sparse(c) && rows >= 6 * graph_.components[c].size())
        return small_eigenvalue(c, q);
    const Eigen::MatrixXd J = jacobian(c, q);
    if (J.cols() == 0)
        return false;
    if (J.rows() == 0) // no constraint at all: every motion is free
        return true;
    const Eigen::VectorXd s = Eigen::JacobiSVD<Eigen::MatrixXd>(J).singularValues();
    return s.minCoeff() <= 1e-6 * std::max(s.maxCoeff(), 1.0);
}

void ComponentTrack::take_limit_at_end()
{
    if (previous_step_ == 0.0)
        return;
    // Cubic extrapolation from four states 1e-3 rad apart on the branch (error ~ h⁴ L).
    const double h = 1e-3;
    const double weights[4] = {4.0, -6.0, 4.0, -1.0};
    const auto& bodies = solver_.graph().components[component_];
    std::vector<Configuration> nodes;
    for (int k = 1; k <= 4; ++k) {
        const double t = k * h / std::abs(previous_step_); // fraction of the way back
        Configuration q = current_;
        for (int b : bodies) {
            const Mat3 turn = previous_[b].rotation * current_[b].rotation.transpose();
            q[b].rotation = rotation_exp(t * rotation_log(turn)) * current_[b].rotation;
            q[b].position += t * (previous_[b].position - current_[b].position);
        }
        solver_.drive_base(theta_ - std::copysign(k * h, previous_step_), q);
        if (!solver_.correct(component_, q, {}, solver_.options().max_newton_iterations, true))
            return;
        nodes.push_back(std::move(q));
    }
    for (int b : bodies) {
        Vec3 turn = Vec3::Zero(), position = Vec3::Zero();
        for (int k = 0; k < 4; ++k) {
            turn +=
                weights[k] * rotation_log(nodes[k][b].rotation * nodes[0][b].rotation.transpose());
            position += weights[k] * nodes[k][b].position;
        }
        current_[b].rotation = rotation_exp(turn) * nodes[0][b].rotation;
        current_[b].position = position;
    }
}

bool ComponentTrack::try_step(double next)
{
    const double h = next - theta_;
    const auto& bodies = solver_.graph().components[component_];
    // Only this component's bodies and the base matter: copy those, not the whole card.
    Configuration& guess = guess_;
    for (int b : bodies)
        guess[b] = current_[b];
    solver_.drive_base(next, guess);
    if (!at_design_ && previous_step_ != 0.0) {
        // Secant predictor along the branch already followed.
        const double s = h / previous_step_;
        for (int b : bodies) {
            const Mat3 turn = current_[b].rotation * previous_[b].rotation.transpose();
            guess[b].rotation = rotation_exp(s * rotation_log(turn)) * current_[b].rotation;
            guess[b].position =
                current_[b].position + s * (current_[b].position - previous_[b].position);
        }
    }
    static const std::vector<BranchHint> none;
    const auto& hints = at_design_ ? solver_.hints(component_) : none;
    if (!solver_.correct(component_, guess, hints, solver_.options().max_newton_iterations))
        return false;
    for (int b : bodies) {
        const Mat3 turn = guess[b].rotation * current_[b].rotation.transpose();
        if (Eigen::AngleAxisd(turn).angle() > 0.5)
            return false; // a jump this large in one step means another branch
    }
    if (at_design_)
        for (const BranchHint& hint : hints)
            if (hint.sign * solver_.fold_sine(hint, guess) <= 0.0)
                branch_ok_ = false;
    previous_.swap(current_);
    current_.swap(guess_);
    previous_step_ = h;
    theta_ = next;
    at_design_ = false;
    return true;
}

} // namespace popup
