#include "design_search.hpp"

#include <cmath>
#include <exception>
#include <sstream>
#include <thread>

#include "motion_annealing.hpp"

namespace popup::motion {

namespace {

// The search returns where its random walk was cheapest, which can leave a chain on worse
// parameters than its own fitted candidate (a short search at a high temperature wanders off a
// path it matched exactly), or on another mechanism that makes its path equally well (a
// diagonal whose step sits still on its wings also rises along the fold). Each single-chain
// slot takes the candidate of its mapping back when that lowers eq 6.5, or, for another kind,
// costs no more than best_mapping's tie (E_m within 1e-4 of the diagonal), and adds no
// collision depth: the result never collides more, and costs at most that tie more.
void restore_own_fits(const AnnealProblem& p, const std::vector<MotionKind>& mapped,
                      AnnealState& state)
{
    double depth = state_collision(p, state);
    for (Slot& s : state.slots) {
        if (s.chains.size() != 1 || s.printed) // a printed part: the greedy finish below
            continue;
        const int j = s.chains.front();
        const Candidate& own = p.candidates[j][int(mapped[j])];
        if (!std::isfinite(own.error_mm))
            continue;
        const double tie = s.mechanism.kind() == mapped[j]
                               ? 0.0
                               : p.chains[j].weight * p.motion_weight * mapping_tie_fraction;
        // Only the mechanism is tried: the slot's chains stay (copying the one-chain vector
        // also tripped GCC 14's -Warray-bounds).
        const MotionMechanism kept = s.mechanism;
        const double cost_before = slot_cost(p, s);
        s.mechanism = own.mechanism;
        if (!(slot_cost(p, s) < cost_before + tie)) {
            s.mechanism = kept;
            continue;
        }
        const double trial_depth = state_collision(p, state);
        if (trial_depth <= depth + 1e-12)
            depth = trial_depth;
        else
            s.mechanism = kept;
    }
}

// A moving mechanism that follows its chain no closer than the part printed on the page takes
// room for nothing: eq 6.5 can keep it only because a flat mechanism's depth is not charged and a
// printed part's is (found on the demo's waving figure: an extruding patch 0.150 of the diagonal
// from its path, printed 0.148, held the room the waving hand's rotation arm needed). Such a
// part is printed, and the others may take the room.
void print_pointless(const AnnealProblem& p, AnnealState& state,
                     std::map<int, std::string>& reasons)
{
    for (Slot& s : state.slots) {
        if (s.printed || s.chains.size() != 1 || s.mechanism.kind() == MotionKind::stationary)
            continue;
        const int j = s.chains.front();
        const double moved = carried_error(s, p.chains[j]), printed = printed_error(p, j);
        if (moved < printed - 1e-9)
            continue;
        std::ostringstream why;
        why << "its " << to_string(s.mechanism.kind()) << " mechanism followed its path no closer ("
            << moved << " mm, eq 6.6) than its part printed on the page (" << printed
            << " mm): printed, leaving the room to the others";
        reasons[j] = why.str();
        s.printed = true;
    }
}

} // namespace

long search_design(MotionDesign& d, const MotionOptions& o, const CancelFlag* cancel,
                   std::atomic<double>* progress)
{
    const AnnealProblem& p = d.problem;
    const AnnealState& start = d.state;
    const int runs = o.search_chains;
    std::vector<AnnealResult> results(runs);
    std::vector<AnnealOptions> options(runs);
    std::vector<std::exception_ptr> errors(runs);
    for (int k = 0; k < runs; ++k) {
        options[k].iterations = o.iterations;
        options[k].seed = o.seed * 0x9E3779B97F4A7C15ULL + std::uint64_t(k) * 0xBF58476D1CE4E5B9ULL;
        options[k].cancel = cancel;
        options[k].progress = k == 0 ? progress : nullptr;
        options[k].progress_from = 0.2;
        options[k].progress_to = 0.85;
    }
    {
        std::vector<std::thread> threads;
        for (int k = 0; k < runs; ++k)
            threads.emplace_back([&, k] {
                try {
                    results[k] = anneal(p, start, options[k]);
                } catch (...) {
                    errors[k] = std::current_exception();
                }
            });
        for (std::thread& th : threads)
            th.join();
    }
    for (const std::exception_ptr& e : errors)
        if (e)
            std::rethrow_exception(e);
    int best = 0;
    for (int k = 1; k < runs; ++k) {
        const AnnealResult &a = results[k], &b = results[best];
        if (a.collision < b.collision - 1e-12 ||
            (a.collision <= b.collision + 1e-12 && a.cost < b.cost))
            best = k;
    }
    AnnealState state = results[best].best;
    long iterations = 0;
    for (const AnnealResult& a : results)
        iterations += a.iterations;
    restore_own_fits(p, d.mapped, state);
    print_pointless(p, state, d.reasons);
    d.state = std::move(state);
    return iterations;
}

} // namespace popup::motion
