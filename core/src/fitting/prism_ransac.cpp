#include "popup/fitting/prism_ransac.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <future>
#include <optional>
#include <random>
#include <vector>

#include "localised_sampling.hpp"
#include "prism_candidates.hpp"
#include "prism_faces.hpp"
#include "prism_scoring.hpp"

namespace popup {
namespace {

using namespace prism_search;

/// Samples on a host's plane facing it (the model's base on the card, a box standing on
/// another's top) are the paper itself: no prism needs to explain them.
void mark_base(const PrismHost& h, const std::vector<Local>& locals, double eps,
               std::vector<bool>& on_base)
{
    for (size_t i = 0; i < on_base.size(); ++i) {
        const Local& l = locals[i];
        if (l.a < -eps || l.a > h.length + eps)
            continue;
        const bool on_page = std::abs(l.t) < eps && l.nt < -kNormalAgreement &&
                             l.s > h.across_min - eps && l.s < h.across_max + eps;
        // A right-angle pair's wall too: a part built against a box's side.
        const bool on_wall = !h.flat && std::abs(l.s) < eps && l.ns < -kNormalAgreement &&
                             l.t > -eps && l.t < h.up_max + eps;
        if (on_page || on_wall)
            on_base[i] = true;
    }
}

/// The samples no prism explains and no host's plane carries.
std::vector<int> unexplained(const RansacResult& r)
{
    std::vector<int> remaining;
    for (size_t i = 0; i < r.owner.size(); ++i)
        if (r.owner[i] < 0 && !r.on_base[i])
            remaining.push_back(int(i));
    return remaining;
}

/// A round over `remaining` (at least one sample): its scoring subset and, per host, the
/// subset and the `guard` samples above it.
Round start_round(std::vector<int> remaining, std::vector<int> starts, const RansacResult& r,
                  const std::vector<std::vector<Local>>& locals, const std::vector<int>& guard,
                  double spacing, double eps)
{
    Round round;
    round.remaining = std::move(remaining);
    round.starts = std::move(starts);
    round.N = double(round.starts.size());
    const std::vector<int> subset = every_kth(round.remaining, 1000);
    round.scale = double(round.remaining.size()) / double(subset.size());
    round.gap = 4.0 * spacing * std::sqrt(round.scale);
    const int H = int(r.hosts.size());
    for (int i : round.remaining) {
        int count = 0;
        for (int h = 0; h < H; ++h)
            count += above_host(r.hosts[h], locals[h][i], eps);
        round.hosts_per_sample = std::max(round.hosts_per_sample, count);
    }
    round.sub.resize(H);
    round.grd.resize(H);
    round.box_sub.resize(H);
    round.tent_sub.resize(H);
    for (int h = 0; h < H; ++h) {
        for (int i : subset)
            if (above_host(r.hosts[h], locals[h][i], eps))
                round.sub[h].push_back(locals[h][i]);
        for (int i : guard)
            if (above_host(r.hosts[h], locals[h][i], eps))
                round.grd[h].push_back(locals[h][i]);
        // Along the hinge: a candidate reads only the samples over its own stretch.
        sort_along(round.sub[h]);
        sort_along(round.grd[h]);
        for (const Local& l : round.sub[h]) {
            if (may_carry_box(l))
                round.box_sub[h].push_back(l);
            if (may_carry_slope(l))
                round.tent_sub[h].push_back(l);
        }
    }
    return round;
}

/// Takes `m` into the result: refitted, its inliers among `remaining` owned (and marked on a
/// principal face), its box taken, and a box's pairs offered as new hosts.
void accept_prism(Prism m, const std::vector<int>& remaining, const Search& search, double eps,
                  std::vector<std::vector<Local>>& locals, std::vector<Eigen::AlignedBox3d>& taken,
                  RansacResult& r)
{
    const PrismHost& host = r.hosts[m.host];
    search.refit(m, locals[m.host], remaining, host);
    const Section sec = section_of(m);
    int n = 0;
    for (int i : remaining) {
        int face = -1;
        if (classify(m, sec, locals[m.host][i], eps, host.flat, &face) == Where::face) {
            r.owner[i] = int(r.prisms.size());
            r.on_principal[i] = face <= 2 || face == 5;
            ++n;
        }
    }
    m.inliers = n;
    r.prisms.push_back(m);
    Eigen::AlignedBox3d box;
    for (const Vec3& c : m.corners(host))
        box.extend(c);
    taken.push_back(box);
    if (m.kind == Prism::Kind::rectangular && host.flat) {
        const size_t before = r.hosts.size();
        offer_box_pairs(m, int(r.prisms.size()) - 1, r.hosts);
        for (size_t h = before; h < r.hosts.size(); ++h) {
            locals.push_back(search.locals(r.hosts[h]));
            mark_base(r.hosts[h], locals[h], eps, r.on_base);
        }
    }
}

/// A round's draws, 64 at a time (a batch). On two lanes, eight batches are drawn at once and
/// tried four on each core, each lane from the best scores before them; a batch joins the
/// round only if the round goes on, and the generator goes back to where it stood after the
/// last batch taken. Tried from a lower best only more candidates are guarded, and keep_better
/// keeps the first of the highest scores: the same candidates, counts and generator as one
/// draw after another.
class Batches {
public:
    static constexpr int kSize = 64;
    static constexpr int kPerLane = 4;

