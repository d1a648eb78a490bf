#pragma once
#include <string>

#include "anneal_problem.hpp"

namespace popup::motion {

/// The names of the chains slot `s` carries, comma separated (the report's words).
std::string chain_names(const AnnealProblem& p, const Slot& s);

// Why chain j and the chains of slot `other` do not share one patch, in the report's words:
// their motions differ, their parts lie too far apart when open, or (alike and beside each
// other) one patch carrying both still collided or missed more.
std::string why_not_shared(const AnnealProblem& p, int j, const Slot& other);

} // namespace popup::motion
