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

} // namespace popup::motion