    Batches(const Round& round, const DrawInputs& in, std::mt19937_64& rng, bool two_lanes)
        : round_(round), in_(in), rng_(rng), two_lanes_(two_lanes),
          pick_point_(0, round.starts.size() - 1), pick_level_(0, kLevels - 1)
    {
    }

    /// The next batch's draws tried into `found`.
    void next(Candidates& found)
    {
        if (!two_lanes_) {
            for (int k = 0; k < kSize; ++k, ++found.draws)
                draw_candidates(round_, in_, rng_, pick_point_, pick_level_, found);
            return;
        }
        if (ahead_.empty())
            try_ahead(found);
        Ahead& batch = ahead_.front();
        keep_better(found, batch.tried);
        found.tri_draws += batch.tri_draws;
        found.draws += kSize;
        taken_ = batch.after;
        ahead_.pop_front();
    }

    /// After the round: the generator as after the last batch taken.
    void finish()
    {
        if (taken_)
            rng_ = *taken_;
    }

private:
    struct Ahead {
        std::vector<Draw> draws;
        std::mt19937_64 after; ///< the generator after its draws
        Candidates tried;      ///< its lane's best up to it, its own tri_draws
        long tri_draws = 0;
    };

    void try_ahead(const Candidates& found)
    {
        for (int b = 0; b < 2 * kPerLane; ++b) {
            Ahead a;
            a.draws.resize(kSize);
            for (Draw& d : a.draws)
                d = draw_sample(round_, in_, rng_, pick_point_, pick_level_);
            a.after = rng_;
            ahead_.push_back(std::move(a));
        }
        auto lane = [&](int first) {
            Candidates c = found;
            for (int b = first; b < first + kPerLane; ++b) {
                const long before = c.tri_draws;
                for (const Draw& d : ahead_[size_t(b)].draws)
                    try_candidates(d, round_, in_, c);
                ahead_[size_t(b)].tried = c;
                ahead_[size_t(b)].tri_draws = c.tri_draws - before;
            }
        };
        std::future<void> other = std::async(std::launch::async, lane, kPerLane);
        lane(0);
        other.get();
    }

