#include "collision_volume.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace popup::motion {

std::array<Vec3, 8> OrientedBox::corners() const
{
    std::array<Vec3, 8> c;
    for (int k = 0; k < 8; ++k) {
        const Vec3 s((k & 1) ? 1.0 : -1.0, (k & 2) ? 1.0 : -1.0, (k & 4) ? 1.0 : -1.0);
        c[k] = centre + axes * s.cwiseProduct(half);
    }
    return c;
}

double overlap_depth(const OrientedBox& a, const OrientedBox& b)
{
    const Vec3 d = b.centre - a.centre;
    if (a.axes == Mat3::Identity() && b.axes == Mat3::Identity()) {
        // Two axis-aligned boxes (every collision volume): the 15 axes reduce to the three
        // coordinate axes (the edge crossings are ±e_k or zero), with the same overlaps.
        const Vec3 overlap = a.half + b.half - d.cwiseAbs();
        return overlap.minCoeff() <= 0 ? 0.0 : overlap.minCoeff();
    }
    double depth = std::numeric_limits<double>::infinity();
    // The shadow of a box on unit axis n has radius Σ half_i |axis_i · n|; the boxes overlap on
    // n by ra + rb − |d·n|.
    auto test = [&](const Vec3& axis) {
        const double len = axis.norm();
        if (len < 1e-9)
            return true; // parallel edges: the face axes decide
        const Vec3 n = axis / len;
        const double ra = a.half.x() * std::abs(a.axes.col(0).dot(n)) +
                          a.half.y() * std::abs(a.axes.col(1).dot(n)) +
                          a.half.z() * std::abs(a.axes.col(2).dot(n));
        const double rb = b.half.x() * std::abs(b.axes.col(0).dot(n)) +
                          b.half.y() * std::abs(b.axes.col(1).dot(n)) +
                          b.half.z() * std::abs(b.axes.col(2).dot(n));
        const double overlap = ra + rb - std::abs(d.dot(n));
        if (overlap <= 0)
            return false;
        depth = std::min(depth, overlap);
        return true;
    };
    for (int i = 0; i < 3; ++i)
        if (!test(a.axes.col(i)) || !test(b.axes.col(i)))
            return 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (!test(a.axes.col(i).cross(b.axes.col(j))))
                return 0.0;
    return depth;
}

namespace {

// The unit normal of a piece's plane (the largest cross of two edges from its first vertex);
// zero for a degenerate piece (no axis to test).
Vec3 piece_normal(const std::vector<Vec3>& v)
{
    Vec3 normal = Vec3::Zero();
    for (std::size_t i = 2; i < v.size(); ++i) {
        const Vec3 n = (v[1] - v[0]).cross(v[i] - v[0]);
        if (n.squaredNorm() > normal.squaredNorm())
            normal = n;
    }
    return normal.norm() < 1e-9 ? Vec3::Zero() : Vec3(normal.normalized());
}

// The shadow of piece i of v on unit axis n: its points', grown by its pad and swept by the
// offsets it is carried along.
std::pair<double, double> shadow(const CollisionVolume& v, std::size_t i, const Vec3& n)
{
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    const double nx = n.x(), ny = n.y(), nz = n.z();
    const double *x = v.xs.data(), *y = v.ys.data(), *z = v.zs.data();
#pragma omp simd reduction(min : lo) reduction(max : hi)
    for (int p = v.first[i]; p < v.first[i + 1]; ++p) {
        const double t = nx * x[p] + ny * y[p] + nz * z[p];
        lo = std::min(lo, t);
        hi = std::max(hi, t);
    }
    // A deviation within pad_i along each axis moves a shadow by at most the sum of |n_i| pad_i;
    // the hull of the points moved by offsets t has the shadow moved by n·t.
    const double pad = n.cwiseAbs().dot(v.pad[i]);
    double tlo = 0.0, thi = 0.0;
    for (const Vec3& t : v.carried) {
        tlo = std::min(tlo, n.dot(t));
        thi = std::max(thi, n.dot(t));
    }
    return {lo - pad + tlo, hi + pad + thi};
}

// Overlap of two pieces' shadows on unit axis n (<= 0: n separates them).
double shadow_overlap(const CollisionVolume& a, std::size_t ia, const CollisionVolume& b,
                      std::size_t ib, const Vec3& n)
{
    const auto [alo, ahi] = shadow(a, ia, n);
    const auto [blo, bhi] = shadow(b, ib, n);
    return std::min(ahi, bhi) - std::max(alo, blo);
}

// The smallest of `depth` and two pieces' shadow overlaps over the separating-axis candidates of
// two convex polygons (each plane's normal at the band's middle angle, the crosses of their
// edges); 0 when one separates them. The test stops once the overlap is at most `floor` (the
// caller keeps the larger of the two): the value returned is then some overlap <= floor.
double piece_overlap(const CollisionVolume& a, std::size_t ia, const CollisionVolume& b,
                     std::size_t ib, double depth, double floor = 0.0)
{
    auto test = [&](const Vec3& axis) {
        const double len = axis.norm();
        if (len < 1e-9)
            return true; // parallel edges: the other axes decide
        depth = std::min(depth, shadow_overlap(a, ia, b, ib, axis / len));
        return depth > floor;
    };
    if (!test(a.normals[ia]) || !test(b.normals[ib]))
        return std::max(depth, 0.0);
    for (int i = a.edge_first[ia]; i < a.edge_first[ia + 1]; ++i)
        for (int j = b.edge_first[ib]; j < b.edge_first[ib + 1]; ++j)
            if (!test(a.edges[i].cross(b.edges[j])))
                return std::max(depth, 0.0);
    return depth;
}

} // namespace

