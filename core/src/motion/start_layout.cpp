#include "start_layout.hpp"

#include <algorithm>
#include <cmath>

namespace popup::motion {

void start_layout(MotionDesign& d)
{
    const AnnealProblem& p = d.problem;
    const std::vector<MotionKind>& mapped = d.mapped;
    std::map<int, std::string>& reasons = d.reasons;
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
        return (a.mechanism.kind() != MotionKind::stationary) >
               (b.mechanism.kind() != MotionKind::stationary);
    });
    std::vector<CollisionVolume> placed;
    for (Slot& slot : start.slots) {
        const CollisionVolume v = slot_volume(p, slot);
        if (slot.mechanism.kind() == MotionKind::stationary)
            for (const CollisionVolume& other : placed)
                if (collide(v, other)) {
                    slot.printed = true;
                    break;
                }
        if (!slot.printed)
            placed.push_back(v);
    }
    d.state = std::move(start);
}

} // namespace popup::motion