    const Round& round_;
    const DrawInputs& in_;
    std::mt19937_64& rng_;
    const bool two_lanes_;
    std::uniform_int_distribution<size_t> pick_point_;
    std::uniform_int_distribution<int> pick_level_;
    std::deque<Ahead> ahead_;
    std::optional<std::mt19937_64> taken_;
};

} // namespace

void offer_box_pairs(const Prism& m, int index, std::vector<PrismHost>& hosts)
{
    const PrismHost h = hosts[m.host];
    const std::string name = "P" + std::to_string(index + 1);
    const Vec3 start = h.origin + m.a0 * h.axis;
    const double d = m.s1;
    PrismHost top;
    top.name = name + ".top";
    top.parent = index;
    top.part = "top";
    top.origin = start + m.height * h.up;
    top.axis = h.axis;
    top.across = h.across;
    top.up = h.up;
    top.length = m.a1 - m.a0;
    top.across_min = -d;
    top.across_max = d;
    hosts.push_back(top);
    for (int side = 0; side < 2; ++side) {
        PrismHost p;
        p.parent = index;
        p.part = side == 0 ? "side_ground" : "side_backdrop";
        p.name = name + "." + p.part;
        p.flat = false;
        p.axis = h.axis;
        p.across = side == 0 ? h.across : Vec3(-h.across);
        p.up = h.up;
        p.origin = start + d * p.across;
        p.length = m.a1 - m.a0;
        p.across_max = side == 0 ? h.across_max - d : -h.across_min - d;
        p.up_max = m.height;
        if (p.across_max > 0)
            hosts.push_back(p);
    }
}

double draw_probability(double n, double N, int k, int hosts, int levels)
{
    if (N <= 0)
        return 1.0;
    // Of the minimal samples inside a shape, about a quarter generate it: a box needs one point
    // on its top and one on a side, a triangular prism two on each slope (docs/MATH.md).
    constexpr double generating = 0.25;
    return std::min(1.0, generating * n /
                             (N * std::max(hosts, 1) * std::max(levels, 1) * std::pow(2.0, k - 1)));
}

double found_probability(double n, double N, int k, int hosts, int levels, long draws)
{
    const double p = draw_probability(n, N, k, hosts, levels);
    if (p >= 1.0)
        return 1.0;
    return 1.0 - std::exp(double(draws) * std::log1p(-p));
}

RansacResult fit_prisms(const SurfaceSamples& samples, const PrismHost& card,
                        const RansacOptions& o)
{
    RansacResult r;
    const size_t total = samples.points.size();
    r.hosts.push_back(card);
    r.owner.assign(total, -1);
    r.on_base.assign(total, false);
    r.on_principal.assign(total, false);
    if (total == 0)
        return r;
    Search search(samples, o);
    std::vector<std::vector<Local>> locals{search.locals(card)};
    const double eps = o.threshold;
    mark_base(r.hosts[0], locals[0], eps, r.on_base);

    Eigen::AlignedBox3d box;
    for (const Vec3& p : samples.points)
        box.extend(p);
    const double extent = box.sizes().maxCoeff();
    std::mt19937_64 rng(o.seed);
    // The guard: samples a prism may not enclose, of the outer surface only.
    std::vector<int> outer;
    for (size_t i = 0; i < total; ++i)
        if (o.inner.empty() || !o.inner[i])
            outer.push_back(int(i));
    const std::vector<int> guard = every_kth(outer, 3000);
    std::vector<Eigen::AlignedBox3d> taken; // boxes of the accepted prisms, card frame

    while (int(r.prisms.size()) < o.max_primitives) {
        stop_if_cancelled(o.cancel, "fit_design: fitting primitives");
        std::vector<int> remaining = unexplained(r);
        std::vector<int> starts;
        for (int i : remaining)
            if (o.inner.empty() || !o.inner[size_t(i)])
                starts.push_back(i);
        const double N = double(starts.size());
        if (N < o.min_points) {
            r.stopped_by_probability = true;
            break;
        }
        const Round round = start_round(std::move(remaining), std::move(starts), r, locals, guard,
                                        samples.spacing, eps);
        Cells cells(samples.points, round.remaining, extent);
        const int hosts_per_sample = round.hosts_per_sample;

        const DrawInputs in{r.hosts, locals, search, cells, taken, box, eps, o.min_part};
        Batches batches(round, in, rng, o.lanes > 1);
        Candidates found;
        bool accepted = false;
        while (!accepted) {
            batches.next(found);
            r.draws += Batches::kSize;
            stop_if_cancelled(o.cancel, "fit_design: fitting primitives");
            // Algorithm 5.2: keep the best candidate once a larger one would have been drawn
            // with probability p_t; stop when even a τ-sized one would have been.
            const bool rect_better = found.best_rect.score >= found.best_tri.score;
            const Scored& best = rect_better ? found.best_rect : found.best_tri;
            const int k = rect_better ? 2 : 4;
            const long s = rect_better ? found.draws : found.tri_draws;
            if (best.score >= o.min_points &&
                found_probability(best.score, N, k, hosts_per_sample, kLevels, s) > o.probability) {
                batches.finish();
                accept_prism(best.prism, round.remaining, search, eps, locals, taken, r);
                accepted = true;
            } else if (found_probability(o.min_points, N, 2, hosts_per_sample, kLevels,
                                         found.draws) > o.probability &&
                       found_probability(o.min_points, N, 4, hosts_per_sample, kLevels,
                                         found.tri_draws) > o.probability) {
                r.stopped_by_probability = true;
                return r;
            } else if (r.draws >= o.max_draws) {
                return r;
            }
        }
    }
    return r;
}

} // namespace popup
