#include "design_from_targets.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include "motion_annealing.hpp"
#include "popup/model/card.hpp"
#include "popup/simulation/check_validity.hpp"
#include "reach_floor.hpp"

namespace popup::motion {

namespace {

using Clock = std::chrono::steady_clock;

/// A chain the search moved onto a mechanism this much worse (E_m, fraction of the character's
/// diagonal) than its own mapping is not resolved by it (docs/DESIGN.md, Conflicting chains).
constexpr double remap_bound = 0.1;

double seconds_since(Clock::time_point t)
{
    return std::chrono::duration<double>(Clock::now() - t).count();
}

std::string mechanism_name(MotionKind kind, const std::string& chain)
{
    static const char* prefix[] = {"VerticalTranslation", "DiagonalTranslation",
                                   "HorizontalTranslation", "RotationArm", "FloatingLayer"};
    std::string clean;
    for (char c : chain)
        clean += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    return std::string(prefix[int(kind)]) + "_" + clean;
}

std::string chain_names(const AnnealProblem& p, const Slot& s)
{
    std::string out;
    for (int j : s.chains)
        out += (out.empty() ? "" : ", ") + p.chains[j].name;
    return out;
}

// Why chain j and the chains of slot `other` do not share one patch, in the report's words:
// their motions differ, their parts lie too far apart when open, or (alike and beside each
// other) one patch carrying both still collided or missed more.
std::string why_not_shared(const AnnealProblem& p, int j, const Slot& other)
{
    std::ostringstream why;
    const ChainTarget &a = p.chains[j], &b = p.chains[other.chains.front()];
    const double motions = motion_distance(a, b);
    const double apart =
        a.target.empty() || b.target.empty() ? 0.0 : (a.target.back() - b.target.back()).norm();
    if (motions > p.alike_fraction * p.diagonal)
        why << "they move too differently to share a patch (motions " << motions
            << " mm apart, RMS)";
    else if (apart > p.beside_fraction * p.diagonal)
        why << "their parts lie " << apart << " mm apart when open, too far to share a patch";
    else
        why << "they move alike (motions " << motions
            << " mm apart, RMS), but one patch carrying both collides or follows them worse";
    return why.str();
}

// Slot i's single chain j and slot `other`'s chains on one patch (a merge): carried by the
// other's mechanism or by j's `own`, whichever collides with nothing and costs least by eq 6.5,
// taken when that is less than `fallback` (the state with j made stationary). True when taken.
bool merged_instead(const AnnealProblem& p, AnnealState& state, int i, int other,
                    const MotionMechanism& own, const AnnealState& fallback)
{
    const Slot& s = state.slots[i];
    if (s.chains.size() != 1 || state.slots[other].printed)
        return false;
    const int j = s.chains.front();
    for (int k : state.slots[other].chains)
        if (p.alike.empty() || !p.alike[j][k])
            return false;
    double best = state_cost(p, fallback);
    std::optional<AnnealState> chosen;
    for (const MotionMechanism& carrier : {state.slots[other].mechanism, own}) {
        AnnealState trial = state;
        Slot& host = trial.slots[other];
        host.mechanism = carrier;
        host.chains.push_back(j);
        std::sort(host.chains.begin(), host.chains.end());
        trial.slots.erase(trial.slots.begin() + i);
        const int merged = other > i ? other - 1 : other;
        bool free = true;
        for (const SlotCollision& h : state_collisions(p, trial))
            free = free && h.a != merged && h.b != merged;
        const double cost = state_cost(p, trial);
        if (free && cost < best) {
            best = cost;
            chosen = std::move(trial);
        }
    }
    if (!chosen)
        return false;
    state = std::move(*chosen);
    return true;
}

double weight_of(const AnnealProblem& p, const Slot& s)
{
    double w = 0;
    for (int j : s.chains)
        w += p.chains[j].weight;
    return w;
}

// Makes slot i stationary (its heaviest chain's floating layer), or takes it out when it already
// is; records why for each of its chains.
void demote(const AnnealProblem& p, AnnealState& state, int i, const std::string& why,
            std::map<int, std::string>& reasons)
{
    Slot& s = state.slots[i];
    for (int j : s.chains)
        reasons[j] = why;
    if (s.mechanism.kind != MotionKind::stationary) {
        int heaviest = s.chains.front();
        for (int j : s.chains)
            if (p.chains[j].weight > p.chains[heaviest].weight)
                heaviest = j;
        const Candidate& c = p.candidates[heaviest][int(MotionKind::stationary)];
        if (std::isfinite(c.error_mm)) {
            s.mechanism = c.mechanism;
            return;
        }
    }
    for (int j : s.chains)
        reasons[j] = why + "; no room for its floating layer, its part stays printed on the page";
    state.slots.erase(state.slots.begin() + i);
}

// True when every chain has the same depth D (eq 6.7): one chain, or a character without depth
// (a planar skeleton). D then says nothing about which part is nearer, and E_d = |D − H| would
// only push the mechanisms with a height (v-box, diagonal, floating layer) away from the flat
// ones whatever the path (docs/DESIGN.md, Depth term without depth).
bool depths_all_equal(const std::vector<ChainTarget>& chains)
{
    for (const ChainTarget& c : chains)
        if (std::abs(c.depth - chains.front().depth) > 1e-9)
            return false;
    return true;
}

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
        Slot trial = s;
        trial.mechanism = own.mechanism;
        const double tie = s.mechanism.kind == mapped[j]
                               ? 0.0
                               : p.chains[j].weight * p.motion_weight * mapping_tie_fraction;
        if (!(slot_cost(p, trial) < slot_cost(p, s) + tie))
            continue;
        const Slot kept = s;
        s = trial;
        const double trial_depth = state_collision(p, state);
        if (trial_depth <= depth + 1e-12)
            depth = trial_depth;
        else
            s = kept;
    }
}