CollisionVolume collision_volume(const MotionMechanism& m, const VolumeOptions& options)
{
    CollisionVolume v;
    const int n = std::max(1, options.bands), k = std::max(2, options.samples_per_band);
    const int last = n * k;
    // The samples' pieces, kept per thread from call to call: the annealing builds a volume
    // per move, and allocating them each time doubled its cost.
    thread_local std::vector<std::vector<MechanismPart>> at;
    at.resize(last + 1);
    for (int j = 0; j <= last; ++j) {
        // Closed, every x is 0 and the volume holds the limit of x / sin(θ/2) (at 1e-7 rad,
        // within 1e-12 of it relatively).
        const double theta = j == 0 ? 1e-7 : M_PI * j / last;
        mechanism_parts(m, theta, at[j]);
        const double across = 1.0 / std::sin(theta / 2);
        for (MechanismPart& part : at[j])
            for (Vec3& x : part.vertices)
                x.x() *= across;
    }
    const std::size_t pieces = at[0].size();
    for (const MechanismPart& part : at[0])
        v.sides.push_back(part.side);
    // Half the largest second difference of each piece's vertices at each inner sample, per
    // axis: how far the piece may stray from the chords next to that sample.
    thread_local std::vector<Vec3> bend;
    bend.assign((last + 1) * pieces, Vec3::Zero());
    for (int j = 1; j < last; ++j)
        for (std::size_t i = 0; i < pieces; ++i) {
            const auto &before = at[j - 1][i].vertices, &here = at[j][i].vertices,
                       &after = at[j + 1][i].vertices;
            if (before.size() != here.size() || after.size() != here.size())
                continue; // the v-box's back corner has no root at some sample: no curve
            Vec3& b = bend[j * pieces + i];
            for (std::size_t q = 0; q < here.size(); ++q)
                b = b.cwiseMax((before[q] - 2 * here[q] + after[q]).cwiseAbs() / 2);
        }
    v.normals.reserve(n * pieces);
    v.aligned.reserve(n * pieces);
    v.pad.reserve(n * pieces);
    for (std::vector<double>* c : {&v.xs, &v.ys, &v.zs})
        c->reserve(n * (k + 1) * pieces * 4);
    v.first.reserve(n * pieces + 1);
    v.first.push_back(0);
    v.edge_first.reserve(n * pieces + 1);
    v.edge_first.push_back(0);
    const Vec3 clearance = Vec3::Constant(options.clearance);
    for (int band = 0; band < n; ++band) {
        const int first = band * k, end = first + k;
        // Second differences at every sample of the band that has neighbours on both sides:
        // each interval of the band has one at each of its ends.
        const int d_first = std::max(1, first), d_last = std::min(last - 1, end);
        Eigen::AlignedBox3d hull;
        for (std::size_t i = 0; i < pieces; ++i) {
            Vec3 bent = Vec3::Zero();
            for (int j = d_first; j <= d_last; ++j)
                bent = bent.cwiseMax(bend[j * pieces + i]);
            Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
            for (int j = first; j <= end; ++j)
                for (const Vec3& x : at[j][i].vertices) {
                    v.xs.push_back(x.x());
                    v.ys.push_back(x.y());
                    v.zs.push_back(x.z());
                    lo = lo.cwiseMin(x);
                    hi = hi.cwiseMax(x);
                }
            v.first.push_back(int(v.xs.size()));
            const std::vector<Vec3>& middle = at[first + k / 2][i].vertices;
            OrientedBox aligned;
            aligned.centre = (lo + hi) / 2;
            aligned.half = (hi - lo) / 2 + bent + clearance;
            v.aligned.push_back(aligned);
            v.normals.push_back(piece_normal(middle));
            v.pad.push_back(bent + clearance);
            hull.extend(aligned.centre - aligned.half);
            hull.extend(aligned.centre + aligned.half);
            // Every two vertices' direction: the outline's edges and, for four or more
            // vertices, its diagonals (testing only the outline's edges changed the search's
            // floating-point path enough that the incremental search no longer followed the full
            // re-evaluation; Annealing.IncrementalEvaluationFollowsTheFullReevaluation).
            for (std::size_t p = 0; p < middle.size(); ++p)
                for (std::size_t q = p + 1; q < middle.size(); ++q) {
                    const Vec3 e = middle[q] - middle[p];
                    if (e.norm() <= 1e-9)
                        continue;
                    // A strip's opposite edges are parallel: one direction each.
                    const Vec3 u = e.normalized();
                    bool parallel = false;
                    for (int f = v.edge_first.back(); f < int(v.edges.size()); ++f)
                        parallel = parallel || std::abs(v.edges[f].dot(u)) > 1 - 1e-12;
                    if (!parallel)
                        v.edges.push_back(u);
                }
            v.edge_first.push_back(int(v.edges.size()));
        }
        OrientedBox b;
        if (!hull.isEmpty()) {
            b.centre = hull.center();
            b.half = hull.sizes() / 2;
        }
        v.bands.push_back(b);
    }
    return v;
}

