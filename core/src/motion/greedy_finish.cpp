#include "greedy_finish.hpp"

#include <algorithm>
#include <cmath>

namespace popup::motion {

namespace {

bool still_slot(const AnnealProblem& p, const Slot& s)
{
    for (int j : s.chains)
        if (!p.still[j])
            return false;
    return true;
}

// Each moving chain, heaviest first, back onto its own mapping's mechanism where that pays.
void lift_moving_chains(MotionDesign& d)
{
    const AnnealProblem& p = d.problem;
    const std::vector<MotionKind>& mapped = d.mapped;
    AnnealState& state = d.state;
    std::map<int, std::string>& reasons = d.reasons;
    std::vector<int> order;
    for (int j = 0; j < int(p.chains.size()); ++j)
        if (!p.still[j])
            order.push_back(j);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return p.chains[a].weight > p.chains[b].weight; });
    for (int j : order) {
        int i = -1;
        for (int k = 0; k < int(state.slots.size()); ++k)
            if (state.slots[k].chains == std::vector<int>{j})
                i = k;
        const Candidate& own = p.candidates[j][int(mapped[j])];
        if (i < 0 || !std::isfinite(own.error_mm) ||
            (!state.slots[i].printed && state.slots[i].mechanism.kind() == mapped[j]))
            continue;
        AnnealState trial = state;
        trial.slots[i].printed = false;
        trial.slots[i].mechanism = own.mechanism;
        const CollisionVolume v = slot_volume(p, trial.slots[i]);
        bool free = true;
        for (int k = 0; k < int(trial.slots.size()) && free; ++k) {
            if (k == i || !collide(v, slot_volume(p, trial.slots[k])))
                continue;
            if (still_slot(p, trial.slots[k]))
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
}

// Each printed still part onto its floating layer where that is free and no dearer.
void float_still_parts(MotionDesign& d)
{
    const AnnealProblem& p = d.problem;
    AnnealState& state = d.state;
    for (int i = 0; i < int(state.slots.size()); ++i) {
        Slot& s = state.slots[i];
        if (!s.printed || !still_slot(p, s))
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

void take_printed_off(MotionDesign& d)
{
    const std::vector<MotionKind>& mapped = d.mapped;
    AnnealState& state = d.state;
    std::map<int, std::string>& reasons = d.reasons;
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
}

} // namespace

void greedy_finish(MotionDesign& d)
{
    lift_moving_chains(d);
    float_still_parts(d);
    take_printed_off(d);
}

} // namespace popup::motion
