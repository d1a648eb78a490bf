#include "greedy_finish.hpp"

#include <algorithm>
#include <cmath>

#include "give_way.hpp"

namespace popup::motion {

namespace {

bool still_slot(const AnnealProblem& p, const Slot& s)
{
    for (int j : s.chains)
        if (!p.still[j])
            return false;
    return true;
}

// Chain j's slot i on `mechanism`: the slots it then meets give way where they can, a floating
// layer by taking another shape about its point (clear_layer), else by printing its part on the
// page (its path from the page's point: a still part's is the layer's, a moving chain's left on
// a layer is its printed path). False when it meets a moving mechanism.
bool lift_onto(const AnnealProblem& p, AnnealState& trial, int i, const MotionMechanism& mechanism)
{
    trial.slots[i].printed = false;
    trial.slots[i].mechanism = mechanism;
    const CollisionVolume v = slot_volume(p, trial.slots[i]);
    for (int k = 0; k < int(trial.slots.size()); ++k) {
        if (k == i || !collide(v, slot_volume(p, trial.slots[k])))
            continue;
        if (trial.slots[k].mechanism.kind() != MotionKind::stationary)
            return false;
        if (!clear_layer(p, trial, k, v, i))
            trial.slots[k].printed = true;
    }
    return true;
}

// Each moving chain, heaviest first, onto the best of its fitted mechanisms that follows it
// closer than it is followed now and than its printed part, where that hits no moving mechanism
// and pays. It pays when eq 6.5 drops, or when the motion error Σ v_j E_m drops (motion first):
// eq 6.5 charges a part printed to make room its whole depth |D − 0|, up to w_d v_j, against a
// limb's motion w_m v_j ΔE_m / diagonal, ten times smaller on a humanoid (the walk's right hand,
// 4.0 mm on its arm against 6.3 mm printed, stood still so that the left hand's floating layer
// kept its depth; docs/MATH.md, "Motion before depth").
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
        if (i < 0 || (!state.slots[i].printed && state.slots[i].mechanism.kind() == mapped[j]))
            continue;
        // Its own mapping first, then its other moving candidates, closest first.
        std::vector<int> kinds;
        for (int k = 0; k < motion_kind_count; ++k)
            if (k != int(MotionKind::stationary) && std::isfinite(p.candidates[j][k].error_mm))
                kinds.push_back(k);
        std::stable_sort(kinds.begin(), kinds.end(), [&](int a, int b) {
            return (a == int(mapped[j])) > (b == int(mapped[j])) ||
                   ((a == int(mapped[j])) == (b == int(mapped[j])) &&
                    p.candidates[j][a].error_mm < p.candidates[j][b].error_mm);
        });
        const double now = carried_error(state.slots[i], p.chains[j]);
        const double cost = state_cost(p, state), motion = state_motion_error(p, state);
        for (int k : kinds) {
            AnnealState trial = state;
            if (!lift_onto(p, trial, i, p.candidates[j][k].mechanism))
                continue;
            // Only a mechanism that follows the chain closer than its printed part and than
            // what carries it now is worth room.
            const double moved = carried_error(trial.slots[i], p.chains[j]);
            if (!(moved < printed_error(p, j) - 1e-9 && moved < now - 1e-9))
                continue;
            if (state_cost(p, trial) < cost || state_motion_error(p, trial) < motion - 1e-9) {
                state = trial;
                reasons.erase(j); // moving again: print_pointless's reason no longer holds
                break;
            }
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
