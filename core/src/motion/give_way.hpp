#pragma once
#include <map>
#include <string>

#include "anneal_problem.hpp"

namespace popup::motion {

// Makes slot i stationary (its heaviest chain's floating layer), or takes it out when it already
// is; records why for each of its chains.
void demote(const AnnealProblem& p, AnnealState& state, int i, const std::string& why,
            std::map<int, std::string>& reasons);

// The slot of the pair (a, b) that gives way: the one whose demotion costs the motion error
// least (a floating layer before a moving mechanism), the lighter on a tie.
int loser_of(const AnnealProblem& p, const AnnealState& state, int a, int b);

/// Makes floating-layer slot k clear `room` and every other slot but `except` (docs/MATH.md,
/// "A floating layer gives way"): its point (x = anchor·sin(θ/2), y = offset + width/2) is all
/// eq 6.6 sees, so its width (about that y), height, support and overhang may take any feasible
/// values, the cheapest by eq 6.5 that collides with nothing is taken. False, the slot untouched,
/// when it is printed, not a floating layer, or no such shape is free.
bool clear_layer(const AnnealProblem& p, AnnealState& state, int k, const CollisionVolume& room,
                 int except = -1);

} // namespace popup::motion
