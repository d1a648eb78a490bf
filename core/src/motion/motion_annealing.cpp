#include "motion_annealing.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "motion_feasibility.hpp"
#include "motion_parameters.hpp"
#include "parameter_table.hpp"

namespace popup::motion {

namespace {

// The change of eq 6.8's energy exp(w_c D_c) (D_c in units of the diagonal; 0 when there is no
// collision) from depth `before` to `after`. Where the exponents leave the doubles the change is
// ±infinity, as it is next to any cost change: more collision is refused, less is taken. (Capping
// the exponent at 700 instead made every state deeper than 700 / w_c diagonals (1.3 mm on a
// 180 mm character) cost the same, and the search stopped reducing its collisions.)
double collision_energy_change(const AnnealProblem& p, double before, double after)
{
    const double a = before > 0 ? p.collision_weight * before / p.diagonal : -HUGE_VAL;
    const double b = after > 0 ? p.collision_weight * after / p.diagonal : -HUGE_VAL;
    if (a == b)
        return 0.0;
    if (std::max(a, b) > 700)
        return b > a ? HUGE_VAL : -HUGE_VAL;
    return (b > -HUGE_VAL ? std::exp(b) : 0.0) - (a > -HUGE_VAL ? std::exp(a) : 0.0);
}

// A move: take the slots `removed` out and put `added` in (a single replacement stays in place).
struct Proposal {
    std::vector<int> removed;
    std::vector<Slot> added;
};

class Search {
public:
    Search(const AnnealProblem& p, const AnnealState& start, const AnnealOptions& o)
        : p_(p), o_(o), rng_(o.seed), state_(start)
    {
        rebuild();
    }

    AnnealResult run()
    {
        AnnealResult r;
        r.best = state_;
        r.cost = cost_;
        r.collision = depth_;
        resolved_ = depth_ <= 0;
        // t0: the mean |ΔE| of 20 trial moves from the start (Kirkpatrick's choice).
        double sum = 0;
        int n = 0;
        for (int k = 0; k < 20; ++k) {
            Proposal q;
            if (!propose(q))
                continue;
            double dcost, ddepth;
            evaluate(q, dcost, ddepth, false);
            sum += std::abs(dcost);
            ++n;
        }
        const double t0 = n > 0 && sum > 0 ? sum / n : 1e-3;
        double T = 10 * t0;
        std::uniform_real_distribution<double> uniform(0.0, 1.0);
        for (long k = 0; k < o_.iterations; ++k) {
            if (k % 64 == 0) {
                stop_if_cancelled(o_.cancel, "design_motion: annealing");
                if (o_.progress)
                    o_.progress->store(o_.progress_from + (o_.progress_to - o_.progress_from) *
                                                              double(k) / o_.iterations);
            }
            if (k > 0 && k % 200 == 0)
                T *= 0.8;
            ++r.iterations;
            Proposal q;
            if (!propose(q))
                continue;
            double dcost, ddepth;
            // Collision-free once: non-collision is a hard constraint, and a move whose
            // mechanisms meet another is refused without its depth or its cost.
            if (!evaluate(q, dcost, ddepth, resolved_))
                continue;
            const double new_depth = std::max(0.0, depth_ + ddepth);
            const double dE = dcost + collision_energy_change(p_, depth_, new_depth);
            if (!(dE <= 0 || uniform(rng_) < std::exp(-dE / T)))
                continue;
            commit(q);
            ++r.accepted;
            if (depth_ <= 1e-9) {
                depth_ = 0.0;
                resolved_ = true;
            }
            if (depth_ < r.collision - 1e-12 || (depth_ <= r.collision + 1e-12 && cost_ < r.cost)) {
                r.best = state_;
                r.cost = cost_;
                r.collision = depth_;
            }
        }
        if (o_.progress)
            o_.progress->store(o_.progress_to);
        return r;
    }

private:
    void rebuild()
    {
        const std::size_t n = state_.slots.size();
        costs_.assign(n, 0.0);
        volumes_.assign(n, {});
        depths_.assign(n, std::vector<double>(n, 0.0));
        for (std::size_t i = 0; i < n; ++i) {
            costs_[i] = slot_cost(p_, state_.slots[i]);
            volumes_[i] = slot_volume(p_, state_.slots[i]);
        }
        cost_ = depth_ = 0;
        for (std::size_t i = 0; i < n; ++i) {
            cost_ += costs_[i];
            for (std::size_t j = i + 1; j < n; ++j) {
                depths_[i][j] = depths_[j][i] = collision_depth(volumes_[i], volumes_[j]);
                depth_ += depths_[i][j];
            }
        }
    }