// E_m of chain j printed on the page (the path its part follows with no mechanism).
double printed_error(const AnnealProblem& p, int j)
{
    Slot printed;
    printed.printed = true;
    printed.chains = {j};
    return carried_error(printed, p.chains[j]);
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
        if (s.printed || s.chains.size() != 1 || s.mechanism.kind == MotionKind::stationary)
            continue;
        const int j = s.chains.front();
        const double moved = carried_error(s, p.chains[j]), printed = printed_error(p, j);
        if (moved < printed - 1e-9)
            continue;
        std::ostringstream why;
        why << "its " << to_string(s.mechanism.kind) << " mechanism followed its path no closer ("
            << moved << " mm, eq 6.6) than its part printed on the page (" << printed
            << " mm): printed, leaving the room to the others";
        reasons[j] = why.str();
        s.printed = true;
    }
}

// What making slot i give way costs the motion error (Σ v_j ΔE_m / diagonal): a floating layer
// becomes a printed part (the same projected path: nothing lost), a moving mechanism becomes its
// heaviest chain's floating layer.
double demotion_cost(const AnnealProblem& p, const Slot& s)
{
    double before = 0, after = 0;
    Slot demoted = s;
    if (s.mechanism.kind == MotionKind::stationary) {
        demoted.printed = true;
    } else {
        int heaviest = s.chains.front();
        for (int j : s.chains)
            if (p.chains[j].weight > p.chains[heaviest].weight)
                heaviest = j;
        const Candidate& c = p.candidates[heaviest][int(MotionKind::stationary)];
        if (std::isfinite(c.error_mm))
            demoted.mechanism = c.mechanism;
        else
            demoted.printed = true;
    }
    for (int j : s.chains) {
        before += p.chains[j].weight * carried_error(s, p.chains[j]);
        after += p.chains[j].weight * carried_error(demoted, p.chains[j]);
    }
    return (after - before) / p.diagonal;
}

// The slot of the pair (a, b) that gives way: the one whose demotion costs the motion error
// least (a floating layer before a moving mechanism), the lighter on a tie.
int loser_of(const AnnealProblem& p, const AnnealState& state, int a, int b)
{
    const double ca = demotion_cost(p, state.slots[a]), cb = demotion_cost(p, state.slots[b]);
    if (std::abs(ca - cb) > 1e-9)
        return ca < cb ? a : b;
    return weight_of(p, state.slots[a]) <= weight_of(p, state.slots[b]) ? a : b;
}

} // namespace

double layer_height_max(const MotionOptions& o)
{
    if (o.layer_height_max > 0)
        return o.layer_height_max;
    return 25.0 * std::sqrt(o.view.card_width * o.view.card_depth / (210.0 * 148.5));
}

