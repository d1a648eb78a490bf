#include "register_piece.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <future>

#include "../../geometry/polygon_2d.hpp"
#include "../clipper_ops.hpp"

namespace popup::sheets {

namespace {

constexpr int faces_tried = 3; // the largest drawn faces propose motions
constexpr int refinements = 4;
// Pairs times corners from which the pairs are refined on two threads: below it (most pieces,
// a few dozen pairs of a handful of corners) starting a thread costs more than it saves.
constexpr std::size_t kParallelCorners = 20000;

Motion2 turn_onto(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d)
{
    // Direction of a→b onto c→d, midpoint onto midpoint.
    const double angle =
        std::atan2((d - c).y(), (d - c).x()) - std::atan2((b - a).y(), (b - a).x());
    Motion2 m;
    m.rotation = Eigen::Rotation2Dd(angle).toRotationMatrix();
    m.translation = 0.5 * (c + d) - m.rotation * (0.5 * (a + b));
    return m;
}

Vec2 nearest_on_segment(const Vec2& q, const Vec2& a, const Vec2& b)
{
    const Vec2 ab = b - a;
    const double t = std::clamp((q - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
    return a + t * ab;
}

Vec2 nearest_on_region(const Region& r, const Vec2& q)
{
    Vec2 best = q;
    double gap = 1e300;
    auto scan = [&](const Loop2& loop) {
        for (size_t i = 0; i < loop.size(); ++i) {
            const Vec2 p = nearest_on_segment(q, loop[i], loop[(i + 1) % loop.size()]);
            if ((p - q).norm() < gap) {
                gap = (p - q).norm();
                best = p;
            }
        }
    };
    scan(r.outer);
    for (const Loop2& h : r.holes)
        scan(h);
    return best;
}

// Least-squares rigid motion taking points p onto q (2D Procrustes).
Motion2 fit(const std::vector<Vec2>& p, const std::vector<Vec2>& q)
{
    Vec2 pc = Vec2::Zero(), qc = Vec2::Zero();
    for (size_t i = 0; i < p.size(); ++i) {
        pc += p[i];
        qc += q[i];
    }
    pc /= double(p.size());
    qc /= double(q.size());
    double sin_sum = 0.0, cos_sum = 0.0;
    for (size_t i = 0; i < p.size(); ++i) {
        const Vec2 a = p[i] - pc, b = q[i] - qc;
        cos_sum += a.dot(b);
        sin_sum += a.x() * b.y() - a.y() * b.x();
    }
    Motion2 m;
    m.rotation = Eigen::Rotation2Dd(std::atan2(sin_sum, cos_sum)).toRotationMatrix();
    m.translation = qc - m.rotation * pc;
    return m;
}

struct Fit {
    double outline = 0.0, folds = 0.0;
    Vec2 worst = Vec2::Zero();
    // Outline corners and their nearest drawn points, for the next refinement. Fold lines only
    // choose between motions: one misplaced fold must not drag the whole piece after it.
    std::vector<Vec2> from, onto;
};

using Lines = std::vector<std::array<Vec2, 2>>;

Fit measure(const Motion2& m, const std::vector<Region>& design, const Lines& folds,
            const Lines& joints, const DrawnPiece& drawn)
{
    Fit f;
    auto corner = [&](const Vec2& p) {
        const Vec2 q = m(p);
        const Vec2 near = nearest_on_region(drawn.outline, q);
        const double gap = (near - q).norm();
        if (gap > f.outline) {
            f.outline = gap;
            f.worst = q;
        }
        f.from.push_back(p);
        f.onto.push_back(m.rotation.transpose() * (near - m.translation));
    };
    for (const Region& r : design) {
        std::for_each(r.outer.begin(), r.outer.end(), corner);
        for (const Loop2& h : r.holes)
            std::for_each(h.begin(), h.end(), corner);
    }
    // Every design fold has its drawn line; every drawn line (fold, tab crease, the crease edge
    // of a glue area) lies on a fold or joint of the design. This tells apart the ways a
    // symmetric outline fits.
    Lines placed;
    for (const Lines* lines : {&folds, &joints})
        for (const auto& line : *lines)
            placed.push_back({m(line[0]), m(line[1])});
    for (size_t i = 0; i < folds.size(); ++i) {
        double gap = drawn.folds.empty() ? 0.0 : 1e300;
        for (const DrawnFold& d : drawn.folds)
            gap = std::min(gap, segment_gap(placed[i], d.from, d.to));
        f.folds = std::max(f.folds, gap);
    }
    Lines drawn_lines;
    for (const DrawnFold& d : drawn.folds)
        drawn_lines.push_back({d.from, d.to});
    for (const DrawnGlue& g : drawn.glue)
        drawn_lines.push_back({g.polygon[0], g.polygon[1]});
    for (const auto& line : drawn_lines) {
        double gap = placed.empty() ? 0.0 : 1e300;
        for (const auto& onto : placed)
            gap = std::min(gap, segment_gap(line, onto[0], onto[1]));
        f.folds = std::max(f.folds, gap);
    }
    return f;
}

// The cut outline is what a cutter follows and weighs most; the lines choose among fits of a
// symmetric outline. (A fold drawn 0.5 mm off must not pull the piece 0.25 mm the other way.)
double score_of(const Fit& f)
{
    return 10.0 * f.outline + f.folds;
}

} // namespace

double segment_gap(const std::array<Vec2, 2>& line, const Vec2& from, const Vec2& to)
{
    return std::max(distance_to_segment(line[0], from, to), distance_to_segment(line[1], from, to));
}

std::vector<Registration> register_piece(const std::vector<Loop2>& patches,
                                         const std::vector<Region>& design, const Lines& folds,
                                         const Lines& joints, const DrawnPiece& drawn, double tie)
{
    struct Edge {
        Vec2 a, b;
        double length;
    };
    auto edges_of = [](const Loop2& loop) {
        std::vector<Edge> edges;
        for (size_t i = 0; i < loop.size(); ++i) {
            const Vec2 &a = loop[i], &b = loop[(i + 1) % loop.size()];
            if ((b - a).norm() > 1e-6)
                edges.push_back({a, b, (b - a).norm()});
        }
        return edges;
    };
    // Faces are whole patches (tabs are faces of their own), so a drawn face and the design
    // patch it is have edges of the same lengths once collinear corners (a tab's foot) go.
    auto straight = [](Loop2 loop) {
        if (loop_area(loop) < 0) // counter-clockwise, so that edges pair up in the same sense
            std::reverse(loop.begin(), loop.end());
        Loop2 out;
        for (size_t i = 0; i < loop.size(); ++i) {
            const Vec2& prev = loop[(i + loop.size() - 1) % loop.size()];
            const Vec2 &p = loop[i], &next = loop[(i + 1) % loop.size()];
            const Vec2 u = p - prev, v = next - p;
            if (std::abs(u.x() * v.y() - u.y() * v.x()) > 1e-9 * u.norm() * v.norm() ||
                u.dot(v) < 0)
                out.push_back(p);
        }
        return out;
    };
    auto area = [](const Loop2& loop) { return std::abs(loop_area(loop)); };
    std::vector<const Region*> faces;
    for (const Region& f : drawn.faces)
        faces.push_back(&f);
    std::sort(faces.begin(), faces.end(),
              [&](const Region* x, const Region* y) { return area(x->outer) > area(y->outer); });
    if (faces.size() > size_t(faces_tried))
        faces.resize(faces_tried);
    std::vector<std::pair<Edge, Edge>> pairs; // (design edge, drawn edge)
    for (const Region* face : faces) {
        const double face_area = area(face->outer);
        const auto drawn_edges = edges_of(straight(face->outer));
        for (const Loop2& patch : patches) {
            if (std::abs(area(patch) - face_area) > 0.05 * face_area)
                continue;
            for (const Edge& e : edges_of(straight(patch)))
                for (const Edge& d : drawn_edges)
                    if (std::abs(e.length - d.length) <= 0.05 * d.length)
                        pairs.push_back({e, d});
        }
    }

    // Each pair's motion, refined on its own: two pairs at a time (two cores) when there are
    // many, taken in order.
    std::vector<std::pair<double, Registration>> refined(pairs.size());
    std::atomic<std::size_t> next_pair{0};
    auto refine_next = [&] {
        for (std::size_t i; (i = next_pair++) < pairs.size();) {
            const auto& [e, d] = pairs[i];
            Motion2 m = turn_onto(e.a, e.b, d.a, d.b);
            Fit f = measure(m, design, folds, joints, drawn);
            for (int k = 0; k < refinements && !f.from.empty(); ++k) {
                // Pairs are in the design frame: fit the design onto its own nearest points,
                // then compose with the motion that found them.
                const Motion2 step = fit(f.from, f.onto);
                Motion2 next;
                next.rotation = m.rotation * step.rotation;
                next.translation = m.rotation * step.translation + m.translation;
                Fit g = measure(next, design, folds, joints, drawn);
                if (score_of(g) > score_of(f))
                    break;
                m = next;
                f = std::move(g);
            }
            refined[i] = {score_of(f), {m, f.outline, f.worst}};
        }
    };
    std::size_t corners = 0;
    for (const Region& r : design) {
        corners += r.outer.size();
        for (const Loop2& h : r.holes)
            corners += h.size();
    }
    if (pairs.size() * corners >= kParallelCorners) {
        std::future<void> other = std::async(std::launch::async, refine_next);
        refine_next();
        other.get();
    } else {
        refine_next();
    }
    // Every distinct motion with its score; a symmetric piece fits equally well more than one way.
    std::vector<std::pair<double, Registration>> found;
    for (const auto& [score, registration] : refined) {
        const Motion2& m = registration.motion;
        const bool known = std::any_of(found.begin(), found.end(), [&](const auto& x) {
            const Motion2& o = x.second.motion;
            return (o.rotation - m.rotation).norm() < 1e-6 &&
                   (o.translation - m.translation).norm() < 1e-4;
        });
        if (!known)
            found.push_back({score, registration});
    }
    std::sort(found.begin(), found.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<Registration> best;
    for (const auto& [score, registration] : found)
        if (score <= found.front().first + tie)
            best.push_back(registration);
    return best;
}

} // namespace popup::sheets