    double step(ParameterRole role)
    {
        std::normal_distribution<double> gauss(0.0, 1.0);
        const double sigma = role == ParameterRole::angle    ? 10 * M_PI / 180
                             : role == ParameterRole::length ? p_.diagonal / 20
                                                             : p_.diagonal / 50;
        return sigma * gauss(rng_);
    }

    int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }

    // Fills q with a feasible move; false when the drawn move is impossible or infeasible (the
    // iteration is spent, as a rejected move).
    bool propose(Proposal& q)
    {
        const int n = int(state_.slots.size());
        if (n == 0)
            return false;
        const double u = std::uniform_real_distribution<double>(0.0, 1.0)(rng_);
        if (u < 0.6 || (u >= 0.8 && u < 0.9)) {
            // Change a parameter (0.6) or translate (0.1): the position parameters move by the
            // translation step, the others by their role's.
            const bool translate = u >= 0.6;
            const int i = pick(n);
            Slot s = state_.slots[i];
            if (s.printed)
                return false; // nothing to change: the part lies on the page
            std::vector<int> params;
            for (int k = 0; k < active_parameter_count(s.mechanism); ++k)
                if ((parameter_info(s.mechanism.kind(), k).role == ParameterRole::position) ==
                    translate)
                    params.push_back(k);
            if (params.empty())
                return false;
            const int k = params[pick(int(params.size()))];
            parameter(s.mechanism, k) += step(parameter_info(s.mechanism.kind(), k).role);
            if (!feasible(s.mechanism, p_.card))
                return false;
            q.removed = {i};
            q.added = {s};
            return true;
        }
        if (u < 0.8) {
            // Merge two mechanisms (thesis §6.4.3 move 2), colliding ones first: one patch
            // carries both chains; parameters weighted by the chains' vertex shares.
            if (n < 2)
                return false;
            // Only chains that move alike may share a patch.
            std::vector<std::pair<int, int>> pairs, colliding;
            for (int i = 0; i < n; ++i)
                for (int j = i + 1; j < n; ++j)
                    if (!state_.slots[i].printed && !state_.slots[j].printed &&
                        alike(state_.slots[i], state_.slots[j])) {
                        pairs.push_back({i, j});
                        if (depths_[i][j] > 0)
                            colliding.push_back({i, j});
                    }
            if (!colliding.empty())
                pairs = colliding;
            if (pairs.empty())
                return false;
            const auto [i, j] = pairs[pick(int(pairs.size()))];
            const Slot &a = state_.slots[i], &b = state_.slots[j];
            const double wa = chain_weight(p_, a), wb = chain_weight(p_, b);
            Slot m = wa >= wb ? a : b;
            if (a.mechanism.kind() == b.mechanism.kind() && wa + wb > 0)
                for (int k = 0; k < parameter_count(m.mechanism.kind()); ++k)
                    parameter(m.mechanism, k) =
                        (wa * parameter(a.mechanism, k) + wb * parameter(b.mechanism, k)) /
                        (wa + wb);
            m.chains = a.chains;
            m.chains.insert(m.chains.end(), b.chains.begin(), b.chains.end());
            std::sort(m.chains.begin(), m.chains.end());
            if (!feasible(m.mechanism, p_.card))
                return false;
            q.removed = {i, j};
            q.added = {m};
            return true;
        }
        // Remap (0.1): a merged slot gives its lightest chain back its best own mechanism; a
        // single chain takes another of its feasible candidates (the floating layer included).
        const int i = pick(n);
        const Slot& s = state_.slots[i];
        if (s.chains.size() > 1) {
            int light = s.chains.front();
            for (int j : s.chains)
                if (p_.chains[j].weight < p_.chains[light].weight)
                    light = j;
            Slot rest = s, alone;
            rest.chains.erase(std::find(rest.chains.begin(), rest.chains.end(), light));
            alone.chains = {light};
            int best = int(MotionKind::stationary);
            for (int k = 0; k < motion_kind_count && !still(light); ++k)
                if (p_.candidates[light][k].error_mm < p_.candidates[light][best].error_mm)
                    best = k;
            alone.mechanism = p_.candidates[light][best].mechanism;
            alone.printed = !std::isfinite(p_.candidates[light][best].error_mm);
            if (!alone.printed && !feasible(alone.mechanism, p_.card))
                return false;
            q.removed = {i};
            q.added = {rest, alone};
            return true;
        }
        // Printing it on the page (index motion_kind_count) is one more choice.
        const int chain = s.chains.front();
        std::vector<int> kinds;
        for (int k = 0; k < motion_kind_count; ++k)
            if ((s.printed || k != int(s.mechanism.kind())) &&
                (!still(chain) || k == int(MotionKind::stationary)) &&
                std::isfinite(p_.candidates[chain][k].error_mm))
                kinds.push_back(k);
        if (!s.printed)
            kinds.push_back(motion_kind_count);
        if (kinds.empty())
            return false;
        Slot r = s;
        const int kind = kinds[pick(int(kinds.size()))];
        r.printed = kind == motion_kind_count;
        if (!r.printed)
            r.mechanism = p_.candidates[chain][kind].mechanism;
        q.removed = {i};
        q.added = {r};
        return true;
    }

