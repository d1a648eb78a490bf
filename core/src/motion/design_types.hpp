#pragma once
#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "anneal_problem.hpp"

namespace popup::motion {

/// The clock of the stages' timings (MotionResult::timings), and seconds since a reading of it.
using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point t)
{
    return std::chrono::duration<double>(Clock::now() - t).count();
}

/// What the stages of design_from_targets hand each other: the problem the search optimises,
/// the chains' own mappings, and the design's slots as each stage leaves them.
struct MotionDesign {
    AnnealProblem problem;                ///< the chains at search_target's samples
    std::vector<ChainTarget> full_chains; ///< every sample: what the report scores
    std::vector<MotionKind> mapped;       ///< per chain, its own mapping (best_mapping)
    /// per chain, held still because the maker did not choose it (MotionOptions::animate_only)
    std::vector<bool> unchosen;
    AnnealState state;                  ///< the design's slots, stage by stage
    std::map<int, std::string> reasons; ///< chain -> why stationary
    /// Per slot, the names of the mechanisms that carry it (the build's).
    std::vector<std::vector<std::string>> slot_mechanisms;
};

} // namespace popup::motion
