#include "chain_mapping.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "mechanism_parts.hpp"
#include "motion_feasibility.hpp"
#include "motion_kinematics.hpp"
#include "motion_parameters.hpp"
#include "parameter_table.hpp"
#include "popup/motion/motion_targets.hpp"

namespace popup::motion {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr int diagonal_polish_rounds = 3;

double clamp(double v, double lo, double hi)
{
    return std::max(lo, std::min(hi, v));
}

// Minimises f on [lo, hi]: a coarse grid, then golden-section around the best cell.
double search_1d(const std::function<double(double)>& f, double lo, double hi, int grid = 40)
{
    double best = lo, fbest = inf;
    for (int i = 0; i <= grid; ++i) {
        const double x = lo + (hi - lo) * i / grid, fx = f(x);
        if (fx < fbest) {
            fbest = fx;
            best = x;
        }
    }
    double a = std::max(lo, best - (hi - lo) / grid), b = std::min(hi, best + (hi - lo) / grid);
    const double r = (std::sqrt(5.0) - 1) / 2;
    double c = b - r * (b - a), d = a + r * (b - a), fc = f(c), fd = f(d);
    for (int k = 0; k < 40; ++k) {
        if (fc < fd) {
            b = d;
            d = c;
            fd = fc;
            c = b - r * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + r * (b - a);
            fd = f(d);
        }
    }
    const double x = (a + b) / 2;
    return f(x) <= fbest ? x : best;
}

// Nelder–Mead over the mechanism's parameters; infeasible points cost +inf.
MotionMechanism polish(MotionMechanism m, const std::function<double(const MotionMechanism&)>& f,
                       int evaluations)
{
    const int n = active_parameter_count(m);
    std::vector<MotionMechanism> simplex(n + 1, m);
    std::vector<double> value(n + 1);
    for (int i = 0; i < n; ++i) {
        const ParameterInfo info = parameter_info(m.kind(), i);
        const double step = info.role == ParameterRole::angle
                                ? 0.1
                                : std::max(2.0, 0.1 * std::abs(parameter(m, i)));
        parameter(simplex[i + 1], i) += step;
    }
    for (int i = 0; i <= n; ++i)
        value[i] = f(simplex[i]);
    int used = n + 1;
    auto blend = [&](const MotionMechanism& a, const MotionMechanism& b, double t) {
        MotionMechanism c = a;
        for (int i = 0; i < n; ++i)
            parameter(c, i) = parameter(a, i) + t * (parameter(b, i) - parameter(a, i));
        return c;
    };
    while (used < evaluations) {
        std::vector<int> order(n + 1);
        for (int i = 0; i <= n; ++i)
            order[i] = i;
        std::sort(order.begin(), order.end(), [&](int a, int b) { return value[a] < value[b]; });
        const int best = order[0], worst = order[n], second = order[n - 1];
        MotionMechanism centroid = m;
        for (int i = 0; i < n; ++i) {
            double s = 0;
            for (int k = 0; k < n; ++k)
                s += parameter(simplex[order[k]], i);
            parameter(centroid, i) = s / n;
        }
        const MotionMechanism reflected = blend(centroid, simplex[worst], -1.0);
        const double fr = f(reflected);
        ++used;
        if (fr < value[best]) {
            const MotionMechanism expanded = blend(centroid, simplex[worst], -2.0);
            const double fe = f(expanded);
            ++used;
            if (fe < fr) {
                simplex[worst] = expanded;
                value[worst] = fe;
            } else {
                simplex[worst] = reflected;
                value[worst] = fr;
            }
        } else if (fr < value[second]) {
            simplex[worst] = reflected;
            value[worst] = fr;
        } else {
            const MotionMechanism contracted = blend(centroid, simplex[worst], 0.5);
            const double fc = f(contracted);
            ++used;
            if (fc < value[worst]) {
                simplex[worst] = contracted;
                value[worst] = fc;
            } else {
                for (int k = 1; k <= n; ++k) {
                    simplex[order[k]] = blend(simplex[best], simplex[order[k]], 0.5);
                    value[order[k]] = f(simplex[order[k]]);
                    ++used;
                }
            }
        }
    }
    int best = 0;
    for (int i = 1; i <= n; ++i)
        if (value[i] < value[best])
            best = i;
    return simplex[best];
}

// Moves m along the fold (its fold_offset) so that its closed-form vertices at θ = 0 lie within
// [0, W] along the fold, when they can (a mechanism longer than the card stays as it is).
void fit_along_fold_when_closed(MotionMechanism& m, double W)
{
    double lo = inf, hi = -inf;
    for (const Vec3& q : mechanism_vertices(m, 0.0)) {
        lo = std::min(lo, q.y());
        hi = std::max(hi, q.y());
    }
    if (!(hi - lo <= W))
        return;
    if (lo < 0)
        fold_offset(m) += -lo;
    else if (hi > W)
        fold_offset(m) -= hi - W;
}

} // namespace