    bool still(int j) const { return !p_.still.empty() && p_.still[j]; }

    bool alike(const Slot& a, const Slot& b) const
    {
        for (int j : a.chains)
            for (int k : b.chains)
                if (p_.alike.empty() || !p_.alike[j][k])
                    return false;
        return true;
    }

    bool removed(const Proposal& q, int k) const
    {
        return std::find(q.removed.begin(), q.removed.end(), k) != q.removed.end();
    }

    // The move's change of cost and of collision depth. With `hard` (collision-free once), false
    // when one of the added mechanisms meets any other: the move is refused.
    bool evaluate(Proposal& q, double& dcost, double& ddepth, bool hard)
    {
        added_costs_.clear();
        added_volumes_.clear();
        if (!o_.incremental) {
            // The baseline: build the whole proposed state and evaluate every mechanism and
            // pair, as without caches.
            AnnealState next = apply(q);
            const double c = state_cost(p_, next);
            double d = 0;
            for (const SlotCollision& pair : state_collisions(p_, next)) {
                d += pair.depth;
                if (hard && (added_slot(q, pair.a) || added_slot(q, pair.b)))
                    return false;
            }
            for (const Slot& s : q.added) {
                added_costs_.push_back(slot_cost(p_, s));
                added_volumes_.push_back(slot_volume(p_, s));
            }
            dcost = c - cost_;
            ddepth = d - depth_;
            return true;
        }
        const int n = int(state_.slots.size());
        for (const Slot& s : q.added)
            added_volumes_.push_back(slot_volume(p_, s));
        if (hard) {
            for (std::size_t a = 0; a < q.added.size(); ++a) {
                for (int k = 0; k < n; ++k)
                    if (!removed(q, k) && collide(added_volumes_[a], volumes_[k]))
                        return false;
                for (std::size_t b = a + 1; b < q.added.size(); ++b)
                    if (collide(added_volumes_[a], added_volumes_[b]))
                        return false;
            }
        }
        dcost = 0;
        ddepth = 0;
        for (const Slot& s : q.added) {
            added_costs_.push_back(slot_cost(p_, s));
            dcost += added_costs_.back();
        }
        for (int r : q.removed) {
            dcost -= costs_[r];
            for (int k = 0; k < n; ++k)
                if (k != r && (!removed(q, k) || k > r))
                    ddepth -= depths_[r][k];
        }
        added_depths_.assign(q.added.size(), std::vector<double>(n, 0.0));
        if (hard)
            return true; // every new pair is apart (collide is false exactly when depth is 0)
        for (std::size_t a = 0; a < q.added.size(); ++a) {
            for (int k = 0; k < n; ++k)
                if (!removed(q, k)) {
                    added_depths_[a][k] = collision_depth(added_volumes_[a], volumes_[k]);
                    ddepth += added_depths_[a][k];
                }
            for (std::size_t b = a + 1; b < q.added.size(); ++b)
                ddepth += collision_depth(added_volumes_[a], added_volumes_[b]);
        }
        return true;
    }

