#include "give_way.hpp"

#include <cmath>
#include <optional>

#include "motion_feasibility.hpp"
#include "motion_parameters.hpp"

namespace popup::motion {

namespace {

// What making slot i give way costs the motion error (Σ v_j ΔE_m / diagonal): a floating layer
// becomes a printed part (the same projected path: nothing lost), a moving mechanism becomes its
// heaviest chain's floating layer.
double demotion_cost(const AnnealProblem& p, const Slot& s)
{
    double before = 0, after = 0;
    Slot demoted = s;
    if (s.mechanism.kind() == MotionKind::stationary) {
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

} // namespace

void demote(const AnnealProblem& p, AnnealState& state, int i, const std::string& why,
            std::map<int, std::string>& reasons)
{
    Slot& s = state.slots[i];
    for (int j : s.chains)
        reasons[j] = why;
    if (s.mechanism.kind() != MotionKind::stationary) {
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

int loser_of(const AnnealProblem& p, const AnnealState& state, int a, int b)
{
    const double ca = demotion_cost(p, state.slots[a]), cb = demotion_cost(p, state.slots[b]);
    if (std::abs(ca - cb) > 1e-9)
        return ca < cb ? a : b;
    return chain_weight(p, state.slots[a]) <= chain_weight(p, state.slots[b]) ? a : b;
}

bool clear_layer(const AnnealProblem& p, AnnealState& state, int k, const CollisionVolume& room,
                 int except)
{
    const Slot& s = state.slots[k];
    if (s.printed || s.mechanism.kind() != MotionKind::stationary)
        return false;
    const StationaryMotion& f = s.mechanism.stationary();
    const double middle = f.offset + f.width / 2;
    // The shortest glued crease upwards: a narrower, lower layer on shorter supports takes less
    // room; the overhang only has to reach the anchor (support + overhang >= |anchor|).
    const double c = shortest_crease();
    std::optional<Slot> best;
    double best_cost = HUGE_VAL;
    for (double width : {c, 1.5 * c, 2 * c, f.width})
        for (double height : {c, 1.5 * c, 2 * c, 3 * c, f.height})
            for (double support : {c, 1.5 * c, 2 * c, f.support}) {
                Slot t = s;
                StationaryMotion& g = t.mechanism.stationary();
                g.width = width;
                g.offset = middle - width / 2;
                g.height = height;
                g.support = support;
                g.overhang = std::max(0.0, std::abs(g.anchor) - support);
                const double cost = slot_cost(p, t);
                if (!(cost < best_cost) || !feasible(t.mechanism, p.card))
                    continue;
                const CollisionVolume v = slot_volume(p, t);
                bool free = !collide(v, room);
                for (int m = 0; m < int(state.slots.size()) && free; ++m)
                    free = m == k || m == except || !collide(v, slot_volume(p, state.slots[m]));
                if (free) {
                    best = t;
                    best_cost = cost;
                }
            }
    if (!best)
        return false;
    state.slots[k] = *best;
    return true;
}

} // namespace popup::motion