std::vector<Vec2> achieved_path(const MotionMechanism& m, const std::vector<double>& s)
{
    std::vector<Vec2> out;
    out.reserve(s.size());
    for (double si : s)
        out.push_back(mechanism_point(m, M_PI * si).head<2>());
    return out;
}

double motion_error(const MotionMechanism& m, const ChainTarget& t)
{
    if (t.s.empty())
        return 0.0;
    double sum = 0.0;
    for (std::size_t i = 0; i < t.s.size(); ++i)
        sum += (mechanism_point(m, M_PI * t.s[i]).head<2>() - t.target[i]).squaredNorm();
    return std::sqrt(sum / t.s.size());
}

ChainTarget search_target(const ChainTarget& t, std::size_t most)
{
    const std::size_t n = t.s.size();
    if (n <= most || most < 2)
        return t;
    const std::size_t k = (n - 1 + most - 2) / (most - 1); // ceil((n − 1)/(most − 1))
    ChainTarget out = t;
    out.s.clear();
    out.target.clear();
    for (std::size_t i = 0; i < n; i += k) {
        out.s.push_back(t.s[i]);
        out.target.push_back(t.target[i]);
    }
    if (out.s.back() != t.s.back()) {
        out.s.push_back(t.s.back());
        out.target.push_back(t.target.back());
    }
    return out;
}

namespace {

// One chain's candidates: the closed-form or searched start of each kind, then its polish
// (each kind a method, in the order fit_candidates runs them).
class CandidateFit {
public:
    CandidateFit(const ChainTarget& full, const CardParams& card, double h_max,
                 std::size_t fit_samples)
        : full(full), card(card), h_max(h_max), W(card.width), D(card.depth),
          t(search_target(full, fit_samples)), A0(t.target.front()), A1(t.target.back())
    {
    }

    Candidate rotation() const;
    Candidate vertical() const;
    Candidate horizontal() const;
    Candidate diagonal() const;
    Candidate stationary() const;

private:
    double cost(const MotionMechanism& m) const
    {
        return feasible(m, card) ? motion_error(m, t) : inf;
    }
    std::function<double(const MotionMechanism&)> cost_of() const
    {
        return [this](const MotionMechanism& m) { return cost(m); };
    }
    Candidate finish(MotionMechanism m, int evaluations) const;