    // Whether slot k of apply(q) is one of the move's added slots.
    bool added_slot(const Proposal& q, int k) const
    {
        if (q.removed.size() == 1 && q.added.size() == 1)
            return k == q.removed[0];
        return k >= int(state_.slots.size() - q.removed.size());
    }

    AnnealState apply(const Proposal& q) const
    {
        AnnealState next;
        if (q.removed.size() == 1 && q.added.size() == 1) {
            next = state_;
            next.slots[q.removed[0]] = q.added[0];
            return next;
        }
        for (int k = 0; k < int(state_.slots.size()); ++k)
            if (!removed(q, k))
                next.slots.push_back(state_.slots[k]);
        for (const Slot& s : q.added)
            next.slots.push_back(s);
        return next;
    }

    void commit(const Proposal& q)
    {
        if (!o_.incremental) {
            state_ = apply(q);
            rebuild();
            return;
        }
        const int n = int(state_.slots.size());
        if (q.removed.size() == 1 && q.added.size() == 1) {
            const int i = q.removed[0];
            state_.slots[i] = q.added[0];
            cost_ += added_costs_[0] - costs_[i];
            costs_[i] = added_costs_[0];
            volumes_[i] = added_volumes_[0];
            for (int k = 0; k < n; ++k)
                if (k != i) {
                    depth_ += added_depths_[0][k] - depths_[i][k];
                    depths_[i][k] = depths_[k][i] = added_depths_[0][k];
                }
            depth_ = std::max(0.0, depth_);
            return;
        }
        // Merges and splits change the slot count: rebuild the tables from the cached parts.
        std::vector<int> keep;
        for (int k = 0; k < n; ++k)
            if (!removed(q, k))
                keep.push_back(k);
        AnnealState next;
        std::vector<double> costs;
        std::vector<CollisionVolume> volumes;
        for (int k : keep) {
            next.slots.push_back(state_.slots[k]);
            costs.push_back(costs_[k]);
            volumes.push_back(volumes_[k]);
        }
        for (std::size_t a = 0; a < q.added.size(); ++a) {
            next.slots.push_back(q.added[a]);
            costs.push_back(added_costs_[a]);
            volumes.push_back(added_volumes_[a]);
        }
        const std::size_t m = next.slots.size();
        std::vector<std::vector<double>> depths(m, std::vector<double>(m, 0.0));
        for (std::size_t i = 0; i < keep.size(); ++i)
            for (std::size_t j = 0; j < keep.size(); ++j)
                depths[i][j] = depths_[keep[i]][keep[j]];
        for (std::size_t a = 0; a < q.added.size(); ++a) {
            const std::size_t row = keep.size() + a;
            for (std::size_t i = 0; i < keep.size(); ++i)
                depths[row][i] = depths[i][row] = added_depths_[a][keep[i]];
            for (std::size_t b = a + 1; b < q.added.size(); ++b)
                depths[row][keep.size() + b] = depths[keep.size() + b][row] =
                    collision_depth(added_volumes_[a], added_volumes_[b]);
        }
        state_ = std::move(next);
        costs_ = std::move(costs);
        volumes_ = std::move(volumes);
        depths_ = std::move(depths);
        cost_ = depth_ = 0;
        for (std::size_t i = 0; i < m; ++i) {
            cost_ += costs_[i];
            for (std::size_t j = i + 1; j < m; ++j)
                depth_ += depths_[i][j];
        }
    }

    const AnnealProblem& p_;
    const AnnealOptions& o_;
    std::mt19937_64 rng_;
    AnnealState state_;
    std::vector<double> costs_;
    std::vector<CollisionVolume> volumes_;
    std::vector<std::vector<double>> depths_;
    double cost_ = 0, depth_ = 0;
    bool resolved_ = false;
    std::vector<double> added_costs_;
    std::vector<CollisionVolume> added_volumes_;
    std::vector<std::vector<double>> added_depths_;
};

} // namespace

AnnealResult anneal(const AnnealProblem& problem, const AnnealState& start,
                    const AnnealOptions& options)
{
    Search search(problem, start, options);
    return search.run();
}

} // namespace popup::motion
