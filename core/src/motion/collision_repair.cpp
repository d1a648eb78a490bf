#include "collision_repair.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "design_reasons.hpp"
#include "give_way.hpp"

namespace popup::motion {

namespace {

/// A chain the search moved onto a mechanism this much worse (E_m, fraction of the character's
/// diagonal) than its own mapping is not resolved by it (docs/DESIGN.md, Conflicting chains).
constexpr double remap_bound = 0.1;

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

} // namespace

void release_far_remaps(MotionDesign& d)
{
    const AnnealProblem& p = d.problem;
    const std::vector<MotionKind>& mapped = d.mapped;
    AnnealState& state = d.state;
    std::map<int, std::string>& reasons = d.reasons;
    for (int i = int(state.slots.size()) - 1; i >= 0; --i) {
        const Slot& s = state.slots[i];
        if (s.chains.size() != 1 || s.mechanism.kind() == MotionKind::stationary)
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
            << to_string(s.mechanism.kind()) << " instead misses it by " << error
            << " mm, more than " << remap_bound << " of the character's diagonal worse";
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
}

void repair_collisions(MotionDesign& d)
{
    const AnnealProblem& p = d.problem;
    AnnealState& state = d.state;
    std::map<int, std::string>& reasons = d.reasons;
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
        why << "its " << to_string(state.slots[loser].mechanism.kind())
            << " mechanism collides with the one carrying " << chain_names(p, state.slots[other])
            << " (volumes overlap by " << worst.depth << " mm) and "
            << why_not_shared(p, state.slots[loser].chains.front(), state.slots[other]);
        demote(p, state, loser, why.str(), reasons);
    }
}

} // namespace popup::motion