    const ChainTarget& full;
    const CardParams& card;
    const double h_max;
    const double W, D;
    const ChainTarget t;
    const Vec2 A0, A1;
};

Candidate CandidateFit::finish(MotionMechanism m, int evaluations) const
{
    Candidate c;
    c.why = infeasibility(m, card);
    if (!c.why.empty()) {
        c.mechanism = m;
        c.error_mm = inf;
        return c;
    }
    // Nelder–Mead restarted from its own best with a fresh simplex: a collapsed simplex
    // stalls short of the minimum on the diagonal's 8 nested parameters (0.35 mm instead of
    // 0.04 mm on rig_diagonal); the others converge in one round.
    c.mechanism = m;
    const int rounds = m.kind() == MotionKind::diagonal ? diagonal_polish_rounds : 1;
    for (int round = 0; round < rounds; ++round)
        c.mechanism = polish(c.mechanism, cost_of(), evaluations);
    c.error_mm = motion_error(c.mechanism, full);
    return c;
}

Candidate CandidateFit::rotation() const
{
    // Rotation: at 180° the tip is at (−h, offset + l) (docs/MATH.md, Rotation), so the last
    // pose gives h and offset + l; the spine l is the 1-D search of eq 6.2 (the y path, the
    // only part that depends on l), for a few runs w below the arm limit h <= l²/w.
    MotionMechanism m = default_mechanism(MotionKind::rotation);
    const double h = clamp(-A1.x(), 2.0, D - 2);
    double best = inf;
    for (double ratio : {0.2, 0.4, 0.6, 0.8}) {
        auto trial = [&](double l) {
            return rotation_mechanism(clamp(A1.y() - l, 0, W), l,
                                      clamp(ratio * l * l / h, shortest_crease(), D - 2), h);
        };
        auto eq62 = [&](double l) {
            const MotionMechanism q = trial(l);
            if (!feasible(q, card))
                return inf;
            double sum = 0;
            for (std::size_t i = 0; i < t.s.size(); ++i) {
                const double dy = mechanism_point(q, M_PI * t.s[i]).y() - t.target[i].y();
                sum += dy * dy;
            }
            return sum;
        };
        const double l = search_1d(eq62, shortest_crease(), W);
        const double e = eq62(l);
        if (e < best || best == inf) {
            best = e;
            m = trial(l);
        }
    }
    Candidate on_fold = finish(m, 600);
    // Off the fold (thesis §4.3.4, last paragraph): the arm on a floating layer's side pair
    // turns about the support's foot. No closed-form start: a coarse grid over the side,
    // the support, the spine, the run and the arm (the offset put where the open tip meets
    // the last pose along the fold), then the polish from the best two starts.
    std::vector<std::pair<double, MotionMechanism>> starts;
    for (double side : {1.0, -1.0})
        for (double sf : {0.12, 0.25, 0.4})
            for (double lf : {0.15, 0.3, 0.5, 0.7})
                for (double wf : {0.0, 0.25, 0.5})
                    for (double hf : {0.1, 0.3, 0.6, 0.9}) {
                        // The layer's height follows Run and Arm, and closed it stands on
                        // the page from the support up: keep both under the card's top.
                        const double support = std::max(sf * D, shortest_crease());
                        const double room = D - support - 2 * shortest_crease();
                        const double l = std::max(lf * W, shortest_crease());
                        const double w = shortest_crease() + 1 + wf * std::max(0.0, room);
                        const double h = hf * std::min(l * l / w, std::max(room, 2.0));
                        MotionMechanism q = rotation_mechanism(0, l, w, h, side * support);
                        const double tip_y = mechanism_point(q, M_PI).y();
                        fold_offset(q) = clamp(A1.y() - tip_y, 0, std::max(0.0, W - l));
                        // Closed, the arm's tip may reach past the fold's ends.
                        fit_along_fold_when_closed(q, W);
                        const double e = cost(q);
                        if (e < inf)
                            starts.push_back({e, q});
                    }
    std::stable_sort(starts.begin(), starts.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    Candidate best_rotation = on_fold;
    for (std::size_t k = 0; k < std::min<std::size_t>(2, starts.size()); ++k) {
        Candidate off = finish(starts[k].second, 600);
        if (off.error_mm < best_rotation.error_mm)
            best_rotation = off;
    }
    return best_rotation;
}

Candidate CandidateFit::vertical() const
{
    // Vertical: F' is at offset when open and offset − height·sin(wall_angle) when closed.
    const double beta = M_PI / 4, drop = clamp(A1.y() - A0.y(), 2.0, D - 2);
    const double height = clamp(drop / std::sin(beta), shortest_crease(), D - 2);
    const double side = clamp(0.5 * height, shortest_crease() / std::sin(beta), 0.4 * D);
    const MotionMechanism m =
        vertical_mechanism(clamp(A1.y(), 0, W - 2 * side * std::cos(beta)), side, height, beta);
    return finish(m, 500);
}

Candidate CandidateFit::horizontal() const
{
    // Horizontal: P = r·C/|C| is at (r, y) open and on the fold closed: r from the last
    // pose; the runs' ratio k = b/a shapes x(θ) (1-D search). The path fixes only the far
    // edge's middle, offset + width/2, and the runs' ratio (P follows C's direction, not its
    // length): the patch is as narrow, and the runs as short (a − b at most r/2), as their
    // creases can be glued (1 mm above infeasibility's bounds), taking the least room from
    // the neighbours (docs/DESIGN.md, "Tight collision volumes").
    const double r = clamp(A1.x(), shortest_crease(), D - 2);
    const double width = std::max(12.0, shortest_crease()) + 1.0;
    auto trial = [&](double k) {
        const double a = clamp(0.5 * r / (1 - k), 2.0, D - 2);
        const double shorter = std::min(1.0, (shortest_crease() + 1.0) / (k * a));
        return horizontal_mechanism(clamp(A1.y() - width / 2, 0, W - width), width, shorter * a,
                                    shorter * k * a, r);
    };
    const double k = search_1d([&](double k) { return cost(trial(k)); }, 0.05, 0.9, 20);
    return finish(trial(k), 600);
}

Candidate CandidateFit::diagonal() const
{
    // Diagonal: open, the nose is at ((a − b) sin α, offset + (a + b) cos α) on the standing
    // spine (docs/MATH.md, Diagonal translation); the spine from the y travel.
    const double alpha = M_PI / 4;
    const double diff = A1.x() / std::sin(alpha);
    const double sum = std::abs(diff) + 2 * shortest_crease() + 2; // both runs glued
    const double a = (sum + diff) / 2, b = (sum - diff) / 2;
    // The step is 0.2 of the spine wide: at least the shortest glued crease.
    const double spine =
        clamp(std::max(2 * std::abs(A1.y() - A0.y()) + 20, 5 * shortest_crease() + 1), 10, D - 2);
    const double run = clamp(2.5 * (std::max(a, b) + 2), 4, (D - 2) / std::sin(alpha));
    MotionMechanism m =
        diagonal_mechanism(clamp(A1.y() - sum * std::cos(alpha), 0, W - run * std::cos(alpha)), run,
                           alpha, spine, 0.3 * spine, 0.2 * spine, a, b);
    // Closed, the standing spine lies down along the fold past O (towards −y) and the step
    // rides on it: slide the whole mechanism along the fold until its closed parts are on
    // the card, or the start is refused before the polish can move it.
    fit_along_fold_when_closed(m, W);
    Candidate c = finish(m, 800);
    // The path leaves the wings' length partly free, and the polish may take a long-run
    // member whose wings, unfolded, outgrow the card's sheet (a 378 mm piece on A4, found on
    // a long capture). Then the run is shortened until they fit and the polish goes on with
    // the sheet as a bound.
    if (std::isfinite(c.error_mm) && !diagonal_wings_fit(c.mechanism, card)) {
        MotionMechanism q = c.mechanism;
        for (int k = 0; k < 60 && !diagonal_wings_fit(q, card); ++k)
            q.diagonal().v_fold.run *= 0.95;
        auto bounded = [&](const MotionMechanism& x) {
            return diagonal_wings_fit(x, card) ? cost(x) : inf;
        };
        if (std::isfinite(bounded(q))) {
            for (int round = 0; round < diagonal_polish_rounds; ++round)
                q = polish(q, bounded, 800);
            c.mechanism = q;
            c.error_mm = motion_error(q, full);
        } else {
            c.why = "its wings, unfolded about their spine, do not fit the card's sheet";
            c.error_mm = inf;
        }
    }
    return c;
}

Candidate CandidateFit::stationary() const
{
    // Stationary: a platform point at the last pose's distance from the fold; the height
    // from the chain's depth (eq 6.7).
    const double anchor = A1.x();
    const double support = clamp(0.6 * std::abs(anchor), shortest_crease(), 0.4 * D);
    const double overhang = std::max(0.0, std::abs(anchor) - support) + 5;
    const double low = shortest_crease();
    const double height = clamp(h_max * t.depth, low, std::max(low, h_max));
    const MotionMechanism m =
        layer_mechanism(clamp(A1.y() - 10, 0, W - 20), 20, height, support, overhang, anchor);
    Candidate c;
    c.mechanism = m;
    c.why = infeasibility(m, card);
    c.error_mm = c.why.empty() ? motion_error(m, full) : inf;
    return c;
}

} // namespace

Candidate fit_candidate(MotionKind kind, const ChainTarget& full, const CardParams& card,
                        double h_max, std::size_t fit_samples)
{
    const CandidateFit fit(full, card, h_max, fit_samples);
    switch (kind) {
    case MotionKind::rotation:
        return fit.rotation();
    case MotionKind::vertical:
        return fit.vertical();
    case MotionKind::horizontal:
        return fit.horizontal();
    case MotionKind::diagonal:
        return fit.diagonal();
    case MotionKind::stationary:
        break;
    }
    return fit.stationary();
}

std::array<Candidate, motion_kind_count> fit_candidates(const ChainTarget& full,
                                                        const CardParams& card, double h_max,
                                                        std::size_t fit_samples)
{
    std::array<Candidate, motion_kind_count> out;
    for (int k = 0; k < motion_kind_count; ++k)
        out[k] = fit_candidate(MotionKind(k), full, card, h_max, fit_samples);
    return out;
}

MotionKind best_mapping(const std::array<Candidate, motion_kind_count>& c, const ChainTarget& t,
                        double still_mm, double diagonal)
{
    const bool still = path_spread(t.target) <= still_mm;
    if (still && c[int(MotionKind::stationary)].error_mm < inf)
        return MotionKind::stationary;
    int best = int(MotionKind::stationary);
    for (int k = 0; k < motion_kind_count; ++k)
        if (c[k].error_mm < c[best].error_mm)
            best = k;
    // A still chain whose floating layer does not fit takes a moving mechanism only when that
    // one holds it within the still bound too; otherwise it is left off (its part printed on the
    // page): a mechanism fitted to a point far from the fold is as large as that distance (a
    // rotation arm reaching 110 mm across the page, 54 mm off, for rig_four's still body) and
    // takes the room of the chains that do move.
    if (still && !(c[best].error_mm <= still_mm))
        return MotionKind::stationary;
    // Paths two mechanisms both make (within mapping_tie_fraction) go to the one with
    // fewer parameters: a diagonal whose step sits still on its wings also rises along the fold
    // exactly, but a vertical path is the v-box's (Table 6.1).
    // A rotation off the fold counts its hinge too. A hand-made candidate may hold no mechanism
    // of its kind: it counts as the kind's defaults (a rotation on the fold).
    auto count = [&](int k) {
        const MotionMechanism& m = c[k].mechanism;
        const MotionKind kind = MotionKind(k);
        return active_parameter_count(m.kind() == kind ? m : default_mechanism(kind));
    };
    const double tie = c[best].error_mm + mapping_tie_fraction * diagonal;
    for (int k = 0; k < motion_kind_count; ++k)
        if (c[k].error_mm <= tie && count(k) < count(best))
            best = k;
    return MotionKind(best);
}

} // namespace popup::motion