Result<MotionResult> design_from_targets(const MotionTargets& targets, const MotionOptions& o,
                                         const CancelFlag* cancel, std::atomic<double>* progress)
{
    Result<MotionResult> out;
    MotionResult& r = out.value;
    r.targets = targets;
    const Clock::time_point begun = Clock::now();
    auto bad = [&](const std::string& option, const std::string& message) {
        out.fail(DiagnosticCode::bad_option, message, about_parameter(option));
    };
    if (!(o.motion_weight >= 0 && o.depth_weight >= 0 && o.motion_weight + o.depth_weight > 0))
        bad("motion_weight", "motion_weight " + std::to_string(o.motion_weight) +
                                 " and depth_weight " + std::to_string(o.depth_weight) +
                                 " must be >= 0, not both 0");
    if (!(o.collision_weight > 0))
        bad("collision_weight",
            "collision_weight " + std::to_string(o.collision_weight) + " must be > 0");
    if (!(o.iterations >= 0 && o.iterations <= 100000000))
        bad("iterations",
            "iterations " + std::to_string(o.iterations) + " must be in [0, 100000000]");
    if (!(o.search_chains >= 1 && o.search_chains <= 16))
        bad("search_chains",
            "search_chains " + std::to_string(o.search_chains) + " must be in [1, 16]");
    if (!(o.view.card_width > 0 && o.view.card_depth > 0))
        bad("card_width", "the card (" + std::to_string(o.view.card_width) + " × " +
                              std::to_string(o.view.card_depth) + " mm) must be > 0 both ways");
    if (targets.paths.size() != targets.chains.size())
        bad("targets", "the targets have " + std::to_string(targets.paths.size()) + " paths for " +
                           std::to_string(targets.chains.size()) + " chains; they must match");
    if (!(targets.diagonal_mm > 0))
        bad("targets", "the character's diagonal on the card (" +
                           std::to_string(targets.diagonal_mm) + " mm) must be > 0");
    for (std::size_t j = 0; j < targets.paths.size(); ++j) {
        const ChainPath& path = targets.paths[j];
        if (path.s.size() < 2 || path.effector.size() != path.s.size())
            bad("targets", "chain " + targets.chains[j].name + ": its path has " +
                               std::to_string(path.s.size()) + " samples and " +
                               std::to_string(path.effector.size()) +
                               " effector points; it needs >= 2 of each, as many");
    }
    if (!out.ok)
        return out;

    r.card.width = o.view.card_width;
    r.card.depth = o.view.card_depth;
    AnnealProblem p;
    p.card = r.card;
    p.diagonal = targets.diagonal_mm;
    p.h_max = layer_height_max(o);
    p.motion_weight = o.motion_weight;
    p.depth_weight = o.depth_weight;
    p.collision_weight = o.collision_weight;

    // Mapping and parameter estimation (thesis §6.2–6.3).
    Clock::time_point t = Clock::now();
    std::vector<MotionKind> mapped;
    // The search scores every k-th sample of a long path (search_target); the report, all.
    std::vector<ChainTarget> full_chains;
    for (std::size_t j = 0; j < targets.chains.size(); ++j) {
        stop_if_cancelled(cancel, "design_motion: mapping");
        ChainTarget c;
        c.name = targets.chains[j].name;
        c.s = targets.paths[j].s;
        c.target = targets.paths[j].effector;
        c.weight = targets.chains[j].weight;
        c.depth = targets.paths[j].depth;
        full_chains.push_back(c);
        p.chains.push_back(search_target(c));
        p.candidates.push_back(fit_candidates(c, r.card, p.h_max));
        mapped.push_back(best_mapping(p.candidates.back(), c, 0.01 * p.diagonal, p.diagonal));
        if (progress)
            progress->store(0.2 * double(j + 1) / targets.chains.size());
    }
    for (MotionKind kind : mapped)
        p.still.push_back(kind == MotionKind::stationary);
    prepare_alike(p);
    if (depths_all_equal(p.chains))
        p.depth_weight = 0.0; // D is undefined (0.5 for all): E_d would only charge height
    r.timings_s.push_back({"mapping", seconds_since(t)});

    std::map<int, std::string> reasons; // chain -> why stationary
    AnnealState start;
    for (std::size_t j = 0; j < p.chains.size(); ++j) {
        const Candidate& c = p.candidates[j][int(mapped[j])];
        if (!std::isfinite(c.error_mm)) {
            reasons[int(j)] = "no mechanism fits it on the card (" + c.why + ")";
            continue;
        }
        start.slots.push_back({c.mechanism, {int(j)}});
    }
    // Layout of the start (thesis §6.4): the moving chains' mechanisms first, then a still
    // chain's floating layer only where it takes no room from them; else its part starts printed
    // on the page (the search may still lift it).
    std::stable_sort(start.slots.begin(), start.slots.end(), [](const Slot& a, const Slot& b) {
        return (a.mechanism.kind != MotionKind::stationary) >
               (b.mechanism.kind != MotionKind::stationary);
    });
    {
        std::vector<CollisionVolume> placed;
        for (Slot& slot : start.slots) {
            const CollisionVolume v = slot_volume(p, slot);
            if (slot.mechanism.kind == MotionKind::stationary)
                for (const CollisionVolume& other : placed)
                    if (collide(v, other)) {
                        slot.printed = true;
                        break;
                    }
            if (!slot.printed)
                placed.push_back(v);
        }
    }

    // Simulated annealing: independent search chains on their own threads, best kept.
    t = Clock::now();
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
    for (const AnnealResult& a : results)
        r.iterations += a.iterations;
    restore_own_fits(p, mapped, state);
    print_pointless(p, state, reasons);
    r.timings_s.push_back({"annealing", seconds_since(t)});
    // Greedy finish (compound moves the search rarely makes in one step): each moving chain,
    // heaviest first, that the search left printed, on a floating layer or off its own mapping
    // takes back its own mapping's mechanism when that hits no moving mechanism (the still
    // parts' floating layers it would hit are printed instead) and eq 6.5 drops; then each
    // printed still part takes its floating layer where that is free and cheaper.
    {
        std::vector<int> order;
        for (int j = 0; j < int(p.chains.size()); ++j)
            if (!p.still[j])
                order.push_back(j);
        std::stable_sort(order.begin(), order.end(),
                         [&](int a, int b) { return p.chains[a].weight > p.chains[b].weight; });
        auto still_slot = [&](const Slot& s) {
            for (int j : s.chains)
                if (!p.still[j])
                    return false;
            return true;
        };
        for (int j : order) {
            int i = -1;
            for (int k = 0; k < int(state.slots.size()); ++k)
                if (state.slots[k].chains == std::vector<int>{j})
                    i = k;
            const Candidate& own = p.candidates[j][int(mapped[j])];
            if (i < 0 || !std::isfinite(own.error_mm) ||
                (!state.slots[i].printed && state.slots[i].mechanism.kind == mapped[j]))
                continue;
            AnnealState trial = state;
            trial.slots[i].printed = false;
            trial.slots[i].mechanism = own.mechanism;
            const CollisionVolume v = slot_volume(p, trial.slots[i]);
            bool free = true;
            for (int k = 0; k < int(trial.slots.size()) && free; ++k) {
                if (k == i || !collide(v, slot_volume(p, trial.slots[k])))
                    continue;
                if (still_slot(trial.slots[k]))
                    trial.slots[k].printed = true;
                else
                    free = false;
            }
            // Only a mechanism that follows the chain closer than its printed part is worth room.
            if (free && state_cost(p, trial) < state_cost(p, state) &&
                carried_error(trial.slots[i], p.chains[j]) < printed_error(p, j) - 1e-9) {
                state = trial;
                reasons.erase(j); // moving again: print_pointless's reason no longer holds
            }
        }
        for (int i = 0; i < int(state.slots.size()); ++i) {
            Slot& s = state.slots[i];
            if (!s.printed || !still_slot(s))
                continue;
            int heaviest = s.chains.front();
            for (int j : s.chains)
                if (p.chains[j].weight > p.chains[heaviest].weight)
                    heaviest = j;
            const Candidate& c = p.candidates[heaviest][int(MotionKind::stationary)];
            if (!std::isfinite(c.error_mm))
                continue;
            Slot trial = s;
            trial.printed = false;
            trial.mechanism = c.mechanism;
            // A floating layer that costs no more than the printed part is taken (thesis §6.4:
            // still parts stand on floating layers); a tie is common, both following the path.
            if (slot_cost(p, trial) > slot_cost(p, s) + 1e-12)
                continue;
            const CollisionVolume v = slot_volume(p, trial);
            bool free = true;
            for (int k = 0; k < int(state.slots.size()) && free; ++k)
                free = k == i || !collide(v, slot_volume(p, state.slots[k]));
            if (free)
                s = trial;
        }
    }
    // Parts the search printed on the page leave the mechanisms (the report's stationary parts
    // without a floating layer).
    for (int i = int(state.slots.size()) - 1; i >= 0; --i) {
        if (!state.slots[i].printed)
            continue;
        for (int j : state.slots[i].chains)
            reasons.emplace(
                j,
                mapped[j] == MotionKind::stationary
                    ? "it does not move: printed on the page, where it takes no room from the "
                      "moving mechanisms (a floating layer would cost more, eq 6.5, or collide)"
                    : "the search printed it on the page: every mechanism that moves it collides "
                      "with the others or costs more (eq 6.5)");
        state.slots.erase(state.slots.begin() + i);
    }

    // Conflicts the search resolved by moving a chain off its own mechanism onto one that
    // misses its path by more than remap_bound (of the diagonal) beyond its own: the chain is
    // not resolved (thesis §6.4.3), so when its own mechanism collides with another slot's it
    // becomes stationary instead, and the reason names the other chain.
    for (int i = int(state.slots.size()) - 1; i >= 0; --i) {
        const Slot& s = state.slots[i];
        if (s.chains.size() != 1 || s.mechanism.kind == MotionKind::stationary)
            continue;
        const int j = s.chains.front();
        const Candidate& own = p.candidates[j][int(mapped[j])];
        const double error = motion_error(s.mechanism, p.chains[j]);
        if (mapped[j] == MotionKind::stationary || !std::isfinite(own.error_mm) ||
            error <= own.error_mm + remap_bound * p.diagonal)
            continue;
        AnnealState trial = state;
        trial.slots[i].mechanism = own.mechanism;
        const SlotCollision* worst = nullptr;
        const std::vector<SlotCollision> hits = state_collisions(p, trial);
        for (const SlotCollision& h : hits)
            if ((h.a == i || h.b == i) && (!worst || h.depth > worst->depth))
                worst = &h;
        if (!worst)
            continue; // its own mechanism fits in: the search kept the other one for eq 6.5
        const int other = worst->a == i ? worst->b : worst->a;
        std::ostringstream why;
        why << "its own " << to_string(mapped[j]) << " mechanism (" << own.error_mm
            << " mm from its path) collides with the one carrying "
            << chain_names(p, state.slots[other]) << " (volumes overlap by " << worst->depth
            << " mm) and " << why_not_shared(p, j, state.slots[other]) << "; the search's "
            << to_string(s.mechanism.kind) << " instead misses it by " << error << " mm, more than "
            << remap_bound << " of the character's diagonal worse";
        // Alike chains may share the other's patch (thesis §6.4.3, merging) rather than stand
        // still, when that costs less.
        std::map<int, std::string> demoted_reasons = reasons;
        AnnealState demoted = state;
        demote(p, demoted, i, why.str(), demoted_reasons);
        if (merged_instead(p, state, i, other, own.mechanism, demoted))
            continue;
        state = std::move(demoted);
        reasons = std::move(demoted_reasons);
    }

    // Collisions the search could not resolve: the lighter mechanism of the deepest pair
    // becomes stationary (thesis §6.4.3 move 4), until none is left.
    t = Clock::now();
    for (;;) {
        const std::vector<SlotCollision> hits = state_collisions(p, state);
        if (hits.empty())
            break;
        const SlotCollision worst = *std::max_element(
            hits.begin(), hits.end(),
            [](const SlotCollision& x, const SlotCollision& y) { return x.depth < y.depth; });
        const int loser = loser_of(p, state, worst.a, worst.b);
        const int other = loser == worst.a ? worst.b : worst.a;
        std::ostringstream why;
        why << "its " << to_string(state.slots[loser].mechanism.kind)
            << " mechanism collides with the one carrying " << chain_names(p, state.slots[other])
            << " (volumes overlap by " << worst.depth << " mm) and "
            << why_not_shared(p, state.slots[loser].chains.front(), state.slots[other]);
        demote(p, state, loser, why.str(), reasons);
    }
    r.timings_s.push_back({"collision repair", seconds_since(t)});

    // Build with the library's generators and run the full simulator; a mechanism the
    // generators refuse or that crosses another is made stationary, then taken out.
    t = Clock::now();
    double validity_s = 0;
    std::vector<std::vector<std::string>> slot_mechanisms;
    for (int round = 0;; ++round) {
        stop_if_cancelled(cancel, "design_motion: building");
        Result<Scaffold> card = make_card(r.card);
        if (!card.ok) {
            out.fail_with(card.diagnostics);
            return out;
        }
        Scaffold scaffold = card.value;
        const BasePatchPair host = central_fold(scaffold);
        std::vector<FittedMechanism> rows;
        std::vector<std::set<int>> slot_patches;
        slot_mechanisms.clear();
        int refused = -1;
        std::string refusal;
        for (int i = 0; i < int(state.slots.size()); ++i) {
            const Slot& s = state.slots[i];
            const std::string name =
                mechanism_name(s.mechanism.kind, p.chains[s.chains.front()].name);
            Result<std::vector<MechanismParts>> built =
                build_mechanism(scaffold, host, s.mechanism, name, rows);
            if (!built.ok) {
                refused = i;
                refusal = built.diagnostics.empty() ? "refused" : built.diagnostics[0].message;
                break;
            }
            std::set<int> ids;
            std::vector<std::string> names;
            for (const MechanismParts& part : built.value) {
                ids.insert(part.patches.begin(), part.patches.end());
                names.push_back(part.name);
            }
            slot_patches.push_back(ids);
            slot_mechanisms.push_back(names);
        }
        if (refused >= 0) {
            out.warn(DiagnosticCode::mechanism_dropped,
                     "chain " + chain_names(p, state.slots[refused]) +
                         ": the generator refused its mechanism: " + refusal);
            demote(p, state, refused, "the generator refused its mechanism: " + refusal, reasons);
            continue;
        }
        const Clock::time_point v0 = Clock::now();
        ValidityOptions vo;
        vo.cancel = cancel;
        vo.clearance = 0.0;
        const ValidityReport report = check_validity(scaffold, vo);
        validity_s += seconds_since(v0);
        r.scaffold = scaffold;
        r.mechanisms = rows;
        r.valid = report.valid();
        if (r.valid || state.slots.empty() || round >= 2 * int(p.chains.size()) + 2) {
            if (!r.valid)
                for (const Diagnostic& d : report.diagnostics)
                    r.diagnostics.push_back(d);
            break;
        }
        // The lightest mechanism among the crossing patches (or, for another verdict, the
        // lightest moving one) gives way.
        std::set<int> involved;
        for (const Crossing& c : report.crossings)
            for (int i = 0; i < int(slot_patches.size()); ++i)
                if (slot_patches[i].count(c.patch_a) || slot_patches[i].count(c.patch_b))
                    involved.insert(i);
        if (involved.empty())
            for (int i = 0; i < int(state.slots.size()); ++i)
                involved.insert(i);
        int loser = *involved.begin();
        for (int i : involved)
            loser = loser_of(p, state, loser, i);
        std::string verdict = !report.intersection_free ? "patches cross in the simulator"
                              : !report.foldable        ? "the card does not fold"
                              : !report.stable          ? "a part moves freely"
                                                        : "a part is not enclosed when closed";
        out.warn(DiagnosticCode::mechanism_dropped,
                 "chain " + chain_names(p, state.slots[loser]) + ": " + verdict +
                     " with its mechanism; it is made stationary");
        demote(p, state, loser, "the full simulator's check failed (" + verdict + ")", reasons);
    }
    r.timings_s.push_back({"build", seconds_since(t) - validity_s});
    r.timings_s.push_back({"validity", validity_s});

    // A moving chain left still by the search: when its own mechanism collides with the final
    // design, the report names the mechanism it would hit (the search's own choice otherwise).
    auto conflict = [&](int j, int own_slot) -> std::string {
        if (mapped[j] == MotionKind::stationary)
            return {};
        const Candidate& own = p.candidates[j][int(mapped[j])];
        if (!std::isfinite(own.error_mm))
            return {};
        Slot mine;
        mine.mechanism = own.mechanism;
        mine.chains = {j};
        const CollisionVolume v = slot_volume(p, mine);
        int other = -1;
        double deepest = 0;
        for (int k = 0; k < int(state.slots.size()); ++k) {
            if (k == own_slot)
                continue;
            const double d = collision_depth(v, slot_volume(p, state.slots[k]));
            if (d > deepest) {
                deepest = d;
                other = k;
            }
        }
        if (other < 0)
            return {};
        std::ostringstream why;
        why << "its own " << to_string(mapped[j]) << " mechanism (" << own.error_mm
            << " mm from its path) collides with the one carrying "
            << chain_names(p, state.slots[other]) << " (volumes overlap by " << deepest
            << " mm) and they move too differently to share a patch (motions "
            << motion_distance(p.chains[j], p.chains[state.slots[other].chains.front()])
            << " mm apart, RMS)";
        return why.str();
    };
    auto generic = [&](int j) {
        return !reasons.count(j) || reasons[j].rfind("the search", 0) == 0;
    };

    // Report (eq 6.6 per chain, the vertex-weighted total, mapping and status).
    r.cost = state_cost(p, state);
    std::vector<int> slot_of(p.chains.size(), -1);
    for (int i = 0; i < int(state.slots.size()); ++i)
        for (int j : state.slots[i].chains)
            slot_of[j] = i;
    for (int j = 0; j < int(p.chains.size()); ++j) {
        const ChainTarget& c = full_chains[j];
        ChainReport cr;
        cr.name = c.name;
        cr.weight = c.weight;
        cr.s = c.s;
        cr.target = c.target;
        const int i = slot_of[j];
        if (i >= 0) {
            const Slot& s = state.slots[i];
            cr.mapping = to_string(s.mechanism.kind);
            if (i < int(slot_mechanisms.size()))
                cr.mechanisms = slot_mechanisms[i];
            cr.achieved = carried_path(s, c);
            cr.error_mm = carried_error(s, c);
            if (s.chains.size() > 1) {
                cr.status = "merged";
                std::string others;
                for (int k : s.chains)
                    if (k != j)
                        others += (others.empty() ? "" : ", ") + p.chains[k].name;
                std::ostringstream why;
                why << "shares its " << cr.mapping << " mechanism with " << others
                    << " (they move alike: their motions, less their open-state places, within "
                    << p.alike_fraction * p.diagonal << " mm RMS; each part keeps its place on the "
                    << "patch)";
                cr.reason = why.str();
            } else if (s.mechanism.kind == MotionKind::stationary) {
                cr.status = "stationary";
                const std::string hit = generic(j) ? conflict(j, i) : std::string();
                cr.reason = !hit.empty()       ? hit + "; a floating layer carries it"
                            : reasons.count(j) ? reasons[j]
                            : mapped[j] == MotionKind::stationary
                                ? "it does not move (a floating layer carries it)"
                                : "the search found the floating layer cheaper than moving it";
            } else {
                cr.status = "animated";
            }
        } else {
            // Printed on the page: it moves with the ground page's point under it.
            cr.mapping = "stationary";
            cr.status = "stationary";
            const std::string hit = generic(j) ? conflict(j, -1) : std::string();
            cr.reason = !hit.empty()       ? hit + "; its part is printed on the page"
                        : reasons.count(j) ? reasons[j]
                                           : "no mechanism carries it";
            Slot printed;
            printed.printed = true;
            printed.chains = {j};
            cr.achieved = carried_path(printed, c);
            cr.error_mm = carried_error(printed, c);
        }
        cr.error = cr.error_mm / p.diagonal;
        r.weighted_error += c.weight * cr.error;
        cr.floor_mm = reach_floor_mm(c, p.card);
        cr.floor = cr.floor_mm / p.diagonal;
        r.weighted_floor += c.weight * cr.floor;
        r.chains.push_back(cr);
    }
    if (!r.valid)
        r.diagnostics.push_back(
            Diagnostic::warning(DiagnosticCode::no_design_found,
                                "the design does not pass the full simulator's validity check"));
    r.timings_s.push_back({"total", seconds_since(begun)});
    if (progress)
        progress->store(1.0);
    out.diagnostics.insert(out.diagnostics.end(), r.diagnostics.begin(), r.diagnostics.end());
    return out;
}

} // namespace popup::motion