void carry_along(CollisionVolume& volume, const std::vector<Vec3>& offsets)
{
    for (std::size_t i = 0; i < volume.sides.size(); ++i)
        for (const Vec3& t : offsets)
            if (volume.sides[i] * t.x() < 0)
                volume.sides[i] = 0;
    auto carry = [&](OrientedBox& b) {
        Vec3 lo = -b.half, hi = b.half;
        for (const Vec3& t : offsets) {
            const Vec3 local = b.axes.transpose() * t;
            lo = lo.cwiseMin(local - b.half);
            hi = hi.cwiseMax(local + b.half);
        }
        b.centre += b.axes * ((lo + hi) / 2);
        b.half = (hi - lo) / 2;
    };
    const std::size_t pieces = volume.sides.size();
    volume.carried.insert(volume.carried.end(), offsets.begin(), offsets.end());
    for (std::size_t band = 0; band < volume.bands.size(); ++band) {
        Eigen::AlignedBox3d hull;
        for (std::size_t i = 0; i < pieces; ++i) {
            OrientedBox& b = volume.aligned[band * pieces + i];
            carry(b);
            hull.extend(b.centre - b.half);
            hull.extend(b.centre + b.half);
        }
        if (!hull.isEmpty()) {
            volume.bands[band].centre = hull.center();
            volume.bands[band].half = hull.sizes() / 2;
        }
    }
}

namespace {

// overlap_depth of two axis-aligned boxes, without checking that they are.
double aligned_overlap(const OrientedBox& a, const OrientedBox& b)
{
    const double overlap = (a.half + b.half - (b.centre - a.centre).cwiseAbs()).minCoeff();
    return overlap > 0 ? overlap : 0.0;
}

// Calls visit(boxes, ia, ib) for the pieces of band k that may meet: on sides of the fold's
// plane that can touch, their boxes overlapping by `boxes` (none when the whole-band boxes, which
// hold every piece's box, are apart). Stops, returning true, when visit does.
template <class Visit>
bool each_box_pair(const CollisionVolume& a, const CollisionVolume& b, std::size_t k, Visit visit)
{
    if (aligned_overlap(a.bands[k], b.bands[k]) <= 0)
        return false;
    const std::size_t na = a.sides.size(), nb = b.sides.size();
    for (std::size_t i = 0; i < na; ++i)
        for (std::size_t j = 0; j < nb; ++j) {
            if (a.sides[i] * b.sides[j] < 0)
                continue;
            const std::size_t ia = k * na + i, ib = k * nb + j;
            const double d = aligned_overlap(a.aligned[ia], b.aligned[ib]);
            if (d > 0 && visit(d, ia, ib))
                return true;
        }
    return false;
}

} // namespace

double collision_depth(const CollisionVolume& a, const CollisionVolume& b)
{
    double sum = 0.0;
    struct Pair {
        double boxes;
        std::size_t ia, ib;
    };
    thread_local std::vector<Pair> pairs;
    for (std::size_t k = 0; k < std::min(a.bands.size(), b.bands.size()); ++k) {
        pairs.clear();
        each_box_pair(a, b, k, [&](double d, std::size_t ia, std::size_t ib) {
            pairs.push_back({d, ia, ib});
            return false;
        });
        // Each piece is within its box and its padded points' hull: the pieces share no room
        // when either pair is apart, and the shallower overlap bounds how deep they can meet.
        // Deepest boxes first: a pair whose boxes overlap less than the deepest found so far
        // cannot change the band's depth, so its hulls are not tested.
        std::sort(pairs.begin(), pairs.end(), [](const Pair& p, const Pair& q) {
            return p.boxes > q.boxes ||
                   (p.boxes == q.boxes && (p.ia < q.ia || (p.ia == q.ia && p.ib < q.ib)));
        });
        double deepest = 0.0;
        for (const Pair& p : pairs) {
            if (p.boxes <= deepest)
                break;
            deepest = std::max(deepest, piece_overlap(a, p.ia, b, p.ib, p.boxes, deepest));
        }
        sum += deepest;
    }
    return sum;
}

bool collide(const CollisionVolume& a, const CollisionVolume& b)
{
    // collision_depth's band depth is positive exactly when some pair of pieces overlaps both
    // as boxes and as hulls; any such pair answers.
    for (std::size_t k = 0; k < std::min(a.bands.size(), b.bands.size()); ++k)
        if (each_box_pair(a, b, k, [&](double d, std::size_t ia, std::size_t ib) {
                return piece_overlap(a, ia, b, ib, d) > 0;
            }))
            return true;
    return false;
}

} // namespace popup::motion
